#include <brdfnav/navigator/silhouette.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace brdfnav {

namespace {

constexpr int kSamples = 8;  // per side of a pixel the edge crosses

// The fraction of the pixel of centre (cx, cy) and side `size` inside the unit disk.
float disk_coverage(double cx, double cy, double size) {
  int inside = 0;
  for (int j = 0; j < kSamples; ++j) {
    const double v = cy + ((j + 0.5) / kSamples - 0.5) * size;
    for (int i = 0; i < kSamples; ++i) {
      const double u = cx + ((i + 0.5) / kSamples - 0.5) * size;
      inside += u * u + v * v < 1.0;
    }
  }
  return float(inside) / float(kSamples * kSamples);
}

// The renderer's mask: whether each pixel was covered, row-major.
std::vector<bool> rendered_mask(const Image& image) {
  std::vector<bool> mask(std::size_t(image.width) * std::size_t(image.height));
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      mask[std::size_t(y) * std::size_t(image.width) + std::size_t(x)] = image.covered(x, y);
  return mask;
}

// The mean colour of the pixels around (x, y) that `mask` covers; false when there is none. Their
// colours are as rendered: only uncovered pixels take a colour.
bool neighbours_color(const Image& image, const std::vector<bool>& mask, int x, int y,
                      float rgb[3]) {
  double sum[3] = {0, 0, 0};
  int count = 0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= image.width || ny >= image.height) continue;
      if (!mask[std::size_t(ny) * std::size_t(image.width) + std::size_t(nx)]) continue;
      const float* p = image.pixel(nx, ny);
      for (int c = 0; c < 3; ++c) sum[c] += p[c];
      ++count;
    }
  }
  for (int c = 0; c < 3; ++c) rgb[c] = count ? float(sum[c] / count) : 0.f;
  return count > 0;
}

}  // namespace

void antialias_sphere_silhouette(Image& image) {
  if (image.width != image.height)
    throw ImageError("a sphere's silhouette needs a square image, not " +
                     std::to_string(image.width) + " x " + std::to_string(image.height));
  // The mask as rendered, since the edge's alpha changes on the way (the colours need no copy).
  const std::vector<bool> covered = rendered_mask(image);
  const int n = image.width;
  const double size = 2.0 / n;                 // a pixel's side in the camera's [-1, 1] square
  const double reach = size * std::sqrt(0.5);  // centre to corner
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double cx = -1 + (x + 0.5) * size, cy = 1 - (y + 0.5) * size;
      const double r = std::hypot(cx, cy);
      if (r <= 1 - reach || r >= 1 + reach) continue;  // wholly inside or outside
      const float coverage = disk_coverage(cx, cy, size);
      float* p = image.pixel(x, y);
      if (!covered[std::size_t(y) * std::size_t(n) + std::size_t(x)]) {
        float rgb[3];
        if (coverage == 0.f || !neighbours_color(image, covered, x, y, rgb)) continue;
        for (int c = 0; c < 3; ++c) p[c] = rgb[c];
      }
      p[3] = coverage;
    }
  }
}

}  // namespace brdfnav
