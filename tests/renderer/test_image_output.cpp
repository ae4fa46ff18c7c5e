// write_exr(): what `brdfnav render` writes (every bit of the float) and what a database stores
// (uncompressed halves), read back by the navigator's own reader.
#include <brdfnav/navigator/image_input.h>
#include <brdfnav/renderer/image_output.h>
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

namespace brdfnav {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& file) {
  const fs::path dir =
      fs::temp_directory_path() / ("brdfnav_test_image_output_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / file;
}

// 16 x 16 pixels spanning what a database image holds: the sky's 1e3, a sphere's dark rim near
// 1e-4, exact zeros outside the mask.
Image test_image() {
  Image image;
  image.width = image.height = 16;
  for (int i = 0; i < 16 * 16; ++i) {
    const bool covered = (i % 16 - 8) * (i % 16 - 8) + (i / 16 - 8) * (i / 16 - 8) < 49;
    for (int c = 0; c < 3; ++c)
      image.rgba.push_back(covered ? float(1e-4 * std::pow(1.07, i) * (1 + 0.1 * c)) : 0.f);
    image.rgba.push_back(covered ? 1.f : 0.f);
  }
  return image;
}

struct Stored {
  std::string format, compression;
};

Stored stored(const fs::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << path;
  if (!in) return {};
  return {in->spec().format.c_str(), in->spec().get_string_attribute("compression")};
}

TEST(ImageOutput, RenderOutputKeepsEveryBitOfTheFloats) {
  const Image image = test_image();
  const fs::path path = scratch("float.exr");
  write_exr(image, path, {{"brdfnav:scene", "sphere"}});
  EXPECT_EQ(read_image(path).rgba, image.rgba);
  EXPECT_EQ(stored(path).format, "float");
  EXPECT_EQ(stored(path).compression, "zip");
  const ImageMetadata metadata{{"brdfnav:scene", "sphere"}};
  EXPECT_EQ(read_image_metadata(path), metadata);
}

// A database's images: halves, uncompressed, each value within half's rounding (2^-11 relative
// for normal halves; below 6.1e-5, subnormal, within 2^-25 absolute).
TEST(ImageOutput, DatabaseImagesAreUncompressedHalvesWithinTheirRounding) {
  const Image image = test_image();
  const fs::path path = scratch("half.exr");
  write_exr(image, path, {}, ExrPixels::half_raw);
  EXPECT_EQ(stored(path).format, "half");
  EXPECT_EQ(stored(path).compression, "none");
  const Image back = read_image(path);
  ASSERT_EQ(back.rgba.size(), image.rgba.size());
  double worst = 0;
  for (std::size_t i = 0; i < image.rgba.size(); ++i) {
    const double v = image.rgba[i], error = std::abs(back.rgba[i] - v);
    EXPECT_LE(error, std::max(v * std::ldexp(1.0, -11), std::ldexp(1.0, -25))) << i << " " << v;
    if (v > 0) worst = std::max(worst, error / v);
    if (v == 0) EXPECT_EQ(back.rgba[i], 0.f) << i;  // the mask and the black outside stay exact
  }
  EXPECT_GT(worst, 0.0);  // it is a half: the floats did not all survive
  EXPECT_LT(fs::file_size(path), 16u * 16u * 4u * 2u + 1024u);
}

// A value a half cannot hold is refused, naming the file and the pixel, and nothing is written:
// a database must not hold an infinity where the render had a number.
TEST(ImageOutput, RefusesWhatAHalfCannotHold) {
  for (const float bad : {7e4f, -1e5f, std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity()}) {
    Image image = test_image();
    image.rgba[4 * 120 + 1] = bad;
    const fs::path path = scratch("refused.exr");
    fs::remove(path);
    try {
      write_exr(image, path, {}, ExrPixels::half_raw);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const ImageError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path.string()), std::string::npos) << what;
      EXPECT_NE(what.find("pixel 120, channel 1"), std::string::npos) << what;
    }
    EXPECT_FALSE(fs::exists(path)) << bad;
    for (const auto& e : fs::directory_iterator(path.parent_path()))  // nor a temporary
      EXPECT_EQ(e.path().filename().string().find("refused"), std::string::npos) << e.path();
  }
  Image big = test_image();
  big.rgba[0] = 7e4f;
  EXPECT_NO_THROW(write_exr(big, scratch("float_big.exr"), {}));  // floats have no such limit
  fs::remove_all(scratch("").parent_path());
}

}  // namespace
}  // namespace brdfnav
