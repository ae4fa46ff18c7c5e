#include <brdfnav/core/grid.h>
#include <brdfnav/core/models.h>
#include <gtest/gtest.h>

#include <numeric>

namespace brdfnav {
namespace {

TEST(ParamGrid, IndexesEveryNodeOnce) {
  const ParamGrid grid(model_info(ModelId::he).params);
  ASSERT_EQ(grid.node_count(), 8u * 9u * 5u);
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    const auto multi = grid.multi_index(node);
    EXPECT_EQ(grid.node_index(multi), node);
  }
  const auto last = grid.node_values(grid.node_count() - 1);
  EXPECT_DOUBLE_EQ(last[0], 2.56);
  EXPECT_DOUBLE_EQ(last[1], 128.0);
  EXPECT_DOUBLE_EQ(last[2], 9.0);
}

TEST(ParamGrid, CoordinatesFollowTheParameterScale) {
  const ParamGrid grid(model_info(ModelId::he).params);
  // sigma is a log axis with x2 steps: the geometric mean of two nodes is half-way.
  EXPECT_NEAR(grid.grid_coordinate(0, std::sqrt(0.02 * 0.04)), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(grid.grid_coordinate(0, 0.001), 0.0);  // clamped below
  EXPECT_DOUBLE_EQ(grid.grid_coordinate(0, 100.0), 7.0);  // clamped above
  for (double v : {0.02, 0.05, 0.3, 2.0, 2.56})
    EXPECT_NEAR(grid.value_at(0, grid.grid_coordinate(0, v)), v, 1e-12 * v);
  // eta has explicit nodes {1.2, 1.5, 2, 4, 9} on a log axis.
  EXPECT_NEAR(grid.grid_coordinate(2, std::sqrt(2.0 * 4.0)), 2.5, 1e-12);
}

TEST(ParamGrid, CornersInterpolateMultilinearly) {
  const ParamGrid grid(model_info(ModelId::ward).params);
  const std::vector<double> at_node = grid.node_values(37);
  const auto exact = grid.corners(at_node);
  ASSERT_EQ(exact.size(), 1u);
  EXPECT_EQ(exact[0].node, 37u);

  // A function linear in the grid coordinates is reproduced exactly.
  const auto f = [&](std::size_t node) {
    const auto m = grid.multi_index(node);
    return 3.0 * double(m[0]) - 2.0 * double(m[1]) + 1.0;
  };
  const std::vector<double> values{0.0123, 0.31};
  const auto corners = grid.corners(values);
  EXPECT_EQ(corners.size(), 4u);
  double sum = 0, w = 0;
  for (const auto& c : corners) sum += c.weight * f(c.node), w += c.weight;
  EXPECT_NEAR(w, 1.0, 1e-12);
  EXPECT_NEAR(sum,
              3 * grid.grid_coordinate(0, values[0]) - 2 * grid.grid_coordinate(1, values[1]) + 1,
              1e-9);
}

}  // namespace
}  // namespace brdfnav
