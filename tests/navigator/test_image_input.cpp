// The navigator's image reading (OpenEXR alone), on files written here with OpenEXR: what it
// reads, and what it refuses with a message naming the file.
#include <brdfnav/navigator/image_input.h>
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <half.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace brdfnav {
namespace {

namespace fs = std::filesystem;

// A directory of this process's own (CTest runs the cases as concurrent processes), removed at
// exit.
struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("brdfnav_test_image_" + std::to_string(::getpid()));
  Scratch() {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

const fs::path& scratch() {
  static const Scratch s;
  return s.dir;
}

struct Channel {
  const char* name;
  Imf::PixelType type;
};

// An OpenEXR file of `channels` (each written from float or uint values), pixel (x, y) of channel
// c being value(x, y, c), with the data window's origin at `origin`.
template <typename Value>
fs::path write_exr_file(const std::string& file, int w, int h, const std::vector<Channel>& channels,
                        Value value, const ImageMetadata& metadata = {},
                        Imath::V2i origin = {0, 0}) {
  const fs::path path = scratch() / file;
  Imf::Header header(w, h);
  header.dataWindow() = Imath::Box2i(origin, origin + Imath::V2i(w - 1, h - 1));
  header.displayWindow() = header.dataWindow();
  for (const Channel& c : channels) header.channels().insert(c.name, Imf::Channel(c.type));
  for (const auto& [key, text] : metadata) header.insert(key, Imf::StringAttribute(text));
  const std::size_t n = channels.size(), pixels = std::size_t(w) * h;
  std::vector<float> floats(pixels * n);
  std::vector<unsigned> uints(pixels * n);
  std::vector<Imath::half> halves(pixels * n);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (std::size_t c = 0; c < n; ++c) {
        const double v = value(x, y, int(c));
        floats[(std::size_t(y) * w + x) * n + c] = float(v);
        // Only a UINT channel reads these; a NaN or negative value has no unsigned form.
        uints[(std::size_t(y) * w + x) * n + c] = v >= 0 && v < 4e9 ? unsigned(v) : 0u;
        halves[(std::size_t(y) * w + x) * n + c] = Imath::half(float(v));
      }
  // The frame buffer holds each channel in the file's type (OpenEXR writes without converting).
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < n; ++c) {
    const Imf::PixelType type = channels[c].type;
    const void* base = type == Imf::UINT   ? static_cast<const void*>(&uints[c])
                       : type == Imf::HALF ? static_cast<const void*>(&halves[c])
                                           : &floats[c];
    const std::size_t size = type == Imf::HALF ? 2 : 4;
    frame.insert(channels[c].name,
                 Imf::Slice::Make(type, base, header.dataWindow(), n * size, n * size * w));
  }
  Imf::OutputFile out(path.string().c_str(), header);
  out.setFrameBuffer(frame);
  out.writePixels(h);
  return path;
}

const std::vector<Channel> kRgba{
    {"R", Imf::FLOAT}, {"G", Imf::FLOAT}, {"B", Imf::FLOAT}, {"A", Imf::FLOAT}};

double ramp(int x, int y, int c) {
  return c == 3 ? (x + y) % 2 : 0.25 * x + 2 * y + 10 * c;
}

void expect_refused(const fs::path& path, const std::vector<std::string>& phrases) {
  try {
    read_image(path);
    ADD_FAILURE() << path << " was read";
  } catch (const ImageError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
    for (const std::string& p : phrases) EXPECT_NE(what.find(p), std::string::npos) << what;
  }
}

TEST(ReadImage, ReadsFloatRgbaAndTheBrdfnavAttributes) {
  const fs::path path = write_exr_file("rgba.exr", 5, 3, kRgba, ramp,
                                       {{db::kHeaderMaterial, "ward:alpha_x=0.1,alpha_y=0.2"},
                                        {db::kHeaderScene, "sphere"},
                                        {"owner", "someone else"}});
  const Image image = read_image(path);
  ASSERT_EQ(image.width, 5);
  ASSERT_EQ(image.height, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(image.pixel(x, y)[c], float(ramp(x, y, c)));
  const ImageMetadata expected{{db::kHeaderMaterial, "ward:alpha_x=0.1,alpha_y=0.2"},
                               {db::kHeaderScene, "sphere"}};
  EXPECT_EQ(read_image_metadata(path), expected);
  const ImageHeader header = read_image_header(path);
  EXPECT_EQ(header.width, 5);
  EXPECT_EQ(header.height, 3);
  EXPECT_EQ(header.attribute(db::kHeaderScene), "sphere");
  EXPECT_EQ(header.attribute(db::kHeaderEnvSha1), "");
}

TEST(ReadImage, HalfRgbGetsAlphaOne) {
  const fs::path path =
      write_exr_file("rgb_half.exr", 4, 2, {{"B", Imf::HALF}, {"G", Imf::HALF}, {"R", Imf::HALF}},
                     [](int x, int y, int c) { return 0.5 * (x + 4 * y) + 100 * c; });
  const Image image = read_image(path);
  ASSERT_EQ(image.width, 4);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      // Written in the order B, G, R: B's values are 0.5 (x + 4 y), R's 200 more.
      EXPECT_EQ(image.pixel(x, y)[0], float(0.5 * (x + 4 * y) + 200));
      EXPECT_EQ(image.pixel(x, y)[2], float(0.5 * (x + 4 * y)));
      EXPECT_EQ(image.pixel(x, y)[3], 1.f);
    }
}

TEST(ReadImage, ADataWindowAwayFromTheOriginIsTheImage) {
  const fs::path path = write_exr_file("window.exr", 3, 2, kRgba, ramp, {}, {-7, 40});
  const Image image = read_image(path);
  ASSERT_EQ(image.width, 3);
  ASSERT_EQ(image.height, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 4; ++c) EXPECT_EQ(image.pixel(x, y)[c], float(ramp(x, y, c)));
}

TEST(ReadImage, RefusesWhatIsNotRadianceNamingTheFile) {
  const fs::path png = scratch() / "display.png";
  std::ofstream(png, std::ios::binary) << std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
  expect_refused(png, {"not an OpenEXR file"});
  const fs::path empty = scratch() / "empty.exr";
  std::ofstream(empty).close();
  expect_refused(empty, {"not an OpenEXR file"});
  expect_refused(scratch() / "none.exr", {"no such file"});
  expect_refused(scratch(), {"is a directory"});

  const fs::path truncated = write_exr_file("truncated.exr", 64, 64, kRgba, ramp);
  fs::resize_file(truncated, fs::file_size(truncated) / 2);
  expect_refused(truncated, {"cannot read"});
  const fs::path header_only = write_exr_file("header_only.exr", 64, 64, kRgba, ramp);
  fs::resize_file(header_only, 200);
  expect_refused(header_only, {"cannot read"});
  try {
    read_image_metadata(header_only);
    ADD_FAILURE() << "read";
  } catch (const ImageError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(header_only.string() + ": ", 0), 0u) << e.what();
  }

  expect_refused(
      write_exr_file("uint.exr", 2, 2, {{"R", Imf::UINT}, {"G", Imf::UINT}, {"B", Imf::UINT}},
                     [](int, int, int) { return 7; }),
      {"holds uint32 pixels", "linear floating point"});
  expect_refused(write_exr_file("two.exr", 2, 2, {{"R", Imf::FLOAT}, {"G", Imf::FLOAT}}, ramp),
                 {"has 2 channel(s)"});
  expect_refused(write_exr_file("xyz.exr", 2, 2,
                                {{"X", Imf::FLOAT}, {"Y", Imf::FLOAT}, {"Z", Imf::FLOAT}}, ramp),
                 {"has no channel R"});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_refused(
      write_exr_file("nan.exr", 3, 3, kRgba,
                     [&](int x, int y, int c) { return x == 1 && y == 2 && c == 1 ? nan : 1; }),
      {"pixel (1, 2) has G", "finite and not negative"});
  expect_refused(
      write_exr_file("negative.exr", 3, 3, kRgba,
                     [](int x, int y, int c) { return x == 2 && y == 0 && c == 2 ? -1 : 1; }),
      {"pixel (2, 0) has B = -1"});
}

}  // namespace
}  // namespace brdfnav
