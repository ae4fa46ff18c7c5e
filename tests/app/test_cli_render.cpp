// `brdfnav render` and `brdfnav distance` end to end: the images, the metric, and failures that
// leave nothing behind; `brdfnav bench render`'s tables at a tiny size.
#include "app/cli_runner.h"

#include <brdfnav/core/atomic_file.h>
#include <brdfnav/core/models.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <string>

namespace brdfnav::test {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("brdfnav_cli_render_" + std::to_string(::getpid()));
  TempDir() { fs::remove_all(path), fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

TEST(CliRender, RendersImagesWhoseDistanceIsTheMetric) {
  TempDir dir;
  const fs::path a = dir.path / "a.exr", b = dir.path / "b.exr";
  auto r = run_cli(
      "render --material ward:alpha_x=0.1,alpha_y=0.1,rho_d=0.2,rho_s=0.5 --res 24 "
      "--out " +
      a.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Each pass says what it is, once (not a second unnamed "render" from 0 to 100%), and the map
  // the project ships warns of nothing (its negative texels are ringing within 0.4% of its mean).
  for (const char* pass : {"render: diffuse pass: 100%", "render: ward lobe pass: 100%"})
    EXPECT_NE(r.err.find(pass), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  r = run_cli("render --material ward:alpha_x=0.2,alpha_y=0.2,rho_d=0.2,rho_s=0.5 --res 24 --out " +
              b.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_cli("distance " + a.string() + " " + a.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::stod(r.out), 0.0);
  r = run_cli("distance " + a.string() + " " + b.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(std::stod(r.out), 0.01);
  EXPECT_LT(std::stod(r.out), 1.0);
}

TEST(CliRender, FailuresLeaveNoOutputFile) {
  TempDir dir;
  const fs::path out = dir.path / "bad.exr";
  auto r = run_cli("render --material ward:alpha_x=-1 --res 16 --out " + out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("alpha_x"), std::string::npos) << r.err;
  r = run_cli("render --material ward --env " + (dir.path / "missing.exr").string() +
              " --res 16 --out " + out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("missing.exr"), std::string::npos) << r.err;
  r = run_cli("render --material ward --scene " + (dir.path / "missing.obj").string() +
              " --res 16 --out " + out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("missing.obj"), std::string::npos) << r.err;
  // Output names that cannot take the image fail before it is rendered.
  const struct {
    fs::path out;
    std::string message;
  } outputs[] = {{dir.path / "linear.png", "an OpenEXR file name must end in .exr"},
                 {dir.path / "missing" / "a.exr", "cannot create a file in its directory"},
                 {dir.path / "a_dir.exr", "is a directory"}};
  fs::create_directory(dir.path / "a_dir.exr");
  for (const auto& o : outputs) {
    r = run_cli("render --material ward --res 16 --out " + o.out.string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(o.out.string() + ": " + o.message), std::string::npos) << r.err;
  }
  fs::remove(dir.path / "a_dir.exr");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator{}), 0);
}

TEST(CliRender, DistanceRejectsMismatchedImages) {
  TempDir dir;
  const fs::path a = dir.path / "a.exr", b = dir.path / "b.exr";
  ASSERT_EQ(run_cli("render --material blinn_phong --res 16 --out " + a.string()).exit_code, 0);
  ASSERT_EQ(run_cli("render --material blinn_phong --res 20 --out " + b.string()).exit_code, 0);
  const auto r = run_cli("distance " + a.string() + " " + b.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_FALSE(r.err.empty());
  EXPECT_NE(run_cli("distance " + a.string() + " " + (dir.path / "none.exr").string()).exit_code,
            0);
}

// Each model's settings, and the batch rows for the models whose lobes the renderer batches along
// their Fresnel parameter: Cook-Torrance along f0, He along eta, none for Ward (its grid instead).
// --json writes the figures bench/results.py reads (bench/cli/bench_figures.h), one per model.
TEST(CliBenchRender, ReportsEveryModelAndTheFresnelBatches) {
  TempDir dir;
  const fs::path json = dir.path / "render.json";
  const auto r = run_cli("bench render --res 8 --repeats 1 --no-accuracy --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* row : {"| blinn_phong | smooth |", "| ward | medium |", "| lafortune | rough |",
                          "| cook_torrance smooth | f0 (10 nodes) |",
                          "| he rough | eta (5 nodes) |", "| ward grid in one pass |"})
    EXPECT_NE(r.out.find(row), std::string::npos) << row << "\n" << r.out;
  const std::string figures = read_file(json);
  EXPECT_EQ(figures.rfind("{\"bench\": \"render\", \"figures\": {\"resolution\": 8, ", 0), 0u)
      << figures;
  for (const ModelInfo& info : models()) {
    const std::string key = std::string("\"").append(info.name).append("_alone_ms\": ");
    EXPECT_NE(figures.find(key), std::string::npos) << figures;
  }
  for (const char* key :
       {"\"he_batched_ms\": ", "\"cook_torrance_batched_ms\": ", "\"ward_grid_ms\": "})
    EXPECT_NE(figures.find(key), std::string::npos) << key << figures;
  EXPECT_EQ(figures.find("_max_ratio"), std::string::npos) << "--no-accuracy: " << figures;
  // A --json file that cannot be written fails the command, naming it.
  const auto unwritable =
      run_cli("bench fits --per-model 1 --json " + (dir.path / "no" / "fits.json").string());
  EXPECT_NE(unwritable.exit_code, 0);
  EXPECT_NE(unwritable.err.find("fits.json"), std::string::npos) << unwritable.err;
  const auto ward = run_cli("bench render --res 8 --repeats 1 --no-accuracy --model ward");
  ASSERT_EQ(ward.exit_code, 0) << ward.err;
  EXPECT_EQ(ward.out.find("(5 nodes)"), std::string::npos) << ward.out;
  EXPECT_EQ(ward.out.find("| he |"), std::string::npos) << ward.out;
}

}  // namespace
}  // namespace brdfnav::test
