// `brdfnav validate` end to end at a small scale (images at 24 x 24, the test profile's database):
// the report's structure (every figure and key of report.yaml, every PNG readable at the size the
// report gives), the claims that already hold at that scale, and one clear error line for each
// kind of bad input.
#include "app/cli_runner.h"

#include <brdfnav/renderer/env_map.h>

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace brdfnav::test {
namespace {

namespace fs = std::filesystem;

const std::string kWorld = "/usr/share/blender/datafiles/studiolights/world/";
// Blender's eight maps, validate's default --env, in its order.
const std::vector<std::string> kMaps{"interior", "forest", "courtyard", "city",
                                     "night",    "studio", "sunrise",   "sunset"};
// The test database's map, the reference of the run on it: the default one.
const std::string kReference = fs::path(kDefaultEnvPath).stem().string();

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("brdfnav_cli_validate_" + std::to_string(::getpid()) + name);
  fs::remove_all(dir);
  return dir;
}

// The lines of stderr that report an error (warnings, e.g. clamped texels, may come first).
std::vector<std::string> error_lines(const std::string& err) {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);)
    if (line.find("error") != std::string::npos) lines.push_back(line);
  return lines;
}

void expect_sequence(const YAML::Node& node, std::size_t size, const std::string& what) {
  ASSERT_TRUE(node.IsSequence()) << what;
  EXPECT_EQ(node.size(), size) << what;
}

// One map's Figure 2 curves (the reference's, or another map's under figure2.other_envs).
void check_pellacini(const YAML::Node& f, const std::string& map) {
  EXPECT_GT(f["white_y"].as<double>(), 0) << map;
  for (const char* m : {"cube_root", "cielab", "rgb", "brdf_l2"}) {
    const YAML::Node c = f["metrics"][m];
    ASSERT_TRUE(c.IsMap()) << map << m;
    expect_sequence(c["cumulative"], 11, m);
    for (std::size_t i = 1; i < 11; ++i)
      EXPECT_GT(c["cumulative"][i].as<double>(), c["cumulative"][i - 1].as<double>()) << m;
    for (const char* k : {"slope", "intercept", "r2"}) EXPECT_TRUE(c[k].IsScalar()) << m << k;
    // The last step against the mean step, from the cumulative values the report gives.
    const double total = c["cumulative"][10].as<double>();
    EXPECT_NEAR(c["last_step_ratio"].as<double>(),
                (total - c["cumulative"][9].as<double>()) / (total / 10), 1e-4)
        << map << m;
  }
  // The paper's claim, from the R^2 the report gives: the cube root and CIELAB within 0.02 of
  // each other, both at least 0.05 above RGB L2 and the BRDF-space metric.
  const auto r2 = [&f](const char* m) { return f["metrics"][m]["r2"].as<double>(); };
  const double perceptual = std::min(r2("cube_root"), r2("cielab"));
  EXPECT_EQ(f["claim_holds"].as<bool>(),
            std::abs(r2("cube_root") - r2("cielab")) <= 0.02 &&
                perceptual >= std::max(r2("rgb"), r2("brdf_l2")) + 0.05)
      << map;
  // Holds at 24 x 24 under every map but sunset (0.028 apart; 0.025 at 128 x 128): the
  // cube-root metric and CIELAB give curves equally straight.
  if (map != "sunset") {
    EXPECT_NEAR(r2("cube_root"), r2("cielab"), 0.02) << map;
  }
  const double peak = f["env_luminance"]["peak"].as<double>();
  EXPECT_GE(peak, f["env_luminance"]["mean"].as<double>()) << map;
  EXPECT_GT(f["env_luminance"]["mean"].as<double>(), 0) << map;
  // Holds at 24 x 24 already, under each map: the cube root straightens the curve compared with
  // plain RGB.
  EXPECT_GT(f["metrics"]["cube_root"]["r2"].as<double>(), f["metrics"]["rgb"]["r2"].as<double>())
      << map;
}

