#include <brdfnav/precompute/image_output.h>

#include <brdfnav/core/atomic_file.h>

#include <OpenImageIO/imageio.h>

#include <cctype>

namespace brdfnav {

void check_exr_name(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".exr")
    throw ImageError(path.string() + ": an OpenEXR file name must end in .exr");
}

void write_exr(const Image& image, const std::filesystem::path& path,
               const ImageMetadata& metadata) {
  check_exr_name(path);
  const std::string name = path.string();
  AtomicOutput out(path);
  auto writer = OIIO::ImageOutput::create(out.temp_path().string());
  if (!writer) throw ImageError(name + ": cannot write: " + OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B", "A"};
  spec.alpha_channel = 3;
  spec.attribute("compression", "zip");
  spec.attribute("oiio:ColorSpace", "Linear");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  if (!writer->open(out.temp_path().string(), spec) ||
      !writer->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data()) || !writer->close())
    throw ImageError(name + ": cannot write: " + writer->geterror());
  writer.reset();
  out.commit();
}

}  // namespace brdfnav
