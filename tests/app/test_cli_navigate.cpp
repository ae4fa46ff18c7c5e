// `brdfnav neighbors`, `brdfnav variations` and `brdfnav export` end to end, on a test-profile
// database built with `brdfnav precompute`: the shared one of CTest's test_database fixture
// ($BRDFNAV_TEST_DATABASE), else one the suite builds once (it is registered WHOLE).
#include "app/cli_runner.h"

#include <brdfnav/core/material.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <unistd.h>

#include <cstdlib>
#include <set>

namespace brdfnav::test {
namespace {

namespace fs = std::filesystem;

class CliNavigate : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("brdfnav_cli_navigate_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    std::string error;
    db_ = suite_database(root_, error);
    ASSERT_FALSE(db_.empty()) << error;
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  static const fs::path& db() { return db_; }
  static fs::path file(const std::string& name) { return root_ / name; }
  static CliResult neighbors(const std::string& args) {
    return run_cli("neighbors --db " + db().string() + " " + args);
  }

  static inline fs::path root_, db_;
};

// Every item has the stable keys; its material reads back through the CLI (`eval`).
TEST_F(CliNavigate, NeighborsPrintsOneYamlListWithTheStableKeys) {
  const CliResult r =
      neighbors("--material ward:alpha_x=0.1,alpha_y=0.05,rho_s=0.4 --radius 0.02 --k 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<YAML::Node> docs = YAML::LoadAll(r.out);
  ASSERT_EQ(docs.size(), 1u);
  const YAML::Node list = docs[0]["neighbors"];
  ASSERT_TRUE(list.IsSequence());
  std::set<std::string> tabs;
  for (const YAML::Node& item : list) {
    std::set<std::string> keys;
    for (const auto& kv : item) keys.insert(kv.first.as<std::string>());
    EXPECT_EQ(keys, (std::set<std::string>{"tab", "label", "words", "change", "opposite",
                                           "distance", "flags", "material"}));
    tabs.insert(item["tab"].as<std::string>());
    EXPECT_GT(item["distance"].as<double>(), 0);
    EXPECT_TRUE(item["flags"].IsSequence());
    std::set<std::string> material_keys;
    for (const auto& kv : item["material"]) material_keys.insert(kv.first.as<std::string>());
    EXPECT_EQ(material_keys,
              (std::set<std::string>{"model", "params", "rho_d", "rho_s", "colorspace"}));
  }
  EXPECT_EQ(tabs, (std::set<std::string>{"lobe", "diffuse", "specular", "models", "gallery"}));
  EXPECT_EQ(list[0]["label"].as<std::string>(), "alpha_x+");

  const CliResult lobe =
      neighbors("--material ward:alpha_x=0.1,alpha_y=0.05 --radius 0.01 --tab lobe");
  ASSERT_EQ(lobe.exit_code, 0) << lobe.err;
  const YAML::Node only = YAML::Load(lobe.out)["neighbors"];
  ASSERT_EQ(only.size(), 6u);
  for (const YAML::Node& item : only) EXPECT_EQ(item["tab"].as<std::string>(), "lobe");
}

// --exact: each lobe offer moved until a render of it is at --radius from the material's. Checked
// with renders of its own (`brdfnav render` at the database's map and resolution, whose render
// quality is the CLI's default rather than the profile's, and `brdfnav distance`): within 5%.
TEST_F(CliNavigate, ExactNeighborsAreAtTheRadiusOfIndependentRenders) {
  const std::string colors = ",rho_d=0.2,rho_s=0.4";
  const std::string spec = "ward:alpha_x=0.1,alpha_y=0.05" + colors;
  const CliResult r = neighbors("--material " + spec + " --radius 0.03 --tab lobe --exact");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const YAML::Node manifest = YAML::LoadFile((db() / "manifest.yaml").string());
  const std::string render = "render --env " + manifest["environment"]["path"].as<std::string>() +
                             " --res " + manifest["resolution"].as<std::string>() + " --out ";
  ASSERT_EQ(run_cli(render + file("current.exr").string() + " --material " + spec).exit_code, 0);
  int checked = 0;
  for (const YAML::Node& item : YAML::Load(r.out)["neighbors"]) {
    if (item["flags"].size() > 0) continue;
    const YAML::Node params = item["material"]["params"];
    const std::string offer = "ward:alpha_x=" + params["alpha_x"].as<std::string>() +
                              ",alpha_y=" + params["alpha_y"].as<std::string>() + colors;
    const fs::path image = file(item["label"].as<std::string>() + ".exr");
    ASSERT_EQ(run_cli(render + image.string() + " --material " + offer).exit_code, 0);
    const CliResult d = run_cli("distance " + file("current.exr").string() + " " + image.string());
    ASSERT_EQ(d.exit_code, 0) << d.err;
    EXPECT_NEAR(std::stod(d.out) / 0.03, 1, 0.05) << offer;
    EXPECT_NEAR(item["distance"].as<double>() / 0.03, 1, 0.02) << offer;
    ++checked;
  }
  EXPECT_GE(checked, 4) << r.out;
}

// The export is a material file: neighbors and eval take it as --material.
TEST_F(CliNavigate, ExportRoundTripsAsAMaterial) {
  const std::string spec = "he:sigma=0.3,tau=9,eta=2,rho_d=0.1/0.2/0.3,rho_s=0.7";
  const fs::path chosen = file("chosen.yaml");
  CliResult r =
      run_cli("export --db " + db().string() + " --material " + spec + " --out " + chosen.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const YAML::Node doc = YAML::LoadFile(chosen.string());
  EXPECT_EQ(doc["brdfnav_material"].as<int>(), 1);
  EXPECT_EQ(doc["model"].as<std::string>(), "he");
  EXPECT_EQ(doc["provenance"]["manifest_sha1"].as<std::string>().size(), 40u);
  EXPECT_FALSE(doc["provenance"]["environment"]["path"].as<std::string>().empty());
  EXPECT_EQ(doc["equivalents"].size(), models().size() - 1);  // its fit in every other model
  for (const auto& kv : doc["equivalents"]) EXPECT_GE(kv.second["residual"].as<double>(), 0);

  const std::string args = " --radius 0.01 --tab lobe";
  const CliResult from_file = neighbors("--material " + chosen.string() + args);
  const CliResult from_spec = neighbors("--material " + spec + args);
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  EXPECT_EQ(from_file.out, from_spec.out);
  const std::string wi = " --wi 0,0.3,1 --wo 0.2,0,1";
  r = run_cli("eval --material " + chosen.string() + wi);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, run_cli("eval --material " + spec + wi).out);
}

// One error line naming the option, key or file; non-zero exit; nothing written.
TEST_F(CliNavigate, RejectsBadInputNamingIt) {
  const std::string ok = "--material ward --radius 0.01";
  const struct {
    std::string args, message;
  } cases[] = {
      {"--material ward --radius 0.01 --tab sideways", "--tab"},
      {"--material ward --radius nan", "--radius"},
      {"--material ward --radius -0.1", "--radius"},
      {"--material ward --radius 0", "--radius"},
      {"--material ward --radius 1e-300", "--radius"},
      {"--material ward --radius 0.01 --k 0", "--k"},
      {"--material ward:alpha_x=7 --radius 0.01", "params.alpha_x"},
      {"--material missing.yaml --radius 0.01", "missing.yaml"},
      {"--material ward:colorspace=acescg --radius 0.01 --tab diffuse", "colorspace 'acescg'"},
      {"--material ward:colorspace=acescg --radius 0.01 --tab lobe", "colorspace 'acescg'"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const CliResult r = neighbors(c.args);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  CliResult r = run_cli("neighbors --db " + file("nodb").string() + " " + ok);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--db: " + file("nodb").string() + "/manifest.yaml"), std::string::npos)
      << r.err;

  const fs::path out = file("never.yaml");
  r = run_cli("export --db " + file("nodb").string() + " --material ward --out " + out.string());
  EXPECT_NE(r.exit_code, 0);
  r = run_cli("export --db " + db().string() + " --material ward:n=3 --out " + out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--material"), std::string::npos) << r.err;
  r = run_cli("export --db " + db().string() + " --material ward --out " +
              (root_ / "no_such_dir" / "x.yaml").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("no_such_dir"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  for (const auto& e : fs::directory_iterator(root_))
    EXPECT_EQ(e.path().filename().string().find("never"), std::string::npos) << e.path();
}

// bench fidelity renders what the navigator offers and prints, per model, the final images' and
// the previews' errors and each tab's steps against eps, with the targets' verdicts.
TEST_F(CliNavigate, BenchFidelityReportsEveryModelAndTab) {
  CliResult r = run_cli("bench fidelity --db " + db().string() + " --materials 1 --radius 0.03");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| model | images | blends | final median | worst | verdict | preview "
                       "median | worst |"),
            std::string::npos)
      << r.out;
  for (const ModelInfo& info : models()) {
    const std::string model(info.name);
    // The final images meet their targets on the test database (blends or renders).
    const std::size_t row = r.out.find("\n| " + model + " | ");
    ASSERT_NE(row, std::string::npos) << model << "\n" << r.out;
    EXPECT_NE(r.out.substr(row, r.out.find('\n', row + 1) - row).find("| met |"), std::string::npos)
        << model << "\n"
        << r.out;
    for (const char* tab : {"lobe", "diffuse", "specular", "models"})
      EXPECT_NE(r.out.find("| " + model + " | " + tab + " | "), std::string::npos)
          << model << " " << tab << "\n"
          << r.out;
  }
  r = run_cli("bench fidelity --db " + db().string() + " --radius 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--radius"), std::string::npos) << r.err;
}

// A contact sheet per tab through OCIO: a PNG of the documented layout (contact_sheet.h); a bad
// view or tab is rejected by name and leaves no file.
TEST_F(CliNavigate, VariationsWritesAContactSheetPerTab) {
  const std::string material = "--material ward:alpha_x=0.05,alpha_y=0.03,rho_d=0.1,rho_s=0.5";
  for (const char* tab : {"lobe", "diffuse", "specular", "models", "gallery"}) {
    const fs::path sheet = file(std::string("sheet_") + tab + ".png");
    const CliResult r =
        run_cli("variations --db " + db().string() + " " + material +
                " --radius 0.05 --size 32 --tab " + tab + " --out " + sheet.string());
    ASSERT_EQ(r.exit_code, 0) << tab << ": " << r.err;
    const std::string png = read_text(sheet);
    ASSERT_GT(png.size(), 8u) << tab;
    EXPECT_EQ(png.substr(1, 3), "PNG") << tab;
  }
  const fs::path out = file("never_sheet.png");
  CliResult r = run_cli("variations --db " + db().string() + " " + material +
                        " --radius 0.05 --view Nope --out " + out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("Nope"), std::string::npos) << r.err;
  r = run_cli("variations --db " + db().string() + " " + material +
              " --radius 0.05 --tab all --out " + out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace brdfnav::test