void check_fig2(const YAML::Node& f) {
  expect_sequence(f["d"], 11, "figure2.d");
  ASSERT_TRUE(f["other_envs"].IsMap());
  EXPECT_EQ(f["other_envs"].size(), kMaps.size() - 1);
  // One map's curves: the reference's at the top level, the others' under other_envs.
  auto under = [&f](const std::string& map) {
    return map == kReference ? f : f["other_envs"][map];
  };
  bool everywhere = true;
  for (const std::string& map : kMaps) {
    check_pellacini(under(map), map);
    everywhere = everywhere && under(map)["claim_holds"].as<bool>();
  }
  EXPECT_EQ(f["claim"]["perceptual_same"].as<double>(), 0.02);
  EXPECT_EQ(f["claim"]["clear_margin"].as<double>(), 0.05);
  EXPECT_EQ(f["claim_holds_everywhere"].as<bool>(), everywhere);
  // Blender's maps as `oiiotool --stats` reads them: interior's lamps reach about 34,000 against
  // a mean near 1, courtyard's brightest sky about 55.
  auto range = [](const YAML::Node& m) {
    return m["env_luminance"]["peak"].as<double>() / m["env_luminance"]["mean"].as<double>();
  };
  EXPECT_GT(range(under("interior")), 1e4);
  EXPECT_LT(range(under("courtyard")), 1e3);
  // The stimuli are the same under every map, so the BRDF-space curve is too.
  EXPECT_EQ(under("sunset")["metrics"]["brdf_l2"]["r2"].as<double>(),
            f["metrics"]["brdf_l2"]["r2"].as<double>());
}

void check_fig3(const YAML::Node& f) {
  expect_sequence(f["alpha"], 25, "figure3.alpha");
  EXPECT_NEAR(f["reference_alpha"].as<double>(), 0.07, 0.0075);
  EXPECT_EQ(f["alpha"][f["reference_sample"].as<std::size_t>()].as<double>(),
            f["reference_alpha"].as<double>());
  EXPECT_EQ(f["tolerance"].as<double>(), 0.2);
  // The reference first, then the other maps in --env's order, the constant environment and the
  // BRDF-space metric.
  std::vector<std::string> names{kReference};
  for (const std::string& m : kMaps)
    if (m != kReference) names.push_back(m);
  names.insert(names.end(), {"uniform", "brdf_l2"});
  std::map<std::string, double> within;
  std::size_t n = 0;
  for (const auto& entry : f["metrics"]) {
    ASSERT_LT(n, names.size());
    const std::string m = entry.first.as<std::string>();
    EXPECT_EQ(m, names[n++]);
    const YAML::Node e = entry.second;
    EXPECT_GT(e["scale"].as<double>(), 0) << m;
    expect_sequence(e["distances"], 25, m);
    for (const YAML::Node& row : e["distances"]) expect_sequence(row, 25, m);
    within[m] = e["within"].as<double>();
  }
  ASSERT_EQ(n, names.size());
  EXPECT_EQ(within[kReference], 1.0);
  // Every entry against every other: rows are references, row 0 the reference map's agreements.
  const YAML::Node matrix = f["within_matrix"];
  expect_sequence(matrix, names.size(), "within_matrix");
  std::size_t j = 0;
  for (const auto& entry : f["metrics"]) {
    expect_sequence(matrix[j], names.size(), "within_matrix row");
    EXPECT_EQ(matrix[j][j].as<double>(), 1.0) << "each entry agrees with itself";
    EXPECT_EQ(matrix[0][j++].as<double>(), entry.second["within"].as<double>());
  }
  const auto at = [&](const std::string& row, const std::string& column) {
    const auto index = [&](const std::string& m) {
      return std::size_t(std::find(names.begin(), names.end(), m) - names.begin());
    };
    return matrix[index(row)][index(column)].as<double>();
  };
  // Holds at 24 x 24 already (95% and 92%; 99% and 98% at 128 x 128): the paper's "over 85%"
  // between the two outdoor maps, whichever is the reference.
  EXPECT_GT(at("forest", "courtyard"), 0.85);
  EXPECT_GT(at("courtyard", "forest"), 0.85);
  // The count over the natural maps' ordered pairs is the matrix's.
  const std::size_t maps = kMaps.size();
  EXPECT_EQ(f["natural_pairs"].as<std::size_t>(), maps * (maps - 1));
  std::size_t agreeing = 0;
  for (std::size_t i = 0; i < maps; ++i)
    for (std::size_t k = 0; k < maps; ++k) agreeing += i != k && matrix[i][k].as<double>() >= 0.85;
  EXPECT_EQ(f["natural_pairs_agreeing"].as<std::size_t>(), agreeing);
  EXPECT_GE(agreeing, 2u);
  EXPECT_TRUE(f["natural_maps_agree"].IsScalar());
  // Each map's agreement with the others: both ways, from the matrix.
  const YAML::Node a = f["agreement"];
  EXPECT_EQ(a["threshold"].as<double>(), 0.85);
  ASSERT_EQ(a["maps"].size(), maps);
  std::size_t most = 0;
  for (std::size_t i = 0; i < maps; ++i) {
    const YAML::Node m = a["maps"][names[i]];
    ASSERT_TRUE(m.IsMap()) << names[i];
    std::size_t count = 0;
    double mean = 0;
    for (std::size_t k = 0; k < maps; ++k)
      if (k != i) {
        const double both = std::min(matrix[i][k].as<double>(), matrix[k][i].as<double>());
        count += both >= 0.85;
        mean += both / double(maps - 1);
      }
    EXPECT_EQ(m["agreeing"].as<std::size_t>(), count) << names[i];
    EXPECT_EQ(m["others"].as<std::size_t>(), maps - 1) << names[i];
    EXPECT_NEAR(m["mean"].as<double>(), mean, 1e-5) << names[i];
    most = std::max(most, count);
  }
  // The most representative map is one of those agreeing with the most others.
  const std::string chosen = a["most_representative"].as<std::string>();
  ASSERT_TRUE(a["maps"][chosen].IsMap()) << chosen;
  EXPECT_EQ(a["maps"][chosen]["agreeing"].as<std::size_t>(), most);
  EXPECT_EQ(a["reference_goal_holds"].as<bool>(),
            a["maps"][kReference]["agreeing"].as<std::size_t>() >= 5);
  // The constant environment and the BRDF-space metric agree less with each outdoor map than the
  // other outdoor map does.
  for (const auto& [map, other] : {std::pair{"forest", "courtyard"}, {"courtyard", "forest"}})
    for (const char* poor : {"uniform", "brdf_l2"})
      EXPECT_LT(at(map, poor), at(map, other)) << poor << " vs " << other << " onto " << map;
}

