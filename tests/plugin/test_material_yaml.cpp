// The material YAML format: exact round trips for every model, and every rejection names the
// file, the line and the key.
#include <brdfnav/io/material_yaml.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <unistd.h>
#include <algorithm>
#include <bit>
#include <cstdint>
#include <fstream>
#include <random>

namespace brdfnav {
namespace {

using ::testing::HasSubstr;

bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void expect_identical(const Material& a, const Material& b) {
  EXPECT_EQ(a.model, b.model);
  ASSERT_EQ(a.params.size(), b.params.size());
  for (std::size_t i = 0; i < a.params.size(); ++i)
    EXPECT_TRUE(same_bits(a.params[i], b.params[i])) << a.params[i] << " vs " << b.params[i];
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(same_bits(a.rho_d[c], b.rho_d[c])) << a.rho_d[c] << " vs " << b.rho_d[c];
    EXPECT_TRUE(same_bits(a.rho_s[c], b.rho_s[c])) << a.rho_s[c] << " vs " << b.rho_s[c];
  }
  EXPECT_EQ(a.colorspace, b.colorspace);
}

// A parameter value anywhere in its valid range: half of the draws log/linear-uniform over the
// grid, the rest uniform over the valid range, plus the range ends and a subnormal near zero.
double random_param(const ParamSpec& p, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  switch (rng() % 8) {
    case 0:
      return p.valid_min;
    case 1:
      return p.valid_max;
    case 2:
      return p.valid_min == 0 ? 1e-310 : p.valid_min;
    case 3:
    case 4:
    case 5: {
      const double lo = to_scale(p, p.grid_min), hi = to_scale(p, p.grid_max);
      return std::clamp(from_scale(p, lo + unit(rng) * (hi - lo)), p.valid_min, p.valid_max);
    }
    default:
      return p.valid_min + unit(rng) * (p.valid_max - p.valid_min);
  }
}

Material random_material(ModelId id, std::mt19937_64& rng) {
  // Names that YAML would read as null, a boolean, a number or a comment unless quoted.
  static const std::vector<std::string> kColorspaces{
      "lin_rec709", "ACES - ACEScg", "null", "true", "1.5", "a: b #c", "say \"hi\"", "~"};
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Material m = default_material(id);
  for (std::size_t i = 0; i < m.params.size(); ++i)
    m.params[i] = random_param(model_info(id).params[i], rng);
  for (int c = 0; c < 3; ++c) {
    m.rho_d[c] = unit(rng) * kRhoDMax;
    m.rho_s[c] = unit(rng) * kRhoSMax;
  }
  m.colorspace = kColorspaces[rng() % kColorspaces.size()];
  return m;
}

TEST(MaterialYaml, RoundTripIsBitExactForEveryModel) {
  std::mt19937_64 rng(20060626);
  for (const ModelInfo& info : models()) {
    for (int trial = 0; trial < 300; ++trial) {
      const Material m = random_material(info.id, rng);
      const std::string text = material_to_yaml(m);
      SCOPED_TRACE(text);
      expect_identical(parse_material_yaml(text, "round_trip.yaml"), m);
    }
  }
}

TEST(MaterialYaml, WritesTheDocumentedSchema) {
  Material m = default_material(ModelId::ward);
  m.params = {0.1, 1e-4};
  m.rho_d = Rgb(0.2, 0.25, 0.5);
  m.rho_s = Rgb::Constant(0.04);
  EXPECT_EQ(material_to_yaml(m),
            "brdfnav_material: 1\n"
            "model: ward\n"
            "params: {alpha_x: 0.1, alpha_y: 1.0e-04}\n"
            "rho_d: [0.2, 0.25, 0.5]\n"
            "rho_s: [0.04, 0.04, 0.04]\n"
            "colorspace: \"lin_rec709\"\n");
}

TEST(MaterialYaml, DoesNotWriteAnInvalidMaterial) {
  Material m = default_material(ModelId::ward);
  m.params[0] = -1;
  EXPECT_THROW(material_to_yaml(m), MaterialError);
}

// A scratch directory per test process: ctest runs the cases of this file in parallel.
class MaterialYamlFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("brdfnav_test_yaml_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }
  std::filesystem::path dir_;
};

TEST_F(MaterialYamlFiles, WriteThenReadIsExactAndLeavesNoTemporary) {
  std::mt19937_64 rng(7);
  const Material m = random_material(ModelId::he, rng);
  const auto path = dir_ / "he.yaml";
  write_material_yaml(path, m);
  expect_identical(read_material_yaml(path), m);
  expect_identical(load_material(path.string()), m);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_), {}), 1);
}

