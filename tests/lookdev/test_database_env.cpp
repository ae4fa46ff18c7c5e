// load_database_env() (lookdev/include/brdfnav/lookdev/database_env.h): the one map check of
// every reader of a database, on a copy of the shared test database.
#include <brdfnav/core/error.h>
#include <brdfnav/lookdev/database_env.h>
#include <gtest/gtest.h>

#include "cli_runner.h"

#include <filesystem>
#include <string>

namespace brdfnav {
namespace {

namespace fs = std::filesystem;

// A copy of the shared test database to edit, fresh for each test and removed after it.
struct DatabaseCopy {
  explicit DatabaseCopy(const std::string& name)
      : root(fs::temp_directory_path() / ("brdfnav_database_env_" + name)), dir(root / "copy") {
    std::string error;
    fs::remove_all(root);
    fs::create_directories(root);
    const fs::path shared = test::suite_database(root, error);
    if (shared.empty()) ADD_FAILURE() << error;
    fs::copy(shared, dir, fs::copy_options::recursive);
  }
  ~DatabaseCopy() { fs::remove_all(root); }
  fs::path root, dir;
};

void replace_in_file(const fs::path& p, const std::string& from, const std::string& to) {
  std::string text = test::read_text(p);
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " in " << p;
  text.replace(at, from.size(), to);
  std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
}

// The error load_database_env() gives for the database in `dir` (ADD_FAILURE when it loads).
std::string load_error(const fs::path& dir) {
  try {
    load_database_env(Database::open(dir));
    ADD_FAILURE() << "loaded a map the images were not rendered under";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::database) << e.what();
    return e.what();
  }
  return "";
}

TEST(DatabaseEnv, LoadsTheMapTheImagesSaw) {
  const DatabaseCopy copy("same");
  const fs::path& dir = copy.dir;
  const Database db = Database::open(dir);
  EXPECT_EQ(load_database_env(db).pixel_sha1(), db.manifest().env_pixel_sha1);
}

// Whatever renders against a database must see the map its images saw: a manifest whose map is
// now another file opens, but its map does not load.
TEST(DatabaseEnv, RefusesAnotherMapNamingItAndTheManifest) {
  const DatabaseCopy copy("other");
  const fs::path& dir = copy.dir;
  const std::string recorded = Database::open(dir).manifest().env_path;
  const std::string other = fs::path(recorded).replace_filename(
      recorded.find("courtyard") == std::string::npos ? "courtyard.exr" : "sunset.exr");
  ASSERT_TRUE(fs::exists(other)) << other;
  replace_in_file(dir / "manifest.yaml", recorded, other);
  const std::string error = load_error(dir);
  EXPECT_NE(error.find(other + ": changed since the database was built"), std::string::npos)
      << error;
  EXPECT_NE(error.find((dir / "manifest.yaml").string()), std::string::npos) << error;
}

TEST(DatabaseEnv, RefusesAMissingMapNamingItAndTheManifest) {
  const DatabaseCopy copy("missing");
  const fs::path& dir = copy.dir;
  replace_in_file(dir / "manifest.yaml", Database::open(dir).manifest().env_path,
                  "/nonexistent/map.exr");
  const std::string error = load_error(dir);
  EXPECT_NE(error.find("/nonexistent/map.exr"), std::string::npos) << error;
  EXPECT_NE(error.find((dir / "manifest.yaml").string() + " names"), std::string::npos) << error;
}

}  // namespace
}  // namespace brdfnav
