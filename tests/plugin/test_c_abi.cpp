// libbrdfnav.so as a host sees it (plugin_api.h): nothing but brdfnav.h through dlopen().
// Results are compared with the C++ core, linked into this test directly.
#include "plugin_api.h"

#include <brdfnav/core/material.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <barrier>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>

namespace brdfnav {
namespace {

using ::testing::HasSubstr;

using test::api;

// Owns a closure created through the ABI.
struct ClosureHandle {
  brdfnav_closure* closure = nullptr;
  ~ClosureHandle() { api().closure_destroy(closure); }
};

// The direction the library evaluates: normalised exactly as brdfnav_closure_eval does.
Vec3 unit(const double w[3]) {
  const Vec3 v(w[0], w[1], w[2]);
  return v / v.stableNorm();
}

class CAbi : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_NO_THROW(api()); }
  const test::Api& c = api();
};

TEST_F(CAbi, EnumeratesTheCoreModelTables) {
  ASSERT_EQ(c.model_count(), kModelCount);
  for (int index = 0; index < kModelCount; ++index) {
    const ModelInfo& info = model_info(static_cast<ModelId>(index));
    brdfnav_model_desc model;
    ASSERT_EQ(c.get_model(index, &model), BRDFNAV_OK);
    EXPECT_EQ(model.name, info.name);
    EXPECT_EQ(model.title, info.title);
    EXPECT_EQ(model.param_count, static_cast<int>(info.params.size()));
    EXPECT_EQ(model.has_mirror, info.has_mirror ? 1 : 0);
    int found = -1;
    ASSERT_EQ(c.find_model(model.name, &found), BRDFNAV_OK);
    EXPECT_EQ(found, index);
    for (int i = 0; i < model.param_count; ++i) {
      const ParamSpec& spec = info.params[i];
      brdfnav_param_desc p;
      ASSERT_EQ(c.get_param(index, i, &p), BRDFNAV_OK);
      EXPECT_EQ(p.name, spec.name);
      EXPECT_EQ(p.unit, spec.unit);
      EXPECT_EQ(p.description, spec.description);
      EXPECT_EQ(p.valid_min, spec.valid_min);
      EXPECT_EQ(p.valid_max, spec.valid_max);
      EXPECT_EQ(p.default_value, spec.default_value);
      EXPECT_EQ(p.grid_min, spec.grid_min);
      EXPECT_EQ(p.grid_max, spec.grid_max);
      EXPECT_EQ(p.grid_count, spec.grid_count);
      EXPECT_EQ(p.scale, spec.scale == Scale::log ? BRDFNAV_SCALE_LOG : BRDFNAV_SCALE_LINEAR);
      EXPECT_EQ(std::vector<double>(p.nodes, p.nodes + p.node_count),
                std::vector<double>(spec.nodes.begin(), spec.nodes.end()));
    }
    brdfnav_param_desc past_end;
    EXPECT_EQ(c.get_param(index, model.param_count, &past_end), BRDFNAV_ERROR_INVALID_ARGUMENT);
    EXPECT_THAT(c.geterror(), HasSubstr("parameter index"));
  }
  brdfnav_model_desc none;
  EXPECT_EQ(c.get_model(kModelCount, &none), BRDFNAV_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(c.get_model(-1, &none), BRDFNAV_ERROR_INVALID_ARGUMENT);
  int found = -1;
  EXPECT_EQ(c.find_model("phong", &found), BRDFNAV_ERROR_INVALID_ARGUMENT);
  EXPECT_THAT(c.geterror(), HasSubstr("phong"));
}

// A valid material with parameters drawn from the grid nodes (named in shuffled order, as a host
// may pass them) and random colours.
Material random_material(ModelId id, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit01(0.0, 1.0);
  Material m = default_material(id);
  for (std::size_t i = 0; i < m.params.size(); ++i) {
    const std::vector<double> nodes = grid_nodes(model_info(id).params[i]);
    m.params[i] = nodes[rng() % nodes.size()];
  }
  for (int k = 0; k < 3; ++k) {
    m.rho_d[k] = unit01(rng) * 0.8;
    m.rho_s[k] = unit01(rng) * 2.0;
  }
  return m;
}

// Random directions, some below the horizon, of random length (the ABI normalises).
void random_direction(std::mt19937_64& rng, double w[3]) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double x = u(rng), y = u(rng), z = u(rng);  // in this order under every compiler
  Vec3 v(x, y, z * 0.6 + 0.4);
  v *= 0.5 + 1.25 * (u(rng) + 1);
  for (int k = 0; k < 3; ++k) w[k] = v[k];
}

