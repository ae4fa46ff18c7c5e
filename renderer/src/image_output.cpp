#include <brdfnav/renderer/image_output.h>

#include <brdfnav/core/atomic_file.h>

#include <OpenImageIO/imageio.h>

#include <cctype>
#include <cmath>
#include <cstdio>

namespace brdfnav {

void check_exr_name(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".exr")
    throw ImageError(path.string() + ": an OpenEXR file name must end in .exr");
}

namespace {
constexpr float kHalfMax = 65504.f;

void check_half_range(const Image& image, const std::string& name) {
  for (std::size_t i = 0; i < image.rgba.size(); ++i)
    if (!(std::abs(image.rgba[i]) <= kHalfMax)) {
      char text[160];
      std::snprintf(text, sizeof text,
                    ": pixel %zu, channel %zu is %g, which a half float cannot hold (|v| <= %g)",
                    i / 4, i % 4, double(image.rgba[i]), double(kHalfMax));
      throw ImageError(name + text);
    }
}
}  // namespace

void write_exr(const Image& image, const std::filesystem::path& path, const ImageMetadata& metadata,
               ExrPixels pixels) {
  check_exr_name(path);
  const std::string name = path.string();
  const bool half = pixels == ExrPixels::half_raw;
  if (half) check_half_range(image, name);
  AtomicOutput out(path);
  auto writer = OIIO::ImageOutput::create(out.temp_path().string());
  if (!writer) throw ImageError(name + ": cannot write: " + OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, 4,
                       half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B", "A"};
  spec.alpha_channel = 3;
  spec.attribute("compression", half ? "none" : "zip");
  spec.attribute("oiio:ColorSpace", "Linear");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  if (!writer->open(out.temp_path().string(), spec) ||
      !writer->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data()) || !writer->close())
    throw ImageError(name + ": cannot write: " + writer->geterror());
  writer.reset();
  out.commit();
}

}  // namespace brdfnav