void check_spacing(const YAML::Node& f, const char* parameter, const char* baseline) {
  EXPECT_EQ(f["parameter"].as<std::string>(), parameter);
  ASSERT_TRUE(f["fine"].IsSequence());
  expect_sequence(f["cumulative_image"], f["fine"].size(), "cumulative_image");
  expect_sequence(f["cumulative_baseline"], f["fine"].size(), "cumulative_baseline");
  for (const char* row : {baseline, "image"}) {
    const YAML::Node r = f["rows"][row];
    ASSERT_TRUE(r.IsMap()) << row;
    expect_sequence(r["values"], 8, row);
    expect_sequence(r["steps"], 7, row);
    EXPECT_GE(r["cv"].as<double>(), 0) << row;
  }
  // Holds at any scale: the image metric's own spacing is the more uniform in that metric.
  EXPECT_TRUE(f["image_more_uniform"].as<bool>()) << parameter;
}

void check_embedding(const YAML::Node& f) {
  EXPECT_EQ(f["pairs"].as<int>(), 20);
  for (const char* kind : {"anywhere", "on_nodes"}) {
    ASSERT_TRUE(f[kind].IsSequence()) << kind;
    ASSERT_GE(f[kind].size(), 2u) << kind;
    for (const YAML::Node& row : f[kind]) {
      EXPECT_GT(row["coefficients"].as<int>(), 0) << kind;
      EXPECT_GE(row["p95"].as<double>(), row["median"].as<double>()) << kind;
    }
  }
  // On the nodes only the truncation is left: a projection never lengthens a distance and each
  // coefficient adds to it, so the error cannot grow with k (the database is this renderer's).
  const YAML::Node nodes = f["on_nodes"];
  for (std::size_t i = 1; i < nodes.size(); ++i)
    for (const char* q : {"median", "p95"})
      EXPECT_LE(nodes[i][q].as<double>(), nodes[i - 1][q].as<double>() + 1e-6) << q << i;
  // Interpolating between the test grids' nodes costs more than truncating to the last k.
  const std::size_t last = nodes.size() - 1;
  EXPECT_LT(nodes[last]["median"].as<double>(), f["anywhere"][last]["median"].as<double>());
  // The embedding's accuracy target holds on the test profile's grids (0.25% and 0.6% measured):
  // the embedding is the metric, anywhere in the grids, to a median of 1% and a p95 of 3%.
  EXPECT_LE(f["anywhere"][last]["median"].as<double>(), 0.01);
  EXPECT_LE(f["anywhere"][last]["p95"].as<double>(), 0.03);
}