TEST_F(MaterialYamlFiles, LoadMaterialTellsFilesFromSpecs) {
  const Material spec = load_material("ward:alpha_x=0.2,alpha_y=0.3,rho_d=0.1");
  EXPECT_EQ(spec.model, ModelId::ward);
  EXPECT_EQ(spec.params, (std::vector<double>{0.2, 0.3}));
  // Any existing file is YAML, whatever its extension.
  Material m = default_material(ModelId::lafortune);
  const auto txt = write("lafortune.txt", material_to_yaml(m));
  expect_identical(load_material(txt.string()), m);
  // A *.yaml path that does not exist is a missing file, not a spec with an unknown model.
  const std::string missing = (dir_ / "missing.YAML").string();
  try {
    load_material(missing);
    FAIL() << "no error";
  } catch (const MaterialError& e) {
    EXPECT_THAT(e.what(), HasSubstr(missing));
    EXPECT_EQ(e.code(), ErrorCode::io);
  }
  for (const auto& unreadable : {dir_ / "missing.yml", dir_}) {
    try {
      read_material_yaml(unreadable);
      FAIL() << unreadable << ": no error";
    } catch (const MaterialError& e) {
      EXPECT_EQ(e.code(), ErrorCode::io) << e.what();
    }
  }
  // A name that is neither a file, a model nor a spec (a file name without its .yaml, a path) is
  // reported as the missing file it most likely is, with what would have been accepted.
  for (const std::string& name : {std::string("chosen"), (dir_ / "chosen").string()}) {
    try {
      load_material(name);
      FAIL() << name << ": no error";
    } catch (const MaterialError& e) {
      EXPECT_EQ(e.code(), ErrorCode::io);
      EXPECT_THAT(e.what(), HasSubstr(name + ": no such material file, and not a model name"));
      EXPECT_THAT(e.what(), HasSubstr("models: blinn_phong, ward"));
    }
  }
  // A model name alone is a spec with the model's defaults.
  EXPECT_EQ(load_material("he").model, ModelId::he);
}

TEST_F(MaterialYamlFiles, ErrorsInAFileNameItsPath) {
  const auto path = write("bad.yaml",
                          "brdfnav_material: 1\nmodel: ward\nparams: {alpha_x: 0.1, alpha_y: 7}\n"
                          "rho_d: [0.2, 0.2, 0.2]\nrho_s: [0.04, 0.04, 0.04]\n"
                          "colorspace: lin_rec709\n");
  try {
    read_material_yaml(path);
    FAIL() << "no error";
  } catch (const MaterialError& e) {
    EXPECT_THAT(e.what(), HasSubstr(path.string() + ":3: params.alpha_y: 7 is outside"));
  }
}

TEST(MaterialYaml, InlineSpecRejectsDuplicateKeys) {
  try {
    parse_material_spec("ward:alpha_x=0.1,alpha_y=0.2,alpha_x=0.3");
    FAIL() << "no error";
  } catch (const MaterialError& e) {
    EXPECT_THAT(e.what(), HasSubstr("alpha_x"));
    EXPECT_THAT(e.what(), HasSubstr("twice"));
  }
}

