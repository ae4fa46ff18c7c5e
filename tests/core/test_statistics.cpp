#include <brdfnav/core/statistics.h>

#include <gtest/gtest.h>

namespace brdfnav {
namespace {

TEST(Quantile, InterpolatesBetweenOrderStatistics) {
  const std::vector<double> v{4, 1, 3, 2};  // unsorted on purpose
  EXPECT_DOUBLE_EQ(quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 2.5);  // halfway between 2 and 3, not the upper middle
  EXPECT_DOUBLE_EQ(quantile(v, 0.9), 3.7);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 4.0);
}

TEST(Quantile, OddSampleMedianIsTheMiddleElement) {
  EXPECT_DOUBLE_EQ(quantile({5, 9, 7}, 0.5), 7.0);
  EXPECT_DOUBLE_EQ(quantile({42}, 0.99), 42.0);
}

TEST(Quantile, ClampsQAndRejectsAnEmptySample) {
  EXPECT_DOUBLE_EQ(quantile({1, 2}, -1.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile({1, 2}, 2.0), 2.0);
  EXPECT_THROW(quantile({}, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace brdfnav