TEST_F(CAbi, StructClosuresMatchTheCoreForEveryModel) {
  std::mt19937_64 rng(510);
  std::uniform_real_distribution<double> unit01(0.0, 1.0);
  for (const ModelInfo& info : models()) {
    SCOPED_TRACE(std::string(info.name));
    for (int trial = 0; trial < 20; ++trial) {
      const Material m = random_material(info.id, rng);
      std::vector<std::string> names;
      for (const ParamSpec& p : info.params) names.emplace_back(p.name);
      std::vector<brdfnav_param_value> params;
      for (std::size_t i = 0; i < m.params.size(); ++i)
        params.push_back({names[i].c_str(), m.params[i]});
      std::shuffle(params.begin(), params.end(), rng);
      const std::string model_name(info.name);
      const brdfnav_material desc{model_name.c_str(),
                                  params.data(),
                                  params.size(),
                                  {m.rho_d[0], m.rho_d[1], m.rho_d[2]},
                                  {m.rho_s[0], m.rho_s[1], m.rho_s[2]},
                                  nullptr};
      ClosureHandle h;
      ASSERT_EQ(c.closure_create(&desc, &h.closure), BRDFNAV_OK) << c.geterror();
      const Closure reference = make_closure(m);
      for (int k = 0; k < 50; ++k) {
        double wi[3], wo[3], f[3], pdf = -1;
        random_direction(rng, wi);
        random_direction(rng, wo);
        ASSERT_EQ(c.closure_eval(h.closure, wi, wo, f), BRDFNAV_OK);
        const Rgb expected = reference.eval(unit(wi), unit(wo));
        for (int ch = 0; ch < 3; ++ch) EXPECT_DOUBLE_EQ(f[ch], expected[ch]);
        ASSERT_EQ(c.closure_pdf(h.closure, wi, wo, &pdf), BRDFNAV_OK);
        EXPECT_DOUBLE_EQ(pdf, reference.pdf(unit(wi), unit(wo)));

        const double uc = unit01(rng), u1 = unit01(rng), u2 = unit01(rng);
        brdfnav_sample s;
        ASSERT_EQ(c.closure_sample(h.closure, wo, uc, u1, u2, &s), BRDFNAV_OK);
        const auto expected_sample = reference.sample(unit(wo), uc, Vec2(u1, u2));
        ASSERT_EQ(s.sampled, expected_sample.has_value() ? 1 : 0);
        if (!expected_sample) continue;
        EXPECT_EQ(s.is_delta, expected_sample->delta ? 1 : 0);
        EXPECT_DOUBLE_EQ(s.pdf, expected_sample->pdf);
        for (int ch = 0; ch < 3; ++ch) {
          EXPECT_DOUBLE_EQ(s.wi[ch], expected_sample->wi[ch]);
          EXPECT_DOUBLE_EQ(s.f[ch], expected_sample->f[ch]);
        }
      }
    }
  }
}

TEST_F(CAbi, HeSamplesItsMirrorTerm) {
  ClosureHandle h;
  ASSERT_EQ(c.closure_load("he:sigma=0.02,tau=8,eta=4,rho_d=0,rho_s=1", &h.closure), BRDFNAV_OK)
      << c.geterror();
  const double wo[3] = {0.6, 0.0, 0.8};
  brdfnav_sample s;
  // A smooth surface: the mirror term dominates, so uc near 0 picks it.
  ASSERT_EQ(c.closure_sample(h.closure, wo, 0.0, 0.5, 0.5, &s), BRDFNAV_OK);
  ASSERT_EQ(s.sampled, 1);
  EXPECT_EQ(s.is_delta, 1);
  EXPECT_DOUBLE_EQ(s.wi[0], -0.6);
  EXPECT_DOUBLE_EQ(s.wi[1], 0.0);
  EXPECT_DOUBLE_EQ(s.wi[2], 0.8);
}

