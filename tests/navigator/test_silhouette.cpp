// The sphere's silhouette as a thumbnail shows it: alpha the fraction of each pixel inside the
// unit disk, the colour of the pixels the renderer left uncovered borrowed from their covered
// neighbours, everything else as rendered.
#include <brdfnav/navigator/silhouette.h>
#include <gtest/gtest.h>

#include <cmath>

namespace brdfnav {
namespace {

// What the renderer draws of the sphere: colour (x, y, 1) in pixels whose centre is inside the
// unit disk (alpha 1), black and alpha 0 elsewhere.
Image rendered_disk(int n) {
  Image image(n, n);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double cx = -1 + (x + 0.5) * 2 / n, cy = 1 - (y + 0.5) * 2 / n;
      if (cx * cx + cy * cy >= 1) continue;
      float* p = image.pixel(x, y);
      p[0] = float(x), p[1] = float(y), p[2] = 1, p[3] = 1;
    }
  }
  return image;
}

TEST(Silhouette, AlphaIsTheCoverageOfTheDisk) {
  const int n = 64;
  const Image rendered = rendered_disk(n);
  Image shown = rendered;
  antialias_sphere_silhouette(shown);
  double area = 0;
  int partial = 0, borrowed = 0;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const float* p = shown.pixel(x, y);
      const float* r = rendered.pixel(x, y);
      area += p[3];
      partial += p[3] > 0 && p[3] < 1;
      if (rendered.covered(x, y)) {
        // A covered pixel keeps its colour; its alpha may drop at the edge, never to 0.
        EXPECT_EQ(p[0], r[0]);
        EXPECT_EQ(p[1], r[1]);
        EXPECT_GT(p[3], 0.f);
      } else if (p[3] > 0) {
        // Its colour is that of its neighbours: here x and y within one pixel.
        ++borrowed;
        EXPECT_NEAR(p[0], x, 1.0) << x << ", " << y;
        EXPECT_NEAR(p[1], y, 1.0) << x << ", " << y;
        EXPECT_EQ(p[2], 1.f);
      }
    }
  }
  // The disk's area in pixels, to the sampling's resolution (8 x 8 per edge pixel).
  EXPECT_NEAR(area, std::acos(-1.0) * 32 * 32, 2.0);
  EXPECT_GT(partial, 100);
  EXPECT_GT(borrowed, 20);
  // Far from the edge, nothing changes.
  EXPECT_EQ(shown.pixel(n / 2, n / 2)[3], 1.f);
  EXPECT_EQ(shown.pixel(0, 0)[3], 0.f);
}

TEST(Silhouette, RefusesAnImageThatIsNotSquare) {
  Image wide(8, 4);
  EXPECT_THROW(antialias_sphere_silhouette(wide), ImageError);
}

}  // namespace
}  // namespace brdfnav
