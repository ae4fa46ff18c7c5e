#include <brdfnav/navigator/image.h>

#include <brdfnav/navigator/database_format.h>

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>
#include <ImfVersion.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>

namespace brdfnav {

void check_same_shape(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw ImageError("image sizes differ: " + std::to_string(a.width) + "x" +
                     std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                     std::to_string(b.height));
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (a.covered(x, y) != b.covered(x, y))
        throw ImageError("image masks (alpha) differ, first at pixel (" + std::to_string(x) + ", " +
                         std::to_string(y) + ")");
}

Image compose(const Image& diffuse, const Image& specular, const Rgb& rho_d, const Rgb& rho_s) {
  check_same_shape(diffuse, specular);
  Image out(diffuse.width, diffuse.height);
  for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c)
      out.rgba[i + c] =
          static_cast<float>(rho_d[c] * diffuse.rgba[i + c] + rho_s[c] * specular.rgba[i + c]);
    out.rgba[i + 3] = diffuse.rgba[i + 3];
  }
  return out;
}

double image_distance(const Image& a, const Image& b) {
  check_same_shape(a, b);
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    if (a.rgba[i + 3] <= 0.5f) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = std::cbrt(double(a.rgba[i + c])) - std::cbrt(double(b.rgba[i + c]));
      sum += d * d;
    }
    count += 3;
  }
  if (count == 0) throw ImageError("the images cover no pixel");
  return std::sqrt(sum / count);
}

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

namespace {

// Lanczos-3: sinc(x) sinc(x / 3) on |x| < 3.
double lanczos3(double x) {
  x = std::abs(x);
  if (x < 1e-9) return 1;
  if (x >= 3) return 0;
  const double px = kPi * x;
  return 3 * std::sin(px) * std::sin(px / 3) / (px * px);
}

// Blackman-Harris (4 terms) on |x| < 1.5.
double blackman_harris(double x) {
  if (std::abs(x) >= 1.5) return 0;
  const double t = 2 * kPi * (x / 1.5 + 1) / 2;
  return 0.35875 - 0.48829 * std::cos(t) + 0.14128 * std::cos(2 * t) - 0.01168 * std::cos(3 * t);
}

// The weights of one axis from `in` samples to `out`: for output sample i, the source indices
// from first[i] on and their normalised weights.
struct AxisWeights {
  std::vector<int> first, count;
  std::vector<std::vector<float>> weights;
};

AxisWeights axis_weights(int in, int out) {
  const double ratio = double(out) / in;
  const bool enlarging = ratio > 1;
  const double scale = enlarging ? 1 : 1 / ratio;  // widen the filter when shrinking
  const double support = (enlarging ? 1.5 : 3) * scale;
  AxisWeights w;
  for (int i = 0; i < out; ++i) {
    const double centre = (i + 0.5) / ratio;  // in source pixel units, centres at k + 0.5
    const int lo = int(std::floor(centre - support)), hi = int(std::ceil(centre + support));
    std::vector<double> raw;
    double sum = 0;
    for (int k = lo; k <= hi; ++k) {
      const double x = (k + 0.5 - centre) / scale;
      const double v = enlarging ? blackman_harris(x) : lanczos3(x);
      raw.push_back(v);
      sum += v;
    }
    // Clamp to the edge: the weights of samples beyond it go to the edge sample.
    std::vector<float> folded(in, 0.f);
    for (int k = lo; k <= hi; ++k) folded[std::clamp(k, 0, in - 1)] += float(raw[k - lo] / sum);
    int first = 0, last = in - 1;
    while (first < last && folded[first] == 0.f) ++first;
    while (last > first && folded[last] == 0.f) --last;
    w.first.push_back(first);
    w.count.push_back(last - first + 1);
    w.weights.emplace_back(folded.begin() + first, folded.begin() + last + 1);
  }
  return w;
}

}  // namespace

Image resample(const Image& image, int width, int height) {
  if (image.width <= 0 || image.height <= 0 || width <= 0 || height <= 0)
    throw ImageError("cannot resample a " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " image to " + std::to_string(width) + "x" +
                     std::to_string(height));
  if (width == image.width && height == image.height) return image;
  // Rows first (image.height x width), then columns, accumulated in double.
  const AxisWeights across = axis_weights(image.width, width);
  const AxisWeights down = axis_weights(image.height, height);
  std::vector<double> rows(static_cast<std::size_t>(image.height) * width * 4, 0.0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < width; ++x) {
      double* out = &rows[4 * (static_cast<std::size_t>(y) * width + x)];
      for (int k = 0; k < across.count[x]; ++k) {
        const float* in = image.pixel(across.first[x] + k, y);
        const double w = across.weights[x][k];
        for (int c = 0; c < 4; ++c) out[c] += w * in[c];
      }
    }
  Image out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double sum[4] = {0, 0, 0, 0};
      for (int k = 0; k < down.count[y]; ++k) {
        const double* in = &rows[4 * (static_cast<std::size_t>(down.first[y] + k) * width + x)];
        const double w = down.weights[y][k];
        for (int c = 0; c < 4; ++c) sum[c] += w * in[c];
      }
      for (int c = 0; c < 4; ++c) out.pixel(x, y)[c] = float(sum[c]);
    }
  return out;
}

}  // namespace brdfnav
