// `brdfnav export --format materialx|cycles` end to end on the test-profile database (the shared
// one of CTest's test_database fixture, else one the suite builds once): the documents renderers
// read, checked against MaterialX 1.38's node definitions and against brdfnav's own renders.
#include "app/cli_runner.h"

#include <brdfnav/core/material.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

#include <OpenImageIO/detail/pugixml/pugixml.hpp>

#include <unistd.h>

#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

namespace brdfnav::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The residuals are rendered at this size: small, for the suite's time.
constexpr int kRes = 16;

// The nodes the MaterialX export uses, as MaterialX 1.38 defines them (its standard library's
// pbrlib and stdlib node definitions): the output type and every input's type.
struct NodeDef {
  std::string output;
  std::map<std::string, std::string> inputs;
};
const std::map<std::string, NodeDef>& materialx_138_nodedefs() {
  static const std::map<std::string, NodeDef> defs{
      {"oren_nayar_diffuse_bsdf",
       {"BSDF",
        {{"weight", "float"}, {"color", "color3"}, {"roughness", "float"}, {"normal", "vector3"}}}},
      {"generalized_schlick_bsdf",
       {"BSDF",
        {{"weight", "float"},
         {"color0", "color3"},
         {"color90", "color3"},
         {"exponent", "float"},
         {"roughness", "vector2"},
         {"normal", "vector3"},
         {"tangent", "vector3"},
         {"distribution", "string"},
         {"scatter_mode", "string"}}}},
      {"add", {"BSDF", {{"in1", "BSDF"}, {"in2", "BSDF"}}}},
      {"surface", {"surfaceshader", {{"bsdf", "BSDF"}, {"edf", "EDF"}, {"opacity", "float"}}}},
      {"surfacematerial",
       {"material",
        {{"surfaceshader", "surfaceshader"}, {"displacementshader", "displacementshader"}}}},
  };
  return defs;
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

class CliExport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("brdfnav_cli_export_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    std::string error;
    db_ = suite_database(root_, error);
    ASSERT_FALSE(db_.empty()) << error;
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  static fs::path file(const std::string& name) { return root_ / name; }
  // The export of `spec` in `format`, written to a file whose text it returns.
  static std::string exported(const std::string& spec, const std::string& format,
                              const std::string& name) {
    const fs::path out = file(name);
    const CliResult r =
        run_cli("export --db " + db_.string() + " --material " + spec + " --format " + format +
                " --res " + std::to_string(kRes) + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_text(out);
  }
  // The ggx equivalent the YAML export lists.
  static Material yaml_equivalent(const std::string& spec) {
    const YAML::Node doc = YAML::Load(exported(spec, "yaml", "export.yaml"));
    const YAML::Node m = doc["equivalents"]["ggx"]["material"];
    std::stringstream s;
    s << "ggx:alpha_x=" << m["params"]["alpha_x"].as<std::string>()
      << ",alpha_y=" << m["params"]["alpha_y"].as<std::string>();
    for (const char* key : {"rho_d", "rho_s"})
      s << "," << key << "=" << m[key][0].as<std::string>() << "/" << m[key][1].as<std::string>()
        << "/" << m[key][2].as<std::string>();
    return parse_material_spec(s.str());
  }
  // brdfnav's image distance between renders of two materials at kRes.
  static double rendered_distance(const std::string& a, const std::string& b) {
    for (const auto& [spec, name] : {std::pair{a, "a.exr"}, std::pair{b, "b.exr"}}) {
      const CliResult r = run_cli("render --material " + spec + " --res " + std::to_string(kRes) +
                                  " --out " + file(name).string());
      EXPECT_EQ(r.exit_code, 0) << r.err;
    }
    const CliResult d =
        run_cli("distance " + file("a.exr").string() + " " + file("b.exr").string());
    EXPECT_EQ(d.exit_code, 0) << d.err;
    return std::stod(d.out);
  }

  static inline fs::path root_, db_;
};

const std::string kWard = "ward:alpha_x=0.05,alpha_y=0.2,rho_d=0.1/0.15/0.2,rho_s=0.5";

// Every node and input of the document is one MaterialX 1.38 defines, with its type; the
// connections join outputs to inputs of the same type; one surfacematerial; the values are the
// ggx equivalent's.
TEST_F(CliExport, MaterialxIsAMaterialx138DocumentOfTheGgxEquivalent) {
  const std::string text = exported(kWard, "materialx", "export.mtlx");
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(text.c_str(), pugi::parse_default | pugi::parse_comments)) << text;
  const pugi::xml_node root = doc.child("materialx");
  ASSERT_TRUE(root);
  EXPECT_STREQ(root.attribute("version").value(), "1.38");
  EXPECT_STREQ(root.attribute("colorspace").value(), "lin_rec709");
  std::map<std::string, std::string> output_of;  // node name -> its output type
  int materials = 0;
  for (const pugi::xml_node node : root.children()) {
    if (node.type() != pugi::node_element) continue;
    const std::string kind = node.name();
    const auto def = materialx_138_nodedefs().find(kind);
    ASSERT_NE(def, materialx_138_nodedefs().end()) << kind << " is not a node the export uses";
    EXPECT_EQ(node.attribute("type").value(), def->second.output) << kind;
    output_of[node.attribute("name").value()] = node.attribute("type").value();
    materials += kind == "surfacematerial";
    for (const pugi::xml_node input : node.children("input")) {
      const std::string name = input.attribute("name").value();
      const auto type = def->second.inputs.find(name);
      ASSERT_NE(type, def->second.inputs.end()) << kind << "." << name;
      EXPECT_EQ(input.attribute("type").value(), type->second) << kind << "." << name;
      if (const pugi::xml_attribute from = input.attribute("nodename")) {
        ASSERT_TRUE(output_of.count(from.value())) << from.value() << " is not defined before";
        EXPECT_EQ(output_of[from.value()], type->second) << kind << "." << name;
      }
    }
  }
  EXPECT_EQ(materials, 1);

  const Material ggx = yaml_equivalent(kWard);
  const std::map<std::string, std::string> names{{"oren_nayar_diffuse_bsdf", "brdfnav_diffuse"},
                                                 {"generalized_schlick_bsdf", "brdfnav_specular"}};
  auto input = [&](const std::string& node, const char* name) {
    return root.find_child_by_attribute(node.c_str(), "name", names.at(node).c_str())
        .find_child_by_attribute("input", "name", name)
        .attribute("value")
        .value();
  };
  auto value = [&](const std::string& node, const char* name) {
    return numbers(input(node, name));
  };
  const std::vector<double> rho_d = value("oren_nayar_diffuse_bsdf", "color");
  const std::vector<double> rho_s = value("generalized_schlick_bsdf", "color0");
  const std::vector<double> alpha = value("generalized_schlick_bsdf", "roughness");
  ASSERT_EQ(rho_d.size(), 3u);
  ASSERT_EQ(rho_s.size(), 3u);
  ASSERT_EQ(alpha.size(), 2u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(rho_d[c], ggx.rho_d[c], 1e-8 * ggx.rho_d[c]);
    EXPECT_NEAR(rho_s[c], ggx.rho_s[c], 1e-8 * ggx.rho_s[c]);
  }
  EXPECT_EQ(value("generalized_schlick_bsdf", "color90"), rho_s);
  EXPECT_EQ(value("oren_nayar_diffuse_bsdf", "roughness"), std::vector<double>{0.0});
  EXPECT_NEAR(alpha[0], ggx.params[0], 1e-8 * ggx.params[0]);
  EXPECT_NEAR(alpha[1], ggx.params[1], 1e-8 * ggx.params[1]);
  EXPECT_STREQ(input("generalized_schlick_bsdf", "distribution"), "ggx");

  // The comment states the residual and MaterialX's two terms.
  const std::string comment = root.first_child().value();
  for (const char* said : {"differs from what brdfnav showed of the chosen",
                           "- masking-shadowing: Smith's height-correlated G2",
                           "- energy compensation", "rendered at"})
    EXPECT_NE(comment.find(said), std::string::npos) << said << " in\n" << comment;
}

// The Cycles export holds the ggx equivalent and the residual, which is brdfnav's image distance
// between the renders of the chosen material and the equivalent.
TEST_F(CliExport, CyclesHoldsTheEquivalentAndItsRenderedResidual) {
  const json doc = json::parse(exported(kWard, "cycles", "export.json"));
  EXPECT_EQ(doc.at("brdfnav_cycles"), 1);
  const Material ggx = yaml_equivalent(kWard);
  const json& m = doc.at("material");
  EXPECT_EQ(m.at("model"), "ggx");
  EXPECT_EQ(m.at("colorspace"), "lin_rec709");
  EXPECT_DOUBLE_EQ(m.at("params").at("alpha_x").get<double>(), ggx.params[0]);
  EXPECT_DOUBLE_EQ(m.at("params").at("alpha_y").get<double>(), ggx.params[1]);
  for (int c = 0; c < 3; ++c) {
    EXPECT_DOUBLE_EQ(m.at("rho_d")[c].get<double>(), ggx.rho_d[c]);
    EXPECT_DOUBLE_EQ(m.at("rho_s")[c].get<double>(), ggx.rho_s[c]);
  }
  EXPECT_EQ(doc.at("chosen").at("model"), "ward");
  const double residual = doc.at("residual").get<double>();
  EXPECT_GT(residual, 0);
  EXPECT_GT(doc.at("embedded_residual").get<double>(), 0);
  EXPECT_NEAR(residual, rendered_distance(kWard, format_material_spec(ggx)), 1e-6);
  EXPECT_NE(doc.at("residual_metric").get<std::string>().find("16 x 16"), std::string::npos);
}

// A ggx material goes out as it is, with no residual.
TEST_F(CliExport, AGgxMaterialIsExportedAsItIs) {
  const std::string spec = "ggx:alpha_x=0.04,alpha_y=0.3,rho_d=0.05/0.1/0.2,rho_s=0.9/0.6/0.3";
  const json doc = json::parse(exported(spec, "cycles", "ggx.json"));
  EXPECT_EQ(doc.at("residual").get<double>(), 0.0);
  EXPECT_EQ(doc.at("material"), doc.at("chosen"));
  EXPECT_DOUBLE_EQ(doc.at("material").at("params").at("alpha_y").get<double>(), 0.3);
  const std::string mtlx = exported(spec, "materialx", "ggx.mtlx");
  EXPECT_NE(mtlx.find("The chosen material, exported as it is"), std::string::npos) << mtlx;
  EXPECT_NE(mtlx.find("value=\"0.04, 0.3\""), std::string::npos) << mtlx;
}

TEST_F(CliExport, AnUnknownFormatIsRefusedWithTheChoices) {
  const CliResult r = run_cli("export --db " + db_.string() + " --material ward --format usd" +
                              " --out " + file("x").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("yaml"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("materialx"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(file("x")));
}

}  // namespace
}  // namespace brdfnav::test