// Every plot the report lists is a readable PNG of the listed size; every figure has one.
void check_plots(const fs::path& dir, const YAML::Node& plots) {
  ASSERT_TRUE(plots.IsSequence());
  std::set<std::string> figures;
  for (const YAML::Node& p : plots) {
    const fs::path file = dir / p["file"].as<std::string>();
    const auto png = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(png) << file << ": " << OIIO::geterror();
    EXPECT_EQ(png->format_name(), std::string("png")) << file;
    EXPECT_EQ(png->spec().width, p["width"].as<int>()) << file;
    EXPECT_EQ(png->spec().height, p["height"].as<int>()) << file;
    figures.insert(p["figure"].as<std::string>());
  }
  EXPECT_EQ(figures,
            (std::set<std::string>{"figure2", "figure3", "figure8", "figure9", "embedding"}));
  std::set<std::string> files;
  for (const YAML::Node& p : plots) files.insert(p["file"].as<std::string>());
  EXPECT_TRUE(files.count("fig2_environments.png")) << "Figure 2 under every map";
}

// A test-profile database: CTest's shared one ($BRDFNAV_TEST_DATABASE) when it is of that
// profile (sanitized trees share a smoke one), else one built under `root`.
fs::path test_profile_database(const fs::path& root) {
  if (const char* shared = std::getenv("BRDFNAV_TEST_DATABASE"); shared && *shared)
    if (YAML::LoadFile((fs::path(shared) / "manifest.yaml").string())["profile"]
            .as<std::string>() == "test")
      return shared;
  const fs::path db = root / "db";
  const auto r = run_cli("precompute --profile test --out " + db.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return db;
}

// One run on the test profile, checked as a whole: the studies are the slow part.
TEST(CliValidate, WritesEveryFigureAtSmallScale) {
  const fs::path root = scratch("_run"), out = root / "report";
  const fs::path db = test_profile_database(root);
  const auto r =
      run_cli("validate --res 24 --pairs 20 --db " + db.string() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;

  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_NE(entry.path().filename().string()[0], '.') << "left behind: " << entry.path();
  const std::string md = read_text(out / "report.md");
  for (const char* heading :
       {"## Figure 2", "## Figure 3", "## Figure 8", "## Figure 9", "## Embedding"})
    EXPECT_NE(md.find(heading), std::string::npos) << heading;

  const YAML::Node report = YAML::LoadFile((out / "report.yaml").string());
  EXPECT_EQ(report["brdfnav_validation"].as<int>(), 1);
  EXPECT_EQ(report["settings"]["resolution"].as<int>(), 24);
  EXPECT_EQ(report["settings"]["reference_env"].as<std::string>(), kDefaultEnvPath)
      << "the database's map";
  EXPECT_EQ(report["settings"]["scene"].as<std::string>(), "sphere");
  check_fig2(report["figure2"]);
  check_fig3(report["figure3"]);
  check_spacing(report["figure8"], "alpha", "brdf_l2");
  check_spacing(report["figure9"], "cz", "linear");
  check_embedding(report["embedding"]);
  check_plots(out, report["plots"]);
  fs::remove_all(root);
}

// The names figure3 gives its metrics, in the report's order.
std::vector<std::string> fig3_names(const YAML::Node& report) {
  std::vector<std::string> names;
  for (const auto& entry : report["figure3"]["metrics"])
    names.push_back(entry.first.as<std::string>());
  return names;
}

TEST(CliValidate, TheDatabasesMapIsTheReference) {
  // A map that is not the default one, so that the database's map is what makes it the reference.
  const fs::path root = scratch("_dbenv"), db = root / "db", out = root / "report";
  auto r = run_cli("precompute --profile smoke --res 8 --env " + kWorld + "courtyard.exr --out " +
                   db.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_cli("validate --res 8 --pairs 2 --fit-samples 1 --db " + db.string() + " --out " +
              out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // courtyard.exr is among the default --env maps: comparing it with itself would say nothing.
  EXPECT_NE(r.err.find(kWorld + "courtyard.exr is the reference map; left out"), std::string::npos)
      << r.err;
  const YAML::Node report = YAML::LoadFile((out / "report.yaml").string());
  EXPECT_EQ(report["settings"]["reference_env"].as<std::string>(), kWorld + "courtyard.exr");
  EXPECT_EQ(report["settings"]["envs"].size(), 7u);
  EXPECT_EQ(fig3_names(report),
            (std::vector<std::string>{"courtyard", "interior", "forest", "city", "night", "studio",
                                      "sunrise", "sunset", "uniform", "brdf_l2"}));
  EXPECT_EQ(report["figure3"]["metrics"]["courtyard"]["within"].as<double>(), 1.0);
  EXPECT_TRUE(report["figure2"]["other_envs"]["forest"].IsMap());
  fs::remove_all(root);
}

TEST(CliValidate, AnyMapCanBeTheReferenceAndEveryMapHasItsOwnName) {
  const fs::path root = scratch("_names"), out = root / "report";
  fs::create_directories(root / "elsewhere");
  // Two more maps whose stems are already taken: by forest.exr and by the constant environment.
  fs::create_symlink(kWorld + "forest.exr", root / "elsewhere" / "forest.exr");
  fs::create_symlink(kWorld + "city.exr", root / "elsewhere" / "uniform.exr");
  const auto r =
      run_cli("validate --res 8 --reference " + kWorld + "courtyard.exr --env " + kWorld +
              "forest.exr," + (root / "elsewhere" / "forest.exr").string() + "," +
              (root / "elsewhere" / "uniform.exr").string() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const YAML::Node report = YAML::LoadFile((out / "report.yaml").string());
  EXPECT_EQ(report["settings"]["reference_env"].as<std::string>(), kWorld + "courtyard.exr");
  EXPECT_EQ(fig3_names(report), (std::vector<std::string>{"courtyard", "forest", "forest-2",
                                                          "uniform-2", "uniform", "brdf_l2"}));
  EXPECT_EQ(report["figure2"]["other_envs"].size(), 3u);
  // The same map under two names gives the same distances.
  EXPECT_EQ(report["figure3"]["metrics"]["forest"]["within"].as<double>(),
            report["figure3"]["metrics"]["forest-2"]["within"].as<double>());
  fs::remove_all(root);
}

// A failing run: non-zero exit and exactly one error line, naming `culprit`.
void expect_one_error(const std::string& args, const std::string& culprit) {
  const auto r = run_cli("validate --res 8 " + args);
  EXPECT_NE(r.exit_code, 0);
  const auto errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r.err;
  EXPECT_NE(errors[0].find(culprit), std::string::npos) << r.err;
}

TEST(CliValidate, NamesAMissingEnvironmentMap) {
  const fs::path out = scratch("_env");
  expect_one_error("--env /nonexistent/sky.exr --out " + out.string(), "/nonexistent/sky.exr");
  EXPECT_FALSE(fs::exists(out)) << "a failed run leaves nothing behind";
}

TEST(CliValidate, NamesAMissingReferenceMap) {
  const fs::path out = scratch("_reference");
  expect_one_error("--reference /nonexistent/reference.exr --out " + out.string(),
                   "/nonexistent/reference.exr");
  EXPECT_FALSE(fs::exists(out)) << "a failed run leaves nothing behind";
}

TEST(CliValidate, NamesABadDatabase) {
  const fs::path out = scratch("_db");
  expect_one_error("--db /nonexistent/db --out " + out.string(), "/nonexistent/db");
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliValidate, NamesAnUnwritableOutputDirectory) {
  // Below a regular file: no directory can be made there, whoever runs the test (even root).
  const fs::path root = scratch("_out");
  fs::create_directories(root);
  std::ofstream(root / "file") << "x";
  const fs::path out = root / "file" / "report";
  expect_one_error("--out " + out.string(), "--out " + out.string());
  fs::remove_all(root);
}

TEST(CliValidate, ADatabaseAndAReferenceMapExcludeEachOther) {
  // A database brings its own reference map; CLI11 rejects the pair before anything is loaded.
  const fs::path out = scratch("_excl");
  const auto r = run_cli("validate --db /nonexistent/db --reference " + kWorld +
                         "forest.exr --out " + out.string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--db excludes --reference"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace brdfnav::test
