#include <brdfnav/navigator/image.h>

#include <brdfnav/navigator/database_format.h>

#include <OpenImageIO/imageio.h>

#include <cmath>

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

Image read_image(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw ImageError(name + ": no such file");
  auto in = OIIO::ImageInput::open(name);
  if (!in) throw ImageError(name + ": cannot read: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  // 8- and 16-bit files are display-encoded: read as radiance they would give plausible, wrong
  // distances.
  const OIIO::TypeDesc::BASETYPE type = OIIO::TypeDesc::BASETYPE(spec.format.basetype);
  if (type != OIIO::TypeDesc::FLOAT && type != OIIO::TypeDesc::HALF &&
      type != OIIO::TypeDesc::DOUBLE)
    throw ImageError(name + ": holds " + spec.format.c_str() +
                     " pixels; a BRDF image is linear floating point (OpenEXR)");
  if (spec.nchannels < 3)
    throw ImageError(name + ": has " + std::to_string(spec.nchannels) +
                     " channel(s); a BRDF image has R, G, B and A");
  Image image(spec.width, spec.height);
  const int channels = std::min(spec.nchannels, 4);
  std::vector<float> buffer(static_cast<std::size_t>(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, buffer.data()))
    throw ImageError(name + ": cannot read pixels: " + in->geterror());
  for (std::size_t p = 0; p < image.rgba.size() / 4; ++p) {
    for (int c = 0; c < 3; ++c) {
      const float v = buffer[channels * p + c];
      if (!(v >= 0 && std::isfinite(v)))
        throw ImageError(name + ": pixel (" + std::to_string(p % spec.width) + ", " +
                         std::to_string(p / spec.width) + ") has " + "RGB"[c] + " = " +
                         std::to_string(v) + "; radiance is finite and not negative");
      image.rgba[4 * p + c] = v;
    }
    image.rgba[4 * p + 3] = channels == 4 ? buffer[channels * p + 3] : 1.f;
  }
  return image;
}

ImageMetadata read_image_metadata(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw ImageError(path.string() + ": cannot read: " + OIIO::geterror());
  ImageMetadata metadata;
  for (const OIIO::ParamValue& p : in->spec().extra_attribs)
    if (p.name().string().rfind(db::kHeaderPrefix, 0) == 0)
      metadata.emplace_back(p.name().string(), p.get_string());
  return metadata;
}

}  // namespace brdfnav
