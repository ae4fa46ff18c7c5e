// The precompute profiles: every named profile holds a grid for every model, in the model
// registry's order, inside each parameter's valid range, so a model added to the registry but not
// to a profile fails here by name instead of leaving a database without it.
#include <brdfnav/precompute/profile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>

namespace brdfnav {
namespace {

TEST(Profile, EveryNamedProfileHoldsEveryModelInRegistryOrder) {
  for (const std::string& name : profile_names()) {
    const Profile p = make_profile(name);
    EXPECT_EQ(p.name, name);
    ASSERT_EQ(p.grids.size(), models().size()) << name;
    for (std::size_t k = 0; k < models().size(); ++k) {
      const ModelInfo& info = models()[k];
      EXPECT_EQ(p.grids[k].model, info.id) << name << ": grid " << k << " is not " << info.name;
      EXPECT_EQ(p.grid(info.id), &p.grids[k].grid) << name << ": " << info.name;
    }
  }
}

TEST(Profile, GridNodesIncreaseInsideTheValidRanges) {
  for (const std::string& name : profile_names()) {
    const Profile p = make_profile(name);
    for (const ProfileGrid& g : p.grids) {
      const ModelInfo& info = model_info(g.model);
      ASSERT_EQ(g.grid.dimensions(), info.params.size()) << name << ": " << info.name;
      for (std::size_t d = 0; d < g.grid.dimensions(); ++d) {
        const std::vector<double>& axis = g.grid.axis(d);
        const std::string where =
            name + ": " + std::string(info.name) + "." + std::string(info.params[d].name);
        EXPECT_GE(axis.size(), 2u) << where;
        // Strictly increasing: no node is <= the one before it.
        EXPECT_TRUE(std::is_sorted(axis.begin(), axis.end(), std::less_equal<>())) << where;
        for (double v : axis) EXPECT_TRUE(in_valid_range(info.params[d], v)) << where << " " << v;
      }
    }
  }
}

// The paper's profile renders the tables' own grids (Table 1 of the paper with this project's
// ranges): its table gives Blinn-Phong 15 nodes, Ward 15 x 15, Cook-Torrance 11 x 13, Lafortune
// 14 x 13 and He 8 x 9 x 5, plus the one diffuse image; GGX, which the paper does not have,
// 13 x 13. The default profile renders the same grids but He's and Lafortune's, denser where
// the table's left the thumbnails' blend far from the render (profile.cpp).
TEST(Profile, PaperAndDefaultRenderTheTablesGrids) {
  constexpr std::size_t kOthers = 1 + 15 + 15 * 15 + 11 * 13 + 13 * 13;
  const std::map<std::string, std::size_t> images{{"paper", kOthers + 14 * 13 + 8 * 9 * 5},
                                                  {"default", kOthers + 91 * 19 + 15 * 17 * 10}};
  for (const auto& [name, count] : images) {
    const Profile p = make_profile(name);
    EXPECT_EQ(p.image_count(), count) << name;
    EXPECT_EQ(p.pca.components, 200) << name;  // the paper's "first 200 coefficients"
    for (const ProfileGrid& g : p.grids) {
      if (name == "default" && (g.model == ModelId::he || g.model == ModelId::lafortune)) continue;
      const ParamGrid table(model_info(g.model).params);
      for (std::size_t d = 0; d < table.dimensions(); ++d)
        EXPECT_EQ(g.grid.axis(d), table.axis(d)) << name << " " << model_info(g.model).name;
    }
  }
  EXPECT_EQ(make_profile("paper").resolution, 320);  // the paper's 320 x 320 images
  EXPECT_EQ(make_profile("default").resolution, 128);
}

// Steps between neighbouring nodes of an axis, in the parameter's scale.
std::vector<double> steps(const ParamSpec& spec, const std::vector<double>& axis) {
  std::vector<double> out;
  for (std::size_t k = 1; k < axis.size(); ++k)
    out.push_back(to_scale(spec, axis[k]) - to_scale(spec, axis[k - 1]));
  return out;
}

// He's denser axes keep the table's ranges but eta's, which starts at 1.1. sigma and tau are
// evenly spaced in their (log) scale; eta's steps in log eta grow by 1.3 from 1.1, where the
// Fresnel factor turns fastest.
TEST(Profile, DefaultHeAxesAreEvenOrGradedInLogScale) {
  const Profile p = make_profile("default");
  const ParamGrid& he = *p.grid(ModelId::he);
  const ParamGrid table(model_info(ModelId::he).params);
  const std::size_t counts[] = {15, 17, 10};
  for (std::size_t d = 0; d < 3; ++d) {
    const ParamSpec& spec = model_info(ModelId::he).params[d];
    const std::vector<double> axis = he.axis(d);
    ASSERT_EQ(axis.size(), counts[d]) << spec.name;
    EXPECT_NEAR(axis.front(), d == 2 ? 1.1 : table.axis(d).front(), 1e-12) << spec.name;
    EXPECT_NEAR(axis.back(), table.axis(d).back(), 1e-12) << spec.name;
    const std::vector<double> s = steps(spec, axis);
    for (std::size_t k = 1; k < s.size(); ++k)
      EXPECT_NEAR(s[k] / s[k - 1], d == 2 ? 1.3 : 1.0, 1e-9) << spec.name << " step " << k;
  }
}

// Lafortune's cz axis crowds around the switch at 1/sqrt(3), 2e-5 apart there, from 0 to 1, each
// step 1.21 times the one nearer the switch (within a percent), with the switch its kink node; n is
// 19 nodes evenly spaced in log n over the table's range.
TEST(Profile, DefaultLafortuneCzAxisIsGradedAroundTheSwitch) {
  const Profile p = make_profile("default");
  const ParamGrid& laf = *p.grid(ModelId::lafortune);
  const std::vector<double> cz = laf.axis(0);
  ASSERT_EQ(cz.size(), 91u);
  EXPECT_EQ(cz.front(), 0.0);
  EXPECT_EQ(cz.back(), 1.0);
  const double c0 = 1 / std::sqrt(3.0);
  const auto at = std::find(cz.begin(), cz.end(), c0);
  ASSERT_NE(at, cz.end());
  const std::size_t i0 = std::size_t(at - cz.begin());
  EXPECT_EQ(i0, 46u);
  EXPECT_EQ(laf.kink_node(0), i0);
  EXPECT_NEAR(cz[i0] - cz[i0 - 1], 2e-5, 1e-15);
  EXPECT_NEAR(cz[i0 + 1] - cz[i0], 2e-5, 1e-15);
  for (std::size_t k = i0 + 2; k < cz.size(); ++k)
    EXPECT_NEAR((cz[k] - cz[k - 1]) / (cz[k - 1] - cz[k - 2]), 1.21, 0.012) << "above, node " << k;
  for (std::size_t k = 2; k <= i0; ++k)
    EXPECT_NEAR((cz[k - 1] - cz[k - 2]) / (cz[k] - cz[k - 1]), 1.21, 0.012) << "below, node " << k;
  const ParamSpec& n = model_info(ModelId::lafortune).params[1];
  const std::vector<double> s = steps(n, laf.axis(1));
  ASSERT_EQ(s.size(), 18u);
  for (double step : s) EXPECT_NEAR(step, s.front(), 1e-12);
}

TEST(Profile, SmallProfilesRenderSixteenPixelsSquare) {
  for (const char* name : {"test", "smoke"}) EXPECT_EQ(make_profile(name).resolution, 16) << name;
}

TEST(Profile, AnUnknownNameIsAnErrorNamingItAndTheKnownOnes) {
  try {
    make_profile("papr");
    FAIL() << "no error";
  } catch (const ProfileError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'papr'"), std::string::npos) << what;
    for (const std::string& name : profile_names())
      EXPECT_NE(what.find(name), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace brdfnav