// A scratch directory per test process: ctest runs these cases in parallel.
std::filesystem::path scratch_dir() {
  const auto dir =
      std::filesystem::temp_directory_path() / ("brdfnav_test_c_abi_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

TEST_F(CAbi, LoadsSpecsAndYamlFiles) {
  const double wi[3] = {0.2, -0.1, 0.9}, wo[3] = {-0.3, 0.2, 0.8};
  const char* spec = "cook_torrance:f0=0.3,m=0.2,rho_d=0.1/0.2/0.3,rho_s=0.7";
  ClosureHandle from_spec;
  ASSERT_EQ(c.closure_load(spec, &from_spec.closure), BRDFNAV_OK) << c.geterror();
  double f[3];
  ASSERT_EQ(c.closure_eval(from_spec.closure, wi, wo, f), BRDFNAV_OK);
  const Rgb expected = make_closure(parse_material_spec(spec)).eval(unit(wi), unit(wo));
  for (int ch = 0; ch < 3; ++ch) EXPECT_DOUBLE_EQ(f[ch], expected[ch]);

  const auto dir = scratch_dir();
  const auto path = dir / "lafortune.yaml";
  std::ofstream(path) << "brdfnav_material: 1\nmodel: lafortune\nparams: {cz: 0.56, n: 64}\n"
                         "rho_d: [0.1, 0.2, 0.3]\nrho_s: [0.5, 0.6, 0.7]\ncolorspace: acescg\n";
  ClosureHandle from_file;
  ASSERT_EQ(c.closure_load(path.c_str(), &from_file.closure), BRDFNAV_OK) << c.geterror();
  Material m = default_material(ModelId::lafortune);
  m.params = {0.56, 64};
  m.rho_d = Rgb(0.1, 0.2, 0.3);
  m.rho_s = Rgb(0.5, 0.6, 0.7);
  ASSERT_EQ(c.closure_eval(from_file.closure, wi, wo, f), BRDFNAV_OK);
  const Rgb expected_file = make_closure(m).eval(unit(wi), unit(wo));
  for (int ch = 0; ch < 3; ++ch) EXPECT_DOUBLE_EQ(f[ch], expected_file[ch]);
  const char* colorspace = nullptr;
  ASSERT_EQ(c.closure_colorspace(from_file.closure, &colorspace), BRDFNAV_OK);
  EXPECT_STREQ(colorspace, "acescg");
  int model = -1;
  ASSERT_EQ(c.closure_model(from_file.closure, &model), BRDFNAV_OK);
  EXPECT_EQ(model, static_cast<int>(ModelId::lafortune));
  std::filesystem::remove_all(dir);
}

// On failure: the documented status, a message naming the problem, outputs left alone.
TEST_F(CAbi, RejectsBadMaterialsWithStatusAndMessage) {
  const auto dir = scratch_dir();
  const auto bad_file = dir / "bad.yaml";
  std::ofstream(bad_file) << "brdfnav_material: 1\nmodel: ward\nparams: {alpha_x: 0.1}\n";
  const auto missing_file = dir / "missing.yaml";
  const struct {
    std::string input;
    brdfnav_status status;
    std::string message;
  } cases[] = {
      {"ward:alpha_x=rough", BRDFNAV_ERROR_PARSE, "alpha_x"},
      {"ward:alpha_x=5", BRDFNAV_ERROR_PARSE, "params.alpha_x"},
      {"phong:n=5", BRDFNAV_ERROR_PARSE, "unknown model 'phong'"},
      {bad_file.string(), BRDFNAV_ERROR_PARSE, bad_file.string() + ":3: params.alpha_y: missing"},
      {missing_file.string(), BRDFNAV_ERROR_IO, missing_file.string()},
  };
  for (const auto& bad : cases) {
    SCOPED_TRACE(bad.input);
    // Not null beforehand, so that the test sees the library reset it.
    int sentinel = 0;
    brdfnav_closure* closure = reinterpret_cast<brdfnav_closure*>(&sentinel);
    EXPECT_EQ(c.closure_load(bad.input.c_str(), &closure), bad.status);
    EXPECT_EQ(closure, nullptr);
    EXPECT_THAT(c.geterror(), HasSubstr(bad.message));
  }
  std::filesystem::remove_all(dir);

  const brdfnav_param_value unknown[] = {{"alpha_z", 0.1}};
  const brdfnav_param_value twice[] = {{"alpha_x", 0.1}, {"alpha_x", 0.2}};
  const brdfnav_param_value out_of_range[] = {{"alpha_y", 3.0}};
  const brdfnav_param_value unnamed[] = {{nullptr, 0.1}};
  const brdfnav_material structs[] = {
      {"ward", unknown, 1, {0.2, 0.2, 0.2}, {0.04, 0.04, 0.04}, nullptr},
      {"ward", twice, 2, {0.2, 0.2, 0.2}, {0.04, 0.04, 0.04}, nullptr},
      {"ward", out_of_range, 1, {0.2, 0.2, 0.2}, {0.04, 0.04, 0.04}, nullptr},
      {"ward", unnamed, 1, {0.2, 0.2, 0.2}, {0.04, 0.04, 0.04}, nullptr},
      {"ward", nullptr, 1, {0.2, 0.2, 0.2}, {0.04, 0.04, 0.04}, nullptr},
      {"ward", nullptr, 0, {0.2, 2.0, 0.2}, {0.04, 0.04, 0.04}, nullptr},
      {"ward", nullptr, 0, {0.2, 0.2, 0.2}, {0.04, NAN, 0.04}, nullptr},
      {"blinn", nullptr, 0, {0.2, 0.2, 0.2}, {0.04, 0.04, 0.04}, nullptr},
      {nullptr, nullptr, 0, {0.2, 0.2, 0.2}, {0.04, 0.04, 0.04}, nullptr},
  };
  const char* messages[] = {"alpha_z", "twice", "params.alpha_y", "name", "params",
                            "rho_d",   "rho_s", "blinn",          "model"};
  for (std::size_t i = 0; i < std::size(structs); ++i) {
    SCOPED_TRACE(messages[i]);
    brdfnav_closure* closure = nullptr;
    EXPECT_EQ(c.closure_create(&structs[i], &closure), BRDFNAV_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(closure, nullptr);
    EXPECT_THAT(c.geterror(), HasSubstr(messages[i]));
  }
}

TEST_F(CAbi, RejectsNullPointersAndBadDirections) {
  ClosureHandle h;
  ASSERT_EQ(c.closure_load("ward", &h.closure), BRDFNAV_OK);
  const double up[3] = {0, 0, 1}, zero[3] = {0, 0, 0}, nan[3] = {0, NAN, 1},
               inf[3] = {INFINITY, 0, 1};
  double f[3] = {-7, -7, -7}, pdf = -7;
  brdfnav_sample s{};
  s.pdf = -7;
  auto expect_invalid = [&](brdfnav_status status, const char* what) {
    EXPECT_EQ(status, BRDFNAV_ERROR_INVALID_ARGUMENT) << what;
    EXPECT_THAT(c.geterror(), HasSubstr(what));
  };
  expect_invalid(c.closure_eval(nullptr, up, up, f), "closure");
  expect_invalid(c.closure_eval(h.closure, nullptr, up, f), "wi");
  expect_invalid(c.closure_eval(h.closure, up, nullptr, f), "wo");
  expect_invalid(c.closure_eval(h.closure, up, up, nullptr), "f");
  expect_invalid(c.closure_eval(h.closure, zero, up, f), "wi is the zero vector");
  expect_invalid(c.closure_eval(h.closure, up, nan, f), "wo is not finite");
  expect_invalid(c.closure_eval(h.closure, inf, up, f), "wi is not finite");
  expect_invalid(c.closure_pdf(h.closure, up, zero, &pdf), "wo is the zero vector");
  expect_invalid(c.closure_pdf(h.closure, up, up, nullptr), "pdf");
  expect_invalid(c.closure_sample(h.closure, zero, 0.5, 0.5, 0.5, &s), "wo is the zero vector");
  expect_invalid(c.closure_sample(h.closure, up, 0.5, 0.5, 0.5, nullptr), "out");
  expect_invalid(c.closure_sample(h.closure, up, 1.0, 0.5, 0.5, &s), "uc");
  expect_invalid(c.closure_sample(h.closure, up, 0.5, NAN, 0.5, &s), "u1");
  expect_invalid(c.closure_sample(h.closure, up, 0.5, 0.5, -0.1, &s), "u2");
  brdfnav_closure* not_created = nullptr;
  expect_invalid(c.closure_create(nullptr, &not_created), "material");
  expect_invalid(c.closure_load(nullptr, &not_created), "path_or_spec");
  expect_invalid(c.closure_load("ward", nullptr), "out");
  expect_invalid(c.closure_colorspace(h.closure, nullptr), "colorspace");
  expect_invalid(c.closure_model(nullptr, nullptr), "closure");
  expect_invalid(c.get_model(0, nullptr), "out");
  expect_invalid(c.get_param(0, 0, nullptr), "out");
  expect_invalid(c.find_model(nullptr, nullptr), "name");
  // Failed calls leave their outputs alone.
  EXPECT_EQ(f[0], -7);
  EXPECT_EQ(pdf, -7);
  EXPECT_EQ(s.pdf, -7);
  c.closure_destroy(nullptr);
}

// Each thread sees its own last error, even when both fail at the same time.
TEST_F(CAbi, ErrorsArePerThread) {
  std::barrier both_failed(2);
  std::string seen_a, seen_b, seen_c;
  std::thread a([&] {
    brdfnav_closure* closure = nullptr;
    EXPECT_EQ(c.closure_load("phong:n=5", &closure), BRDFNAV_ERROR_PARSE);
    both_failed.arrive_and_wait();
    seen_a = c.geterror();
  });
  std::thread b([&] {
    int model = 0;
    EXPECT_EQ(c.find_model("glossy", &model), BRDFNAV_ERROR_INVALID_ARGUMENT);
    both_failed.arrive_and_wait();
    seen_b = c.geterror();
  });
  std::thread no_failure([&] { seen_c = c.geterror(); });
  a.join();
  b.join();
  no_failure.join();
  EXPECT_THAT(seen_a, HasSubstr("phong"));
  EXPECT_THAT(seen_a, ::testing::Not(HasSubstr("glossy")));
  EXPECT_THAT(seen_b, HasSubstr("glossy"));
  EXPECT_THAT(seen_b, ::testing::Not(HasSubstr("phong")));
  EXPECT_EQ(seen_c, "");
}

}  // namespace
}  // namespace brdfnav
