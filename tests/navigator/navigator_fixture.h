// The database the navigator tests query: the `test` precompute profile. Under CTest it is the
// `test_database` fixture, built once per run by the CLI and named by $BRDFNAV_TEST_DATABASE
// (tests/CMakeLists.txt); run alone, an executable builds it once into a temporary directory of
// its own. Either way the tests only read it; scratch() is this process's own directory, removed
// at exit.
#pragma once

#include <brdfnav/core/material.h>
#include <brdfnav/navigator/navigator.h>
#include <brdfnav/precompute/database.h>

#include <unistd.h>

#include <cstdlib>
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
  const std::filesystem::path& scratch() const { return scratch_; }

 private:
  NavigationDatabase()
      : scratch_(std::filesystem::temp_directory_path() /
                 ("brdfnav_test_navigator_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(scratch_);
    std::filesystem::create_directories(scratch_);
    if (const char* shared = std::getenv("BRDFNAV_TEST_DATABASE"); shared && *shared) {
      dir_ = shared;
      return;
    }
    dir_ = scratch_ / "db";
    const EnvMap env = EnvMap::load(kDefaultEnvPath, {}, [](const std::string&) {});
    precompute_database({make_profile("test"), dir_, false, 0, {}}, env, Scene::sphere());
  }
  ~NavigationDatabase() { std::filesystem::remove_all(scratch_); }

  std::filesystem::path scratch_, dir_;
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

// The navigator over that database, opened once per process.
inline const Navigator& navigator() {
  static const Navigator nav = Navigator::open(NavigationDatabase::get().dir());
  return nav;
}

}  // namespace brdfnav::test
