#include <brdfnav/core/cube_root.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace brdfnav {
namespace {

// Units in the last place between two positive finite floats: their bit patterns are ordered.
std::int64_t ulps_between(float a, float b) {
  std::int32_t ia, ib;
  std::memcpy(&ia, &a, sizeof ia);
  std::memcpy(&ib, &b, sizeof ib);
  return std::abs(std::int64_t(ia) - ib);
}

// Every binade of float, subnormals included, at 4096 points each.
TEST(CubeRoot, IsWithinTwoUlpOfLibmOverEveryPositiveFloat) {
  std::int64_t worst = 0;
  float worst_x = 0;
  for (int e = -149; e < 128; ++e)
    for (int k = 0; k < 4096; ++k) {
      const float x = std::ldexp(1.0f + k / 4096.0f, e);
      if (!std::isfinite(x)) continue;
      const std::int64_t d = ulps_between(cube_root(x), std::cbrt(x));
      if (d > worst) worst = d, worst_x = x;
    }
  EXPECT_LE(worst, 2) << "at x = " << worst_x;
}

TEST(CubeRoot, IsExactOnCubes) {
  for (float r : {0.5f, 1.0f, 2.0f, 3.0f, 10.0f, 0.25f}) EXPECT_EQ(cube_root(r * r * r), r);
}

TEST(CubeRoot, GivesZeroForZeroAndNegativesAndNaNForInfinityAndNaN) {
  EXPECT_EQ(cube_root(0.0f), 0.0f);
  EXPECT_EQ(cube_root(-0.0f), 0.0f);
  EXPECT_EQ(cube_root(-8.0f), 0.0f);
  EXPECT_EQ(cube_root(-std::numeric_limits<float>::infinity()), 0.0f);
  EXPECT_TRUE(std::isnan(cube_root(std::numeric_limits<float>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(cube_root(std::numeric_limits<float>::infinity())));
}

}  // namespace
}  // namespace brdfnav
