#include <brdfnav/core/grid.h>
#include <brdfnav/core/models.h>
#include <gtest/gtest.h>

#include <cmath>
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

// Sum of weight * f(node) over corners.
template <typename F>
double interpolate(const std::vector<ParamGrid::Corner>& corners, F f) {
  double sum = 0;
  for (const auto& c : corners) sum += c.weight * f(c.node);
  return sum;
}

TEST(ParamGrid, CubicCornersReproduceQuadraticsInsideAndAtTheEnds) {
  const ParamGrid grid(model_info(ModelId::ward).params);  // 15 x 15 nodes
  const std::vector<double> at_node = grid.node_values(37);
  const auto exact = grid.cubic_corners(at_node);
  ASSERT_EQ(exact.size(), 1u);
  EXPECT_EQ(exact[0].node, 37u);

  const auto coordinate = [&](std::size_t node, std::size_t d) {
    return double(grid.multi_index(node)[d]);
  };
  const auto quadratic = [&](std::size_t node) {
    const double x = coordinate(node, 0), y = coordinate(node, 1);
    return 0.5 * x * x - x * y + 2 * y * y - 3 * x + 1;
  };
  // Coordinates (4.37, 9.81): both cells have two nodes on either side; (0.3, 13.6): first and
  // last cells, where the slopes come from the three nodes at the end.
  for (const auto& [x, y] : {std::pair{4.37, 9.81}, std::pair{0.3, 13.6}}) {
    const std::vector<double> values{grid.value_at(0, x), grid.value_at(1, y)};
    const auto corners = grid.cubic_corners(values);
    EXPECT_EQ(corners.size(), x > 1 ? 16u : 9u);
    EXPECT_NEAR(interpolate(corners, [](std::size_t) { return 1.0; }), 1.0, 1e-12);
    EXPECT_NEAR(interpolate(corners, quadratic), 0.5 * x * x - x * y + 2 * y * y - 3 * x + 1, 1e-9)
        << x << " " << y;
  }
}

// On graded nodes the spline follows their spacing: a quadratic in the parameter's scale is
// reproduced everywhere (Catmull-Rom in grid coordinates would be off by the steps' unevenness).
TEST(ParamGrid, CubicCornersFollowGradedNodes) {
  const ParamSpec& eta = model_info(ModelId::he).params[2];  // log scale
  std::vector<double> nodes{1.1};
  for (double step = 0.05; nodes.size() < 10; step *= 1.3)
    nodes.push_back(nodes.back() * std::exp(step));
  const ParamGrid grid(model_info(ModelId::he).params, {{0.1, 0.2}, {4.0, 8.0}, nodes});
  const auto f = [](double x) { return 2 * x * x - 3 * x + 0.5; };
  const auto at_node = [&](std::size_t node) {
    return f(to_scale(eta, grid.node_values(node)[2]));
  };
  for (double c = 0; c <= 9; c += 0.125) {
    const double v = grid.value_at(2, c);
    const auto corners = grid.cubic_corners(std::vector<double>{0.1, 4.0, v});
    EXPECT_NEAR(interpolate(corners, at_node), f(to_scale(eta, v)), 1e-9) << c;
  }
}

TEST(ParamGrid, CubicCornersAreSmoothAcrossNodes) {
  const ParamGrid grid(model_info(ModelId::blinn_phong).params);
  const auto f = [](std::size_t node) { return std::sin(0.7 * double(node)); };
  const auto at = [&](double c) {
    return interpolate(grid.cubic_corners(std::vector<double>{grid.value_at(0, c)}), f);
  };
  // One-sided slopes either side of node 5 agree (the multilinear ones jump there).
  const double h = 1e-6;
  const double left = (at(5.0) - at(5.0 - h)) / h, right = (at(5.0 + h) - at(5.0)) / h;
  EXPECT_NEAR(left, right, 1e-4);
  const auto linear_at = [&](double c) {
    return interpolate(grid.corners(std::vector<double>{grid.value_at(0, c)}), f);
  };
  EXPECT_GT(std::abs((linear_at(5.0) - linear_at(5.0 - h)) / h -
                     (linear_at(5.0 + h) - linear_at(5.0)) / h),
            0.1);
}

