#include <brdfnav/core/material.h>
#include <gtest/gtest.h>

namespace brdfnav {
namespace {

TEST(Params, EveryModelHasAConsistentTable) {
  ASSERT_EQ(models().size(), 6u);
  for (const ModelInfo& m : models()) {
    EXPECT_EQ(&model_info(m.id), &m);
    EXPECT_EQ(find_model(m.name), &m);
    for (const ParamSpec& p : m.params) {
      SCOPED_TRACE(std::string(m.name) + "." + std::string(p.name));
      EXPECT_LE(p.valid_min, p.default_value);
      EXPECT_LE(p.default_value, p.valid_max);
      const auto nodes = grid_nodes(p);
      ASSERT_GE(nodes.size(), 2u);
      EXPECT_TRUE(std::is_sorted(nodes.begin(), nodes.end()));
      EXPECT_TRUE(in_valid_range(p, nodes.front()));
      EXPECT_TRUE(in_valid_range(p, nodes.back()));
    }
  }
  EXPECT_EQ(find_model("phong"), nullptr);
}

// Table 1 of the paper: grid sizes of the embedding.
TEST(Params, GridsMatchTableOne) {
  auto count = [](ModelId id, int i) { return grid_nodes(model_info(id).params[i]).size(); };
  EXPECT_EQ(count(ModelId::ward, 0), 15u);
  EXPECT_EQ(count(ModelId::ward, 1), 15u);
  EXPECT_EQ(count(ModelId::blinn_phong, 0), 15u);
  EXPECT_EQ(count(ModelId::cook_torrance, 0), 11u);
  EXPECT_EQ(count(ModelId::cook_torrance, 1), 13u);
  EXPECT_EQ(count(ModelId::he, 0), 8u);
  EXPECT_EQ(count(ModelId::he, 1), 9u);
  EXPECT_EQ(count(ModelId::he, 2), 5u);
  EXPECT_EQ(count(ModelId::lafortune, 0), 14u);
  EXPECT_EQ(count(ModelId::lafortune, 1), 13u);
  EXPECT_EQ(count(ModelId::ggx, 0), 13u);  // not the paper's: alpha 0.01..1, log-spaced
  EXPECT_EQ(count(ModelId::ggx, 1), 13u);
}

TEST(Params, LogGridsAreGeometric) {
  const auto nodes = grid_nodes(model_info(ModelId::he).params[0]);  // sigma, x2 steps
  for (std::size_t i = 1; i < nodes.size(); ++i) EXPECT_NEAR(nodes[i] / nodes[i - 1], 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(nodes.front(), 0.02);
  EXPECT_DOUBLE_EQ(nodes.back(), 2.56);
}

TEST(Params, LafortuneGridResolvesThePhongPoint) {
  const auto nodes = grid_nodes(model_info(ModelId::lafortune).params[0]);
  const double phong = 1 / std::sqrt(3.0);
  int near = 0;
  for (double v : nodes) near += std::abs(v - phong) < 0.05;
  EXPECT_GE(near, 6) << "the cz grid must be dense around 1/sqrt(3)";
}

}  // namespace
}  // namespace brdfnav
