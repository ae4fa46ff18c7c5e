// BRDF images in memory (core/image.h): composing a material's image from its linear parts, the
// paper's cube-root metric, and resample().
#include <brdfnav/core/image.h>
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace brdfnav {
namespace {

// A w x h image of one colour, every pixel covered but those where `hole` says not.
Image filled(int w, int h, float r, float g, float b, bool (*hole)(int, int) = nullptr) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float* p = image.pixel(x, y);
      const bool covered = !(hole && hole(x, y));
      p[0] = r, p[1] = g, p[2] = b, p[3] = covered ? 1.f : 0.f;
    }
  return image;
}

bool left_column(int x, int) {
  return x == 0;
}

TEST(Compose, IsDiffuseTimesRhoDPlusSpecularTimesRhoSPerChannel) {
  const Image diffuse = filled(3, 2, 1.f, 2.f, 4.f, left_column);
  const Image specular = filled(3, 2, 8.f, 0.5f, 0.25f, left_column);
  const Image out = compose(diffuse, specular, Rgb(0.5, 0.25, 0.125), Rgb(0.25, 2, 4));
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      const float* p = out.pixel(x, y);
      EXPECT_FLOAT_EQ(p[0], 0.5f * 1 + 0.25f * 8);
      EXPECT_FLOAT_EQ(p[1], 0.25f * 2 + 2 * 0.5f);
      EXPECT_FLOAT_EQ(p[2], 0.125f * 4 + 4 * 0.25f);
      EXPECT_EQ(out.covered(x, y), x != 0);
    }
}

// The RMS of cube-root differences over the covered pixels and three channels: 8 against 1 in
// one channel of every covered pixel is cbrt 8 - cbrt 1 = 1 in a third of the terms.
TEST(ImageDistance, IsTheRmsOfCubeRootDifferencesOverCoveredPixels) {
  const Image a = filled(4, 4, 8.f, 1.f, 27.f, left_column);
  Image b = filled(4, 4, 1.f, 1.f, 27.f, left_column);
  EXPECT_DOUBLE_EQ(image_distance(a, a), 0);
  EXPECT_NEAR(image_distance(a, b), std::sqrt(1.0 / 3), 1e-12);
  EXPECT_NEAR(image_distance(b, a), std::sqrt(1.0 / 3), 1e-12);
  // What an uncovered pixel holds does not count.
  b.pixel(0, 2)[1] = 1000.f;
  EXPECT_NEAR(image_distance(a, b), std::sqrt(1.0 / 3), 1e-12);
  // The same difference at any resolution is the same distance.
  EXPECT_NEAR(image_distance(filled(9, 9, 8, 1, 27), filled(9, 9, 1, 1, 27)), std::sqrt(1.0 / 3),
              1e-12);
}

TEST(ImageDistance, RefusesImagesOfOtherShapesOrNothingCovered) {
  const Image a = filled(4, 4, 1, 1, 1);
  EXPECT_THROW(image_distance(a, filled(4, 5, 1, 1, 1)), ImageError);
  EXPECT_THROW(image_distance(a, filled(4, 4, 1, 1, 1, left_column)), ImageError);
  EXPECT_THROW(compose(a, filled(5, 4, 1, 1, 1), Rgb(1, 1, 1), Rgb(1, 1, 1)), ImageError);
  const Image none = filled(2, 2, 1, 1, 1, [](int, int) { return true; });
  EXPECT_THROW(image_distance(none, none), ImageError);
  try {
    check_same_shape(a, filled(4, 4, 1, 1, 1, left_column));
    ADD_FAILURE() << "masks that differ passed";
  } catch (const ImageError& e) {
    EXPECT_NE(std::string(e.what()).find("pixel (0, 0)"), std::string::npos) << e.what();
  }
}

// A smooth image: low frequencies only, which resampling keeps.
Image smooth(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double u = (x + 0.5) / w, v = (y + 0.5) / h;
      float* p = image.pixel(x, y);
      p[0] = float(1 + 0.5 * std::sin(2 * u + 1) * std::cos(1.5 * v));
      p[1] = float(2 + u * v);
      p[2] = float(0.5 + 0.25 * u - 0.1 * v);
      p[3] = 1;
    }
  return image;
}

TEST(Resample, AConstantStaysTheConstant) {
  Image constant(40, 40);
  for (std::size_t i = 0; i < constant.rgba.size(); ++i) constant.rgba[i] = i % 4 == 3 ? 1 : 0.3f;
  for (auto [w, h] : {std::pair{40, 40}, {128, 128}, {13, 13}, {7, 90}, {1, 1}}) {
    const Image out = resample(constant, w, h);
    ASSERT_EQ(out.width, w);
    ASSERT_EQ(out.height, h);
    for (std::size_t i = 0; i < out.rgba.size(); ++i)
      ASSERT_NEAR(out.rgba[i], i % 4 == 3 ? 1 : 0.3f, 1e-6) << w << "x" << h << " at " << i;
  }
}

TEST(Resample, UpThenDownStaysClose) {
  const Image image = smooth(24, 24);
  for (int up : {48, 61, 128}) {
    const Image back = resample(resample(image, up, up), 24, 24);
    double worst = 0;
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
      worst = std::max(worst, std::abs(double(back.rgba[i]) - image.rgba[i]));
    EXPECT_LT(worst, 0.01) << up;
  }
  // Down, the image is its smooth self at the coarser sampling.
  const Image down = resample(smooth(96, 96), 24, 24);
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    EXPECT_NEAR(down.rgba[i], image.rgba[i], 0.01) << i;
}

TEST(Resample, RefusesEmptySizes) {
  EXPECT_THROW(resample(smooth(4, 4), 0, 4), ImageError);
  EXPECT_THROW(resample(Image(), 4, 4), ImageError);
}

}  // namespace
}  // namespace brdfnav