// Lafortune's cz kinks at 1/sqrt(3): the spline on either side of that node uses no node across
// it, so a function with a corner there is reproduced exactly, where a spline reaching across
// would round the corner off. The table's 0.57735 counts as the kink.
TEST(ParamGrid, CubicCornersDoNotReachAcrossAKink) {
  const ParamSpec& cz = model_info(ModelId::lafortune).params[0];
  const double c0 = 1 / std::sqrt(3.0);
  const ParamGrid grid(model_info(ModelId::lafortune).params,
                       {{0.55, 0.56, 0.57, c0, 0.58, 0.59, 0.6}, {10.0, 100.0}});
  ASSERT_EQ(grid.kink_node(0), 3u);
  EXPECT_EQ(grid.kink_node(1), ParamGrid::kNoKink);
  EXPECT_EQ(ParamGrid(model_info(ModelId::lafortune).params).kink_node(0), 7u);  // 0.57735
  EXPECT_EQ(ParamGrid(model_info(ModelId::ward).params).kink_node(0), ParamGrid::kNoKink);
  // A corner at the kink, linear on each side (in cz's linear scale), with the sides' slopes apart.
  const auto corner_at = [&](double v) { return v < c0 ? 2 * (c0 - v) : 5 * (v - c0); };
  const auto corner = [&](std::size_t node) { return corner_at(grid.node_values(node)[0]); };
  for (double c : {2.25, 2.5, 2.9, 3.0, 3.1, 3.5, 3.75}) {
    const std::vector<double> values{grid.value_at(0, c), 10.0};
    const auto corners = grid.cubic_corners(values);
    for (const auto& k : corners) {
      const std::size_t i = grid.multi_index(k.node)[0];
      EXPECT_TRUE(c < 3.0 ? i <= 3 : i >= 3) << "coordinate " << c << " reaches node " << i;
    }
    EXPECT_NEAR(interpolate(corners, [](std::size_t) { return 1.0; }), 1.0, 1e-12) << c;
    EXPECT_NEAR(interpolate(corners, corner), corner_at(values[0]), 1e-12) << c;
  }
  // Away from the kink the spline is the plain one: four nodes along cz.
  EXPECT_EQ(grid.cubic_corners(std::vector<double>{grid.value_at(0, 1.5), 10.0}).size(), 4u);
  EXPECT_EQ(cz.name, "cz");
}

TEST(ParamGrid, CubicCornersOfATwoNodeAxisAreLinear) {
  const ParamGrid grid(model_info(ModelId::blinn_phong).params, {{2.0, 200.0}});
  const auto corners = grid.cubic_corners(std::vector<double>{20.0});  // half-way on the log axis
  ASSERT_EQ(corners.size(), 2u);
  EXPECT_NEAR(corners[0].weight, 0.5, 1e-12);
  EXPECT_NEAR(corners[1].weight, 0.5, 1e-12);
}

TEST(ParamGrid, CellsAreTheBoxesBetweenNodes) {
  // Ward: alpha_x and alpha_y, 3 x 4 nodes on log axes -> 2 x 3 cells, alpha_x fastest.
  const ParamGrid grid(model_info(ModelId::ward).params,
                       {{0.01, 0.1, 1.0}, {0.01, 0.02, 0.04, 0.08}});
  EXPECT_EQ(grid.cell_count(), 6u);
  EXPECT_EQ(grid.cell_index(std::vector<double>{0.5, 0.03}), 1u + 2u * 1u);
  // A value on a node belongs to the cell above it, the last node to the cell below.
  EXPECT_EQ(grid.cell_index(std::vector<double>{0.1, 0.01}), 1u);
  EXPECT_EQ(grid.cell_index(std::vector<double>{1.0, 0.08}), 1u + 2u * 2u);
  // Outside the grid: clamped to its boxes.
  EXPECT_EQ(grid.cell_index(std::vector<double>{5.0, 0.001}), 1u);
  // The centre in grid coordinates: half-way on the log scale.
  const std::vector<double> mid = grid.cell_midpoint(1u + 2u * 2u);
  EXPECT_NEAR(mid[0], std::sqrt(0.1 * 1.0), 1e-12);
  EXPECT_NEAR(mid[1], std::sqrt(0.04 * 0.08), 1e-12);
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    EXPECT_EQ(grid.cell_index(grid.cell_midpoint(c)), c);
}

}  // namespace
}  // namespace brdfnav
