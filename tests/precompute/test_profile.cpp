// The precompute profiles: every named profile holds a grid for every model, in the model
// registry's order, inside each parameter's valid range, so a model added to the registry but not
// to a profile fails here by name instead of leaving a database without it.
#include <brdfnav/precompute/profile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
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

// The paper's profile and the default one render the tables' own grids (Table 1 of the paper
// with this project's ranges): its table gives Blinn-Phong 15 nodes, Ward 15 x 15,
// Cook-Torrance 11 x 13, Lafortune 14 x 13 and He 8 x 9 x 5, plus the one diffuse image; GGX,
// which the paper does not have, 13 x 13.
TEST(Profile, PaperAndDefaultRenderTheTablesGrids) {
  constexpr std::size_t kTableImages = 1 + 15 + 15 * 15 + 11 * 13 + 14 * 13 + 8 * 9 * 5 + 13 * 13;
  for (const char* name : {"paper", "default"}) {
    const Profile p = make_profile(name);
    EXPECT_EQ(p.image_count(), kTableImages) << name;
    EXPECT_EQ(p.pca.components, 200) << name;  // the paper's "first 200 coefficients"
    for (const ProfileGrid& g : p.grids) {
      const ParamGrid table(model_info(g.model).params);
      for (std::size_t d = 0; d < table.dimensions(); ++d)
        EXPECT_EQ(g.grid.axis(d), table.axis(d)) << name << " " << model_info(g.model).name;
    }
  }
  EXPECT_EQ(make_profile("paper").resolution, 320);  // the paper's 320 x 320 images
  EXPECT_EQ(make_profile("default").resolution, 128);
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