TEST(MaterialYaml, EmbeddedMaterialsReportLinesOfTheWholeDocument) {
  const YAML::Node doc = YAML::Load(
      "neighbours:\n"
      "  - distance: 0.5\n"
      "    material:\n"
      "      model: blinn_phong\n"
      "      params: {n: 40}\n"
      "      rho_d: [0.1, 0.1, 0.1]\n"
      "      rho_s: [0.5, 0.5, 0.5]\n"
      "      colorspace: lin_rec709\n"
      "  - distance: 0.7\n"
      "    material:\n"
      "      model: blinn_phong\n"
      "      params: {n: -3}\n"
      "      rho_d: [0.1, 0.1, 0.1]\n"
      "      rho_s: [0.5, 0.5, 0.5]\n"
      "      colorspace: lin_rec709\n");
  const Material first = material_from_node(doc["neighbours"][0]["material"], "db.yaml", false);
  EXPECT_EQ(first.params, std::vector<double>{40});
  try {
    material_from_node(doc["neighbours"][1]["material"], "db.yaml", false);
    FAIL() << "no error";
  } catch (const MaterialError& e) {
    EXPECT_THAT(e.what(), HasSubstr("db.yaml:12: params.n: -3 is outside"));
  }
  try {
    material_from_node(doc["neighbours"][0]["material"], "db.yaml", true);
    FAIL() << "no error";
  } catch (const MaterialError& e) {
    EXPECT_THAT(e.what(), HasSubstr("db.yaml:4: brdfnav_material: missing"));
  }
}

// One rejected document: the message must start with "bad.yaml:LINE: KEY:".
struct Rejection {
  const char* what;
  std::string text;
  int line;
  const char* key;
};

// The valid document the cases edit, one key per line (lines 1 to 6).
const std::string kSchema = "brdfnav_material: 1\n";
const std::string kModel = "model: ward\n";
const std::string kParams = "params: {alpha_x: 0.1, alpha_y: 0.05}\n";
const std::string kRhoD = "rho_d: [0.2, 0.2, 0.2]\n";
const std::string kRhoS = "rho_s: [0.04, 0.04, 0.04]\n";
const std::string kColorspace = "colorspace: lin_rec709\n";

std::string doc_with(int line, const std::string& replacement) {
  std::string lines[] = {kSchema, kModel, kParams, kRhoD, kRhoS, kColorspace};
  lines[line - 1] = replacement;
  std::string text;
  for (const std::string& l : lines) text += l;
  return text;
}

