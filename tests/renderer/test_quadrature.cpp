// The quadrature's cached angles (renderer/src/quadrature_scratch.h): what GridAngles and
// outline_angles() return is what std::sin and std::cos give for the same angles, to the bit, so
// that the images do not depend on what the caches held before.
#include "quadrature_scratch.h"

#include <gtest/gtest.h>

#include <cmath>

namespace brdfnav {
namespace {

void expect_grid(GridAngles& angles, int width, int height) {
  angles.use(width, height);
  for (int y = 0; y < height; ++y) {
    const double theta = (y + 0.5) * (kPi / height);
    EXPECT_EQ(angles.row(y), Vec2(std::sin(theta), std::cos(theta))) << "row " << y;
  }
  for (int x = 0; x < width; ++x) {
    const double phi = 2 * kPi * ((x + 0.5) / width - 0.5);
    EXPECT_EQ(angles.column(x), Vec2(std::sin(phi), std::cos(phi))) << "column " << x;
  }
}

TEST(GridAngles, AreThoseOfTheGridInUseAcrossSwitches) {
  GridAngles angles;
  expect_grid(angles, 64, 32);
  expect_grid(angles, 96, 48);
  expect_grid(angles, 64, 32);  // the first grid's values again, not the second's
  expect_grid(angles, 64, 48);  // the same width, another height
}

TEST(GridAngles, AreComputedOnFirstUseInAnyOrder) {
  GridAngles angles;
  angles.use(40, 20);
  for (int y = 19; y >= 0; y -= 3) {
    const double theta = (y + 0.5) * (kPi / 20);
    EXPECT_EQ(angles.row(y), Vec2(std::sin(theta), std::cos(theta)));
    EXPECT_EQ(angles.row(y), Vec2(std::sin(theta), std::cos(theta)));  // cached
  }
}

TEST(OutlineAngles, AreTheCosineAndSineOfTwoPiJOverN) {
  for (int n : {4, 32, 36, 128, kMaxOutlineAngles}) {
    const Vec2* angles = outline_angles(n);
    for (int j = 0; j <= n; ++j) {
      const double t = 2 * kPi * j / n;
      EXPECT_EQ(angles[j], Vec2(std::cos(t), std::sin(t))) << "n " << n << ", j " << j;
    }
  }
}

}  // namespace
}  // namespace brdfnav
