#include <brdfnav/navigator/image_input.h>

#include <brdfnav/navigator/database_format.h>

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>
#include <ImfVersion.h>

#include <cmath>
#include <cstdint>
#include <fstream>

namespace brdfnav {

namespace {

// The largest image read: 2^28 pixels (4 GiB of float RGBA), allocated before the pixels are read,
// so that a corrupt header claiming more is refused instead of exhausting memory.
constexpr std::int64_t kMaxPixels = std::int64_t{1} << 28;

// Refuses what is not an OpenEXR file before OpenEXR reads it, so that the message says so.
void check_openexr(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw ImageError(name + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw ImageError(name + ": is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImageError(name + ": cannot read: cannot open the file");
  char magic[4] = {};
  in.read(magic, sizeof magic);
  if (in.gcount() != sizeof magic || !Imf::isImfMagic(magic))
    throw ImageError(name + ": not an OpenEXR file; brdfnav reads BRDF images from OpenEXR only");
}

// Runs `read` on the file's OpenEXR input, turning OpenEXR's exceptions into ImageError.
template <typename Read>
auto with_input(const std::filesystem::path& path, Read read) {
  check_openexr(path);
  const std::string name = path.string();
  try {
    Imf::InputFile in(name.c_str());
    return read(in);
  } catch (const ImageError&) {
    throw;
  } catch (const std::exception& e) {  // Iex::BaseExc is a std::exception
    throw ImageError(name + ": cannot read: " + e.what());
  }
}

ImageHeader header_of(const Imf::Header& header, const std::string& name) {
  const Imath::Box2i& window = header.dataWindow();
  const std::int64_t width = std::int64_t{window.max.x} - window.min.x + 1;
  const std::int64_t height = std::int64_t{window.max.y} - window.min.y + 1;
  if (width <= 0 || height <= 0 || width * height > kMaxPixels)
    throw ImageError(name + ": is " + std::to_string(width) + "x" + std::to_string(height) +
                     "; brdfnav reads images of 1 to " + std::to_string(kMaxPixels) + " pixels");
  ImageHeader out;
  out.width = int(width), out.height = int(height);
  const std::string prefix = db::kHeaderPrefix;
  for (auto it = header.begin(); it != header.end(); ++it)
    if (std::string(it.name()).starts_with(prefix))
      if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        out.metadata.emplace_back(it.name(), text->value());
  return out;
}

const char* pixel_type_name(Imf::PixelType type) {
  switch (type) {
    case Imf::UINT:
      return "uint32";
    case Imf::HALF:
      return "half";
    case Imf::FLOAT:
      return "float";
    default:
      return "unknown";
  }
}

}  // namespace

std::string ImageHeader::attribute(const std::string& key) const {
  for (const auto& [k, value] : metadata)
    if (k == key) return value;
  return "";
}

ImageHeader read_image_header(const std::filesystem::path& path) {
  return with_input(path,
                    [&](Imf::InputFile& in) { return header_of(in.header(), path.string()); });
}

ImageMetadata read_image_metadata(const std::filesystem::path& path) {
  return read_image_header(path).metadata;
}

Image read_image(const std::filesystem::path& path) {
  const std::string name = path.string();
  return with_input(path, [&](Imf::InputFile& in) {
    const ImageHeader header = header_of(in.header(), name);
    const Imf::ChannelList& channels = in.header().channels();
    int count = 0;
    for (auto it = channels.begin(); it != channels.end(); ++it) ++count;
    if (count < 3)
      throw ImageError(name + ": has " + std::to_string(count) +
                       " channel(s); a BRDF image has R, G, B and A");
    for (const char* c : {"R", "G", "B", "A"}) {
      const Imf::Channel* channel = channels.findChannel(c);
      if (!channel) {
        if (c[0] == 'A') continue;
        throw ImageError(name + ": has no channel " + c + "; a BRDF image has R, G, B and A");
      }
      // Integer channels are not radiance (8- and 16-bit images, display-encoded, cannot be
      // OpenEXR): read as radiance they would give plausible, wrong distances.
      if (channel->type != Imf::HALF && channel->type != Imf::FLOAT)
        throw ImageError(name + ": holds " + pixel_type_name(channel->type) + " pixels (channel " +
                         c + "); a BRDF image is linear floating point (OpenEXR)");
      if (channel->xSampling != 1 || channel->ySampling != 1)
        throw ImageError(name + ": its channel " + c + " is subsampled; a BRDF image is not");
    }
    Image image(header.width, header.height);
    const Imath::Box2i& window = in.header().dataWindow();
    const std::size_t x_stride = 4 * sizeof(float), y_stride = x_stride * image.width;
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)  // a missing A is filled with 1: all covered
      frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, &image.rgba[c], window, x_stride,
                                              y_stride, 1, 1, c == 3 ? 1.0 : 0.0));
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    for (std::size_t p = 0; p < image.rgba.size() / 4; ++p)
      for (int c = 0; c < 3; ++c) {
        const float v = image.rgba[4 * p + c];
        if (!(v >= 0 && std::isfinite(v)))
          throw ImageError(name + ": pixel (" + std::to_string(p % image.width) + ", " +
                           std::to_string(p / image.width) + ") has " + "RGB"[c] + " = " +
                           std::to_string(v) + "; radiance is finite and not negative");
      }
    return image;
  });
}

}  // namespace brdfnav
