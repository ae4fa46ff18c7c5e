// The computations behind `brdfnav validate` on inputs whose answers are known by hand; the
// studies themselves run end to end in tests/app/test_cli_validate.cpp.
#include <brdfnav/studies/validation.h>

#include <gtest/gtest.h>

namespace brdfnav {
namespace {

// A w x h image of one colour, every pixel covered.
Image flat(int w, int h, float r, float g, float b) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float* p = img.pixel(x, y);
      p[0] = r, p[1] = g, p[2] = b, p[3] = 1;
    }
  return img;
}

TEST(Validation, RgbDistanceIsTheRmsOfTheLinearDifference) {
  EXPECT_NEAR(rgb_distance(flat(4, 4, 1, 1, 1), flat(4, 4, 0, 0, 0)), 1.0, 1e-12);
  // Only the red channel differs, by 3: sqrt(9 / 3).
  EXPECT_NEAR(rgb_distance(flat(2, 2, 3, 1, 1), flat(2, 2, 0, 1, 1)), std::sqrt(3.0), 1e-12);
  // Uncovered pixels do not count.
  Image a = flat(2, 1, 5, 5, 5), b = flat(2, 1, 5, 5, 5);
  a.pixel(1, 0)[0] = 100, a.pixel(1, 0)[3] = b.pixel(1, 0)[3] = 0;
  EXPECT_EQ(rgb_distance(a, b), 0.0);
  EXPECT_THROW(rgb_distance(flat(2, 2, 0, 0, 0), flat(3, 2, 0, 0, 0)), ImageError);
}

TEST(Validation, LabDistanceFromWhiteToBlackIsOneHundred) {
  // The white (Y = white_y, D65 chromaticity = equal linear Rec. 709) has L* = 100, a* = b* = 0.
  EXPECT_NEAR(lab_distance(flat(3, 3, 2, 2, 2), flat(3, 3, 0, 0, 0), 2.0), 100.0, 0.05);
  // Twice as bright as the white: L* = 116 cbrt(2) - 16, still neutral.
  EXPECT_NEAR(lab_distance(flat(1, 1, 4, 4, 4), flat(1, 1, 2, 2, 2), 2.0),
              116 * std::cbrt(2.0) - 116, 0.05);
  EXPECT_THROW(lab_distance(flat(1, 1, 1, 1, 1), flat(1, 1, 1, 1, 1), 0.0), ImageError);
  EXPECT_NEAR(mean_luminance(flat(2, 2, 0.5, 0.5, 0.5)), 0.5, 1e-12);
}

TEST(Validation, BrdfDistanceIsASymmetricMetricOnWardLobes) {
  const Material a = ward_sample(0.05), b = ward_sample(0.1), c = ward_sample(0.3);
  EXPECT_EQ(brdf_distance(a, a), 0.0);
  EXPECT_DOUBLE_EQ(brdf_distance(a, b), brdf_distance(b, a));
  EXPECT_GT(brdf_distance(a, c), brdf_distance(b, c));
  // The sharp end dominates (the paper's point against this metric): the same alpha ratio
  // costs far more near the mirror.
  EXPECT_GT(brdf_distance(ward_sample(0.01), ward_sample(0.02)),
            5 * brdf_distance(ward_sample(0.1), ward_sample(0.2)));
}

// A map of 8 x 4 grey texels of luminance 1 with one of 9: the mean over the sphere weighs each
// texel by its solid angle, (2 pi / 8) (cos theta0 - cos theta1) for the rows' band
// [theta0, theta1] = [y, y + 1] pi / 4; the texels' solid angles add up to 4 pi.
TEST(Validation, EnvLuminanceIsThePeakAndTheSolidAngleMean) {
  auto map_with_hot_texel = [](int row) {
    std::vector<float> rgb(8 * 4 * 3, 1.0f);
    for (int c = 0; c < 3; ++c) rgb[3 * (row * 8 + 5) + c] = 9.0f;
    return EnvMap(8, 4, std::move(rgb), "hot texel");
  };
  for (int row : {0, 1}) {
    const double solid_angle =
        2 * kPi / 8 * (std::cos(row * kPi / 4) - std::cos((row + 1) * kPi / 4));
    const EnvLuminance l = env_luminance(map_with_hot_texel(row));
    EXPECT_NEAR(l.peak, 9.0, 1e-6);
    EXPECT_NEAR(l.mean, 1 + 8 * solid_angle / (4 * kPi), 1e-6) << row;
  }
  const EnvLuminance flat_map = env_luminance(EnvMap(4, 2, std::vector<float>(24, 2.5f), "flat"));
  EXPECT_NEAR(flat_map.peak, 2.5, 1e-6);
  EXPECT_NEAR(flat_map.mean, 2.5, 1e-6);
}

TEST(Validation, LineFitScaleAndVariation) {
  const std::vector<double> x{0, 1, 2, 3}, y{1, 3, 5, 7};
  const LineFit f = fit_line(x, y);
  EXPECT_NEAR(f.slope, 2, 1e-12);
  EXPECT_NEAR(f.intercept, 1, 1e-12);
  EXPECT_NEAR(f.r2, 1, 1e-12);
  EXPECT_LT(fit_line(x, std::vector<double>{0, 0, 0, 9}).r2, 0.7);
  EXPECT_THROW(fit_line(std::vector<double>{1, 1}, std::vector<double>{0, 1}),
               std::invalid_argument);

  EXPECT_NEAR(least_squares_scale(std::vector<double>{1, 2}, std::vector<double>{3, 6}), 3, 1e-12);
  EXPECT_EQ(cumulative(std::vector<double>{1, 2, 3}), (std::vector<double>{0, 1, 3, 6}));
  EXPECT_EQ(coefficient_of_variation(std::vector<double>{2, 2, 2}), 0.0);
  EXPECT_NEAR(coefficient_of_variation(std::vector<double>{1, 3}), 0.5, 1e-12);
}

