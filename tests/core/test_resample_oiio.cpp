// resample() gives what OpenImageIO's ImageBufAlgo::resize() gave the thumbnails before it
// (its default filters: Lanczos-3 when shrinking, Blackman-Harris when enlarging), on an image
// like a database's: a lit disk on black, alpha its mask.
#include <brdfnav/core/image.h>
#include <gtest/gtest.h>

#include <OpenImageIO/imagebufalgo.h>

#include <cmath>

namespace brdfnav {
namespace {

Image disk(int size) {
  Image image(size, size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double u = 2 * (x + 0.5) / size - 1, v = 2 * (y + 0.5) / size - 1;
      if (u * u + v * v >= 1) continue;
      float* p = image.pixel(x, y);
      const double highlight = std::exp(-20 * ((u - 0.3) * (u - 0.3) + (v + 0.2) * (v + 0.2)));
      for (int c = 0; c < 3; ++c) p[c] = float(0.2 + 0.1 * c + 0.5 * (1 - v) + 4 * highlight);
      p[3] = 1;
    }
  return image;
}

Image oiio_resize(const Image& image, int size) {
  const OIIO::ImageBuf source(OIIO::ImageSpec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT),
                              const_cast<float*>(image.rgba.data()));
  const OIIO::ROI roi(0, size, 0, size, 0, 1, 0, 4);
  const OIIO::ImageBuf scaled = OIIO::ImageBufAlgo::resize(source, "", 0, roi);
  Image out(size, size);
  scaled.get_pixels(roi, OIIO::TypeDesc::FLOAT, out.rgba.data());
  return out;
}

TEST(Resample, IsOpenImageIOsDefaultResize) {
  for (int from : {16, 64})
    for (int to : {5, 8, 12, 17, 32, 45, 128}) {
      if (to == from) continue;
      const Image source = disk(from);
      const Image ours = resample(source, to, to), theirs = oiio_resize(source, to);
      for (std::size_t i = 0; i < ours.rgba.size(); ++i) {
        ASSERT_NEAR(ours.rgba[i], theirs.rgba[i], 1e-3 * (1 + std::abs(theirs.rgba[i])))
            << from << " to " << to << " at " << i;
        if (i % 4 == 3) ASSERT_EQ(ours.rgba[i] > 0.5f, theirs.rgba[i] > 0.5f) << i;
      }
    }
}

}  // namespace
}  // namespace brdfnav
