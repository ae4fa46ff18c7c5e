// The database the navigator tests query: the `test` precompute profile, built once per test
// process into a temporary directory of its own and removed at exit. Executables that use it
// are registered WHOLE, so the build is paid once per executable.
#pragma once

#include <brdfnav/core/material.h>
#include <brdfnav/precompute/database.h>

#include <unistd.h>

#include <filesystem>
#include <random>
#include <string>

namespace brdfnav::test {

class NavigationDatabase {
 public:
  static const NavigationDatabase& get() {
    static const NavigationDatabase db;
    return db;
  }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  NavigationDatabase()
      : root_(std::filesystem::temp_directory_path() /
              ("brdfnav_test_navigator_" + std::to_string(::getpid()))),
        dir_(root_ / "db") {
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
    const EnvMap env = EnvMap::load(kDefaultEnvPath, {}, [](const std::string&) {});
    precompute_database({make_profile("test"), dir_, false, 0, {}}, env, Scene::sphere());
  }
  ~NavigationDatabase() { std::filesystem::remove_all(root_); }

  std::filesystem::path root_, dir_;
};

// A material of `id` with every parameter uniform (in its scale) inside `grid` and random
// colours in [lo, hi) per channel.
inline Material random_material(ModelId id, const ParamGrid& grid, std::mt19937_64& rng,
                                double rho_d_max = 0.5, double rho_s_lo = 0.05,
                                double rho_s_hi = 1.0) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Material m = default_material(id);
  for (std::size_t d = 0; d < grid.dimensions(); ++d) {
    const ParamSpec& spec = grid.specs()[d];
    const double lo = to_scale(spec, grid.axis(d).front()),
                 hi = to_scale(spec, grid.axis(d).back());
    m.params[d] = from_scale(spec, lo + unit(rng) * (hi - lo));
  }
  for (int c = 0; c < 3; ++c) {
    m.rho_d[c] = unit(rng) * rho_d_max;
    m.rho_s[c] = rho_s_lo + unit(rng) * (rho_s_hi - rho_s_lo);
  }
  return m;
}

}  // namespace brdfnav::test
