// The environment pyramid's hot texels merged by the nodes of each level
// (renderer/src/env_pyramid.h): every hot texel in one group, the power kept, each group's
// radius around its members, and the level chosen for a node size; the nodes' weights, the
// corrected midpoint rule summed by parts.
#include "env_pyramid.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace brdfnav {
namespace {

// A dim map with two lamps of several texels each and three single bright texels.
EnvMap map_with_lamps() {
  const int w = 256, h = 128;
  std::vector<float> rgb(3 * w * h, 0.1f);
  auto light = [&](int x, int y, float r, float g, float b) {
    float* p = &rgb[3 * (static_cast<std::size_t>(y) * w + x)];
    p[0] = r, p[1] = g, p[2] = b;
  };
  for (int y = 32; y < 36; ++y)
    for (int x = 40; x < 45; ++x) light(x, y, 2e4f + 100 * x, 1.5e4f, 1e4f + 50 * y);
  for (int y = 90; y < 92; ++y)
    for (int x = 250; x < 256; ++x) light(x, y, 8e3f, 9e3f, 1.2e4f);  // up to the seam
  light(0, 90, 8e3f, 9e3f, 1.2e4f);
  light(128, 2, 3e4f, 3e4f, 3e4f);  // by the north pole
  light(200, 64, 5e3f, 1e4f, 5e3f);
  return EnvMap(w, h, std::move(rgb), "lamps");
}

double angle(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
}

TEST(EnvPyramid, HotGroupsHoldEveryHotTexelWithItsPower) {
  const EnvPyramid pyramid(map_with_lamps());
  const auto& hot = pyramid.hot();
  ASSERT_EQ(hot.size(), 4u * 5 + 2 * 6 + 3);
  Rgb total = Rgb::Zero();
  for (const auto& t : hot) total += t.radiance * t.solid_angle;
  std::size_t previous = hot.size();
  for (int level = 1; level < pyramid.level_count(); ++level) {
    const auto& groups = pyramid.hot_groups(level);
    EXPECT_LE(groups.size(), previous) << level;
    previous = groups.size();
    Rgb power = Rgb::Zero();
    for (const auto& g : groups) {
      power += g.power;
      EXPECT_NEAR(g.centroid.norm(), 1, 1e-12);
      EXPECT_GE(g.radius, pyramid.node_angle(0));
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(power[c], total[c], 1e-12 * total[c]) << level;
    // Each texel is within the radius of the group of its node.
    for (const auto& t : hot) {
      bool inside = false;
      for (const auto& g : groups)
        inside =
            inside || angle(g.centroid, t.centroid) + pyramid.node_angle(0) <= g.radius + 1e-12;
      EXPECT_TRUE(inside) << "texel " << t.x << ", " << t.y << " at level " << level;
    }
  }
  // The first lamp spans 5 x 4 texels from (40, 32): 3 x 2 nodes of level 1, one of level 3. The
  // seam's lamp stays split in two at every level: its texels are at both ends of the rows.
  EXPECT_EQ(pyramid.hot_groups(1).size(), 6u + 4 + 2);
  EXPECT_EQ(pyramid.hot_groups(3).size(), 1u + 2 + 2);
}

TEST(EnvPyramid, CoarsestLevelIsTheLargestNodeWithinTheStep) {
  const EnvPyramid pyramid(map_with_lamps());
  EXPECT_EQ(pyramid.coarsest_level(0.5 * pyramid.node_angle(0)), 0);
  for (int level = 0; level + 1 < pyramid.level_count(); ++level) {
    EXPECT_EQ(pyramid.coarsest_level(pyramid.node_angle(level)), level);
    EXPECT_EQ(pyramid.coarsest_level(0.99 * pyramid.node_angle(level + 1)), level);
  }
  EXPECT_EQ(pyramid.coarsest_level(100), pyramid.level_count() - 1);
}

// Summed over a whole level, weight * K is the corrected midpoint rule's power * (K + its second
// differences / 24), the rows wrapping around and the first and last rows without neighbours
// beyond the pole, for any K: here one that varies from node to node with no pattern.
TEST(EnvPyramid, WeightsAreTheCorrectedMidpointRuleSummedByParts) {
  const EnvPyramid pyramid(map_with_lamps());
  for (int level = 0; level < pyramid.level_count(); ++level) {
    const int w = pyramid.width(level), h = pyramid.height(level);
    auto k = [&](int x, int y) { return 1.5 + std::sin(0.7 * x + 1.3 * y * y); };
    Rgb rule = Rgb::Zero(), weighed = Rgb::Zero();
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const EnvNode n = pyramid.node(level, x, y);
        double differences =
            k(x > 0 ? x - 1 : w - 1, y) + k(x + 1 < w ? x + 1 : 0, y) - 2 * k(x, y);
        if (y > 0) differences += k(x, y - 1) - k(x, y);
        if (y + 1 < h) differences += k(x, y + 1) - k(x, y);
        rule += n.power * (k(x, y) + differences / 24);
        weighed += n.weight * k(x, y);
      }
    }
    // The weights are stored as floats, like the powers.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(weighed[c], rule[c], 1e-6 * rule[c]) << level;
  }
}

// A node's spread is the luminance-weighted covariance of the directions it covers about its
// centroid: summed here over 8 x 8 pieces of each of its texels, on a map without hot texels
// whose texels differ, away from the poles (where texels are not rectangles).
TEST(EnvPyramid, SpreadIsTheLuminanceWeightedCovarianceOfItsDirections) {
  const int w = 256, h = 128;
  std::vector<float> rgb(3 * w * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        rgb[3 * (std::size_t(y) * w + x) + c] = float(1 + ((x * 7 + y * 13 + c) % 11));
  const EnvPyramid pyramid(EnvMap(w, h, std::move(rgb), "pattern"));
  ASSERT_TRUE(pyramid.hot().empty());
  for (const auto& [level, x, y] : {std::array{0, 5, 37}, {2, 3, 12}, {2, 60, 25}, {3, 1, 9}}) {
    const Vec3 centroid = pyramid.centroid(level, x, y);
    Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
    double total = 0;
    for (int ty = y << level; ty < (y + 1) << level; ++ty)
      for (int tx = x << level; tx < (x + 1) << level; ++tx) {
        const double weight = luminance(pyramid.power(0, tx, ty));
        for_each_texel_piece(tx, ty, w, h, 8, [&](const Vec3& d) {
          sum += weight * (d - centroid) * (d - centroid).transpose();
          total += weight;
        });
      }
    const Eigen::Matrix3d expected = sum / total, got = pyramid.spread(level, x, y);
    // 2%: the pieces are points, and the texels flat rectangles in their tangent planes.
    EXPECT_LT((got - expected).norm(), 0.02 * expected.norm()) << level << " " << x << " " << y;
  }
  EXPECT_LT((pyramid.spread(0, 5, 37) - EnvPyramid::texel_spread(5, 37, w, h)).norm(),
            1e-6 * EnvPyramid::texel_spread(5, 37, w, h).norm());
}

}  // namespace
}  // namespace brdfnav
