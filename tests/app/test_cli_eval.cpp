#include "app/cli_runner.h"

#include <brdfnav/core/material.h>
#include <gtest/gtest.h>

#include <cstdlib>

namespace brdfnav::test {
namespace {

Rgb parse_rgb(const std::string& text) {
  Rgb v;
  std::istringstream in(text);
  in >> v[0] >> v[1] >> v[2];
  EXPECT_TRUE(in) << "not three numbers: " << text;
  return v;
}

TEST(CliEval, MatchesTheCoreClosure) {
  const std::string spec = "ward:alpha_x=0.1,alpha_y=0.05,rho_d=0.2/0.3/0.4,rho_s=0.04";
  const auto r = run_cli("eval --material " + spec + " --wi 0,0.5,1 --wo 0.3,0,1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Closure c = make_closure(parse_material_spec(spec));
  const Rgb expected = c.eval(Vec3(0, 0.5, 1).normalized(), Vec3(0.3, 0, 1).normalized());
  const Rgb got = parse_rgb(r.out);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected[i], 1e-8 * expected[i]);  // %.9g
}

TEST(CliEval, ReadsAYamlMaterialFile) {
  const auto path = std::filesystem::temp_directory_path() / "brdfnav_cli_eval_material.yaml";
  std::ofstream(path) << "brdfnav_material: 1\nmodel: blinn_phong\nparams: {n: 50}\n"
                         "rho_d: [0.1, 0.1, 0.1]\nrho_s: [1, 1, 1]\ncolorspace: lin_rec709\n";
  const auto r = run_cli("eval --material " + path.string() + " --wi 0,0,1 --wo 0,0,1");
  std::filesystem::remove(path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // At wi = wo = n, cos_h = 1: f = 0.1/pi + (50 + 2)/(8 pi).
  const double expected = 0.1 / kPi + 52.0 / (8 * kPi);
  const Rgb got = parse_rgb(r.out);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expected, 1e-8 * expected);
}

TEST(CliEval, BelowTheHorizonIsZero) {
  const auto r = run_cli("eval --material blinn_phong:n=10 --wi 0,0,-1 --wo 0,0,1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "0 0 0\n");
}

// Any finite non-zero vector is a direction: components near the ends of double's range must
// neither overflow the length (1e300 squared is inf) nor read as zero.
TEST(CliEval, NormalisesHugeAndTinyDirections) {
  const auto unit = run_cli("eval --material ward --wi 0,0.5,1 --wo 0,0,1");
  ASSERT_EQ(unit.exit_code, 0) << unit.err;
  ASSERT_NE(unit.out, "0 0 0\n");
  for (const char* wi : {"0,0.5e300,1e300", "0,0.5e-300,1e-300", "0,5e-14,1e-13"}) {
    SCOPED_TRACE(wi);
    const auto r = run_cli(std::string("eval --material ward --wi ") + wi + " --wo 0,0,1");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, unit.out);
  }
}

TEST(CliEval, RejectsBadDirections) {
  for (const char* wi : {"0,0,0", "nan,0,1", "1,2", "1,2,3,4", "a,b,c", "inf,0,1"}) {
    SCOPED_TRACE(wi);
    const auto r = run_cli(std::string("eval --material ward --wi ") + wi + " --wo 0,0,1");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("--wi"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
}

TEST(CliEval, RejectsBadMaterials) {
  struct Case {
    const char* spec;
    const char* message;
  };
  for (const Case& c :
       {Case{"phong:n=10", "unknown model 'phong'"}, Case{"ward:alpha=0.1", "unknown key 'alpha'"},
        Case{"ward:alpha_x=-1", "params.alpha_x"},
        Case{"ward:alpha_x=abc", "'abc' is not a number"},
        Case{"ward:rho_d=0.1/0.2", "expected one value or r/g/b"}, Case{"ward:rho_d=2", "rho_d"}}) {
    SCOPED_TRACE(c.spec);
    const auto r = run_cli(std::string("eval --material ") + c.spec + " --wi 0,0,1 --wo 0,0,1");
    EXPECT_EQ(r.exit_code, 3);  // a malformed spec
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
}

// Each kind of failure has its exit status, whichever layer failed, and the help lists them.
TEST(CliHelp, ExitStatusSaysWhatKindOfFailure) {
  const struct {
    std::string args;
    int status;
    std::string phrase;
  } cases[] = {
      {"eval --material ward --wi 0,0,0 --wo 0,0,1", 2, "--wi: direction has zero length"},
      {"eval --material ward:alpha_x=abc --wi 0,0,1 --wo 0,0,1", 3, "'abc' is not a number"},
      {"eval --material /nonexistent/m.yaml --wi 0,0,1 --wo 0,0,1", 4, "no such material file"},
      {"neighbors --db /nonexistent/brdfnav-db --material ward --radius 0.05", 5,
       "--db: /nonexistent/brdfnav-db"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.exit_code, c.status) << r.err;
    EXPECT_NE(r.err.find("brdfnav: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.phrase), std::string::npos) << r.err;
    // Only a wrong command line points at the help.
    EXPECT_EQ(r.err.find("Run 'brdfnav --help'") != std::string::npos, c.status == 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  const auto help = run_cli("--help");
  EXPECT_NE(help.out.find("Exit status: 0 done; 1 an internal failure; 2 a wrong command line"),
            std::string::npos)
      << help.out;
}

TEST(CliHelp, EveryCommandHasHelp) {
  for (const char* cmd : {"", "eval ", "models ", "demo "}) {
    SCOPED_TRACE(cmd);
    const auto r = run_cli(std::string(cmd) + "--help");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << r.out;
  }
}

// A command line that does not parse: one "brdfnav: error:" line naming what is wrong, then the
// way to the help, and exit status 2 (CLI11's own codes were 105 to 109).
TEST(CliHelp, UsageErrorsNameTheProblemAndExitWith2) {
  const struct {
    std::string args, phrase;
  } cases[] = {
      {"", "brdfnav: error: a command is required"},
      {"rendr --material ward", "brdfnav: error: unknown command 'rendr' (did you mean 'render'?)"},
      {"frobnicate", "brdfnav: error: unknown command 'frobnicate'; commands: eval,"},
      {"render --out x.exr", "brdfnav: error: --material"},
      {"render --material ward --res abc --out x.exr", "brdfnav: error: --res"},
      {"eval --material ward --wi 0,0,1 --wo 0,0,1 --bogus", "brdfnav: error: "},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(c.phrase), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("Run 'brdfnav --help'"), std::string::npos) << r.err;
  }
  // A material name that is no file, model or spec says so (it said "unknown model 'chosen'").
  const auto r = run_cli("eval --material chosen --wi 0,0,1 --wo 0,0,1");
  EXPECT_EQ(r.exit_code, 4);  // a file that cannot be read
  EXPECT_NE(r.err.find("brdfnav: error: chosen: no such material file, and not a model name"),
            std::string::npos)
      << r.err;
}

TEST(CliModels, DocsAreGeneratedFromTheTables) {
  const auto r = run_cli("models --markdown");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, read_text(std::filesystem::path(BRDFNAV_SOURCE_DIR) / "docs/MODELS.md"))
      << "docs/MODELS.md is stale: regenerate it with `brdfnav models --markdown`";
}

TEST(CliDemo, WritesThePlotAndTables) {
  const auto dir = std::filesystem::temp_directory_path() / "brdfnav_cli_demo";
  std::filesystem::remove_all(dir);
  const auto r = run_cli("demo --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"lobes.png", "lobes.csv", "albedo.csv"})
    EXPECT_GT(std::filesystem::file_size(dir / f), 100u) << f;
  EXPECT_NE(r.out.find("Directional albedo"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace brdfnav::test
