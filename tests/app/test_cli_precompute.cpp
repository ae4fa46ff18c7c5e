#include "app/cli_runner.h"

#include <gtest/gtest.h>

#include <unistd.h>

namespace brdfnav::test {
namespace {

namespace fs = std::filesystem;

// The smoke profile end to end through the CLI (the test profile's build is the CTest fixture
// test_database), in one case: build, inspect, refuse to overwrite, then reject a corrupted file.
TEST(CliPrecompute, BuildsVerifiesAndRejectsACorruptDatabase) {
  const fs::path root =
      fs::temp_directory_path() / ("brdfnav_cli_precompute_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const fs::path db = root / "db";

  // --res: the smallest size the CLI takes (the renderer is the bottleneck).
  auto r = run_cli("precompute --profile smoke --res 8 --out " + db.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* phase : {"render: ", "embedding: ", "fits: ", "blend check: ", "manifest: "})
    EXPECT_NE(r.err.find(std::string("brdfnav: ") + phase), std::string::npos) << phase;
  EXPECT_FALSE(fs::exists(db.string() + ".partial"));

  r = run_cli("db-info --db " + db.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("profile: smoke"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("resolution: 8"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("model he: 8 nodes"), std::string::npos) << r.out;
  // Ward's smoke grid is 3 x 3 nodes, 2 x 2 cells.
  EXPECT_NE(r.out.find("blend check ward: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" of 4 cells vouched for (median "), std::string::npos) << r.out;

  r = run_cli("precompute --profile smoke --res 8 --out " + db.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("already exists"), std::string::npos) << r.err;

  // The same database as format version 2, whose blend checks were measured with an earlier
  // spline: it opens, and says why it vouches for no blend.
  const fs::path old = root / "version_2";
  fs::copy(db, old, fs::copy_options::recursive);
  std::string manifest = read_text(old / "manifest.yaml");
  const std::size_t at = manifest.find("brdfnav_database: 3");
  ASSERT_NE(at, std::string::npos) << manifest;
  std::ofstream(old / "manifest.yaml") << manifest.replace(at, 19, "brdfnav_database: 2");
  r = run_cli("db-info --db " + old.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("blend check ward: none usable (format version 2: any check was measured "
                       "with an earlier spline); every final image is rendered"),
            std::string::npos)
      << r.out;

  const fs::path table = db / "conversions" / "he_to_ward.f32";
  std::string bytes = read_text(table);
  bytes[bytes.size() - 1] ^= 0x40;
  std::ofstream(table, std::ios::binary) << bytes;
  r = run_cli("db-info --db " + db.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("conversions/he_to_ward.f32: checksum mismatch"), std::string::npos)
      << r.err;

  fs::remove_all(root);
}

TEST(CliPrecompute, RejectsAnUnknownProfile) {
  const auto r = run_cli("precompute --profile huge --out /tmp/never_written");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--profile"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace brdfnav::test
