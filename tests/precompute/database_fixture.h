// The precompute suites' shared database: a tiny profile built once per test process, and
// helpers to read and compare databases as files (test_database.cpp, test_shards.cpp).
#pragma once

#include <brdfnav/precompute/database.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace brdfnav::test {

namespace fs = std::filesystem;

// A three-model profile (He is by far the slowest model to render) at 8 x 8: the pipeline is the
// same as for the named profiles, at a size that keeps each test process (ctest runs every case
// in its own process, each building the fixture) at a few seconds.
inline Profile tiny_profile() {
  Profile p = make_profile("smoke");
  p.name = "unit";
  p.resolution = 8;
  p.pca.components = 400;  // more than the data's rank: the embedding is then lossless
  p.grids = {
      {ModelId::blinn_phong, ParamGrid(model_info(ModelId::blinn_phong).params, {{5, 2000}})},
      {ModelId::ward, ParamGrid(model_info(ModelId::ward).params, {{0.02, 0.3}, {0.02, 0.3}})},
      {ModelId::lafortune,
       ParamGrid(model_info(ModelId::lafortune).params, {{0.54, 0.57735026918962573}, {8, 800}})},
  };
  return p;
}

inline fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("brdfnav_test_database_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::remove_all(dir.string() + ".partial");
  fs::create_directories(dir.parent_path());
  return dir;
}

struct Fixture {
  EnvMap env = EnvMap::load(kDefaultEnvPath, {}, [](const std::string&) {});
  Scene scene = Scene::sphere();
  fs::path db = scratch("reference");

  Fixture() { precompute_database({tiny_profile(), db, false, 0, {}}, env, scene); }
  ~Fixture() { fs::remove_all(db.parent_path()); }
};

inline Fixture& fixture() {
  static Fixture f;
  return f;
}

inline std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

// Every file below `dir`, relative path -> contents.
inline std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).generic_string()] = read_bytes(e);
  return files;
}

}  // namespace brdfnav::test
