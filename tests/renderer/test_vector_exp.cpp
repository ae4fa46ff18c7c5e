// exp_in_place(): the quadrature's vector exp agrees with std::exp wherever it is used.
#include "vector_exp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace brdfnav {
namespace {

// Every length from 0 to 11, so that the four-lane part and the tail both run, over exponents
// from the underflow (-745) to 0 (Ward's are never positive) and a few positive ones.
TEST(VectorExp, AgreesWithStdExpToFourUlpsAtEveryLength) {
  for (int n = 0; n < 12; ++n) {
    Eigen::ArrayXd v(n), expected(n);
    for (int i = 0; i < n; ++i) {
      v[i] = -745.0 * i / 11 + (i % 3 == 2 ? 3.5 : 0.0);
      expected[i] = std::exp(v[i]);
    }
    exp_in_place(v);
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(v[i], expected[i], 4 * std::numeric_limits<double>::epsilon() * expected[i])
          << "length " << n << ", element " << i;
  }
}

TEST(VectorExp, KeepsTheSpecialValues) {
  const double inf = std::numeric_limits<double>::infinity();
  Eigen::ArrayXd v(8);
  v << -inf, 0.0, -0.0, std::nan(""), -1e300, 1e300, -inf, std::nan("");
  exp_in_place(v);
  EXPECT_EQ(v[0], 0.0);
  EXPECT_EQ(v[1], 1.0);
  EXPECT_EQ(v[2], 1.0);
  EXPECT_TRUE(std::isnan(v[3]));
  EXPECT_EQ(v[4], 0.0);
  EXPECT_EQ(v[5], inf);
  EXPECT_EQ(v[6], 0.0);
  EXPECT_TRUE(std::isnan(v[7]));
}

}  // namespace
}  // namespace brdfnav