std::vector<Rejection> rejections() {
  const std::string valid = doc_with(1, kSchema);
  return {
      {"unknown top-level key", valid + "gloss: 0.5\n", 7, "gloss"},
      {"unknown parameter", doc_with(3, "params: {alpha_x: 0.1, alpha_y: 0.05, beta: 1}\n"), 3,
       "params.beta"},
      {"missing key", doc_with(5, ""), 1, "rho_s"},
      {"missing schema key", doc_with(1, ""), 1, "brdfnav_material"},
      {"missing parameter", doc_with(3, "params: {alpha_x: 0.1}\n"), 3, "params.alpha_y"},
      {"missing parameter, block style", doc_with(3, "params:\n  alpha_x: 0.1\n"), 3,
       "params.alpha_y"},
      {"string for a number", doc_with(3, "params: {alpha_x: rough, alpha_y: 0.05}\n"), 3,
       "params.alpha_x"},
      {"quoted number", doc_with(3, "params: {alpha_x: \"0.1\", alpha_y: 0.05}\n"), 3,
       "params.alpha_x"},
      {"map for params", doc_with(3, "params: [0.1, 0.05]\n"), 3, "params"},
      {"map where a list is", doc_with(4, "rho_d: {r: 0.2, g: 0.2, b: 0.2}\n"), 4, "rho_d"},
      {"scalar where a list is", doc_with(4, "rho_d: 0.2\n"), 4, "rho_d"},
      {"two colour components", doc_with(5, "rho_s: [0.04, 0.04]\n"), 5, "rho_s"},
      {"string component, block list", doc_with(4, "rho_d:\n  - 0.2\n  - red\n  - 0.2\n"), 6,
       "rho_d[1]"},
      {"parameter out of range", doc_with(3, "params:\n  alpha_x: 0.1\n  alpha_y: 7\n"), 5,
       "params.alpha_y"},
      {"negative parameter", doc_with(3, "params: {alpha_x: -0.1, alpha_y: 0.05}\n"), 3,
       "params.alpha_x"},
      {"rho_d out of range", doc_with(4, "rho_d: [0.2, 1.5, 0.2]\n"), 4, "rho_d"},
      {"negative rho_s", doc_with(5, "rho_s: [0.04, -0.04, 0.04]\n"), 5, "rho_s"},
      {"NaN parameter", doc_with(3, "params: {alpha_x: 0.1, alpha_y: .nan}\n"), 3,
       "params.alpha_y"},
      {"infinite component", doc_with(4, "rho_d: [.inf, 0.2, 0.2]\n"), 4, "rho_d[0]"},
      {"negative infinity", doc_with(5, "rho_s: [0.04, 0.04, -.Inf]\n"), 5, "rho_s[2]"},
      {"schema version 2", doc_with(1, "brdfnav_material: 2\n"), 1, "brdfnav_material"},
      {"schema version not a number", doc_with(1, "brdfnav_material: one\n"), 1,
       "brdfnav_material"},
      {"unknown model", doc_with(2, "model: phong\n"), 2, "model"},
      {"model is a list", doc_with(2, "model: [ward]\n"), 2, "model"},
      {"duplicate top-level key", valid + "model: ward\n", 7, "model"},
      {"duplicate parameter", doc_with(3, "params: {alpha_x: 0.1, alpha_y: 0.05, alpha_x: 0.2}\n"),
       3, "params.alpha_x"},
      {"colorspace without a value", doc_with(6, "colorspace:\n"), 6, "colorspace"},
      {"empty colorspace", doc_with(6, "colorspace: \"\"\n"), 6, "colorspace"},
      // Noncharacters: yaml-cpp would write either as U+FFFD, a different name.
      {"colorspace with U+FDD0", doc_with(6, "colorspace: \"lin\\uFDD0\"\n"), 6, "colorspace"},
      {"colorspace with U+10FFFF", doc_with(6, "colorspace: \"a\\U0010FFFF\"\n"), 6, "colorspace"},
      {"empty file", "", 1, "material"},
      {"comments only", "# a material\n", 1, "material"},
      {"top level is a list", "- ward\n- 0.1\n", 1, "material"},
      {"two documents", valid + "---\n" + valid, 8, "material"},
      {"non-scalar key", valid + "[a, b]: 1\n", 7, "material"},
  };
}

TEST(MaterialYaml, EveryRejectionNamesFileLineAndKey) {
  for (const Rejection& r : rejections()) {
    SCOPED_TRACE(std::string(r.what) + ":\n" + r.text);
    try {
      parse_material_yaml(r.text, "bad.yaml");
      ADD_FAILURE() << "accepted";
    } catch (const MaterialError& e) {
      EXPECT_THAT(e.what(), HasSubstr("bad.yaml:" + std::to_string(r.line) + ": " + r.key + ":"));
    }
  }
}

// yaml-cpp's parser errors carry a position; the message reports its line.
TEST(MaterialYaml, SyntaxErrorsReportTheLine) {
  const struct {
    std::string text;
    int line;
  } cases[] = {
      {doc_with(4, "rho_d: [0.2, 0.2, 0.2]]\n"), 4},
      {doc_with(5, "  rho_s: [0.04, 0.04, 0.04]\n"), 5},
      {doc_with(3, "params: {alpha_x: 0.1, alpha_y: 0.05\n"), 4},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    try {
      parse_material_yaml(c.text, "bad.yaml");
      ADD_FAILURE() << "accepted";
    } catch (const MaterialError& e) {
      EXPECT_THAT(e.what(), HasSubstr("bad.yaml:" + std::to_string(c.line) + ": syntax error"));
    }
  }
}

}  // namespace
}  // namespace brdfnav
