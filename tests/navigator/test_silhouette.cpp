// The sphere's silhouette as a thumbnail shows it: alpha the fraction of each pixel inside the
// unit disk, the colour of the pixels the renderer left uncovered borrowed from their covered
// neighbours, everything else as rendered; and the display encoding of it, with straight alpha.
#include <brdfnav/navigator/display_thumbnails.h>
#include <brdfnav/navigator/silhouette.h>
#include <brdfnav/ocio/color_pipeline.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

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

// display_encode(): straight alpha. A grey disk's edge keeps the grey of its inside (no
// darkening by the coverage), its alpha the antialiased coverage; without `sphere` the mask stays
// 0 or 1; a pixel nothing covers is 0 0 0 0.
TEST(Silhouette, DisplayEncodingHasStraightAlphaAndTheAntialiasedEdge) {
  const int n = 32;
  Image disk = rendered_disk(n);
  for (std::size_t i = 0; i < disk.rgba.size(); i += 4)
    if (disk.rgba[i + 3] > 0) disk.rgba[i] = disk.rgba[i + 1] = disk.rgba[i + 2] = 0.18f;
  Image antialiased = disk;
  antialias_sphere_silhouette(antialiased);
  const ocio::ColorPipeline pipeline;
  const std::string display = pipeline.default_display();
  const std::string view = pipeline.default_view(display);
  const ocio::Thumbnail shown = display_encode(disk, true, pipeline, display, view);
  const ocio::Thumbnail mesh = display_encode(disk, false, pipeline, display, view);
  const std::uint8_t* inside = &shown.rgba[(std::size_t(n / 2) * n + n / 2) * 4];
  EXPECT_GT(inside[0], 0);
  int partial = 0;
  for (std::size_t p = 0; p < shown.rgba.size() / 4; ++p) {
    const std::uint8_t* s = &shown.rgba[4 * p];
    const float coverage = antialiased.rgba[4 * p + 3];
    ASSERT_EQ(s[3], std::lround(255 * coverage)) << p;
    partial += s[3] > 0 && s[3] < 255;
    for (int c = 0; c < 3; ++c) ASSERT_EQ(s[c], s[3] ? inside[c] : 0) << p << " " << c;
    const bool covered = disk.rgba[4 * p + 3] > 0;
    ASSERT_EQ(mesh.rgba[4 * p + 3], covered ? 255 : 0) << p;
  }
  EXPECT_GT(partial, 20);
}

TEST(Silhouette, RefusesAnImageThatIsNotSquare) {
  Image wide(8, 4);
  EXPECT_THROW(antialias_sphere_silhouette(wide), ImageError);
}

}  // namespace
}  // namespace brdfnav