TEST(Validation, EqualStepsInvertsACumulativeCurve) {
  // curve = x^2 on [0, 2]: equal steps of 4/4 fall at sqrt(0, 1, 2, 3, 4), up to interpolation.
  std::vector<double> x, curve;
  for (int i = 0; i <= 200; ++i) x.push_back(i / 100.0), curve.push_back(x.back() * x.back());
  const std::vector<double> at = equal_steps(x, curve, 5);
  ASSERT_EQ(at.size(), 5u);
  for (int j = 0; j < 5; ++j) EXPECT_NEAR(at[j], std::sqrt(double(j)), 1e-3) << j;
  // A flat stretch (no change) is skipped over, not landed in.
  const std::vector<double> flat_curve{0, 0, 0, 1};
  EXPECT_EQ(equal_steps(std::vector<double>{0, 1, 2, 3}, flat_curve, 3),
            (std::vector<double>{0, 2.5, 3}));
}

TEST(Validation, CompareDistancesFindsTheScaleAndTheAgreement) {
  Eigen::MatrixXd ref(3, 3);
  ref << 0, 1, 2, 1, 0, 3, 2, 3, 0;
  const Agreement same = compare_distances(ref, 0.5 * ref, 0.2);
  EXPECT_NEAR(same.scale, 2, 1e-12);
  EXPECT_EQ(same.within, 1.0);
  Eigen::MatrixXd off = ref;
  off(0, 1) = off(1, 0) = 10;  // 2 of the 6 ordered pairs are far off
  EXPECT_LT(compare_distances(ref, off, 0.2).within, 1.0);
}

// Four maps, then a fifth entry (the constant environment) that is not counted. Map 0 agrees
// with 1 and 2 one way only (0.80 the other way); 1, 2 and 3 agree with one another both ways.
TEST(Validation, MapAgreementsCountBothWaysAndTheRuleBreaksTies) {
  Eigen::MatrixXd within(5, 5);
  within << 1.00, 0.90, 0.95, 0.50, 0.99,  //
      0.80, 1.00, 0.90, 0.86, 0.99,        //
      0.80, 0.92, 1.00, 0.88, 0.99,        //
      0.60, 0.90, 0.85, 1.00, 0.99,        //
      0.99, 0.99, 0.99, 0.99, 1.00;
  const std::vector<MapAgreement> maps = map_agreements(within, 4);
  ASSERT_EQ(maps.size(), 4u);
  EXPECT_EQ(maps[0].agreeing, 0u);  // min(0.90, 0.80), min(0.95, 0.80), min(0.50, 0.60)
  EXPECT_NEAR(maps[0].mean, (0.80 + 0.80 + 0.50) / 3, 1e-12);
  EXPECT_EQ(maps[1].agreeing, 2u);
  EXPECT_NEAR(maps[1].mean, (0.80 + 0.90 + 0.86) / 3, 1e-12);
  EXPECT_EQ(maps[2].agreeing, 2u);  // 0.85 counts: at least kAgreeingWithin
  EXPECT_NEAR(maps[2].mean, (0.80 + 0.90 + 0.85) / 3, 1e-12);
  EXPECT_EQ(maps[3].agreeing, 2u);
  EXPECT_NEAR(maps[3].mean, (0.50 + 0.86 + 0.85) / 3, 1e-12);
  // Maps 1 to 3 agree with two others; 1 and 2 have the highest means (0.853, 0.850: within
  // kMeanAgreementTie), 3 is 0.117 lower. Between 1 and 2, the straighter Figure 2 decides,
  // and a map outside the tie does not win by its R^2.
  EXPECT_EQ(most_representative(maps, {0.99, 0.87, 0.92, 0.99}), 2u);
  EXPECT_EQ(most_representative(maps, {0.99, 0.93, 0.92, 0.99}), 1u);
  // A map agreeing with more others wins whatever its mean.
  std::vector<MapAgreement> more = maps;
  more[3].agreeing = 3;
  EXPECT_EQ(most_representative(more, {0.99, 0.93, 0.92, 0.5}), 3u);
  EXPECT_THROW(map_agreements(within, 6), std::invalid_argument);
  EXPECT_THROW(most_representative(maps, {0.9}), std::invalid_argument);
}

TEST(Validation, TruncatedDistanceKeepsTheFirstCoefficientsOfEachChannel) {
  Eigen::VectorXf a(6), b(6);
  a << 1, 5, 2, 7, 3, 9;  // channels (1, 5), (2, 7), (3, 9)
  b.setZero();
  EXPECT_NEAR(truncated_distance(a, b, 2), embedding_distance(a, b), 1e-6);
  EXPECT_NEAR(truncated_distance(a, b, 1), std::sqrt(1.0 + 4 + 9), 1e-6);
}

}  // namespace
}  // namespace brdfnav
