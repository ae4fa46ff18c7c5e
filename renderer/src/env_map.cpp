#include <brdfnav/renderer/env_map.h>

#include <brdfnav/core/sha1.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstdio>
#include <optional>

namespace brdfnav {

namespace {

// The SHA-1 of the float RGB texels' bytes, row 0 first: what OpenImageIO's
// ImageBufAlgo::computePixelHashSHA1() gave for them, which older manifests record
// (tests/renderer/test_sha1_oiio.cpp).
std::string texels_sha1(const std::vector<float>& rgb) {
  Sha1 sha;
  sha.append(rgb.data(), rgb.size() * sizeof(float));
  return sha.digest();
}

void check_shape(const std::string& source, int width, int height) {
  // In 64 bits: a header may claim a height whose double overflows an int.
  if (width <= 0 || height <= 0 || width != 2 * std::int64_t{height})
    throw EnvMapError(source + ": is " + std::to_string(width) + "x" + std::to_string(height) +
                      "; a latitude-longitude map must be exactly 2:1 (width = 2 * height)");
}

struct RawMap {
  int width, height;
  std::vector<float> rgb;
};

RawMap read_rgb(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw EnvMapError(name + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw EnvMapError(name + ": is a directory");
  auto in = OIIO::ImageInput::open(name);
  if (!in) throw EnvMapError(name + ": cannot read: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3)
    throw EnvMapError(name + ": has " + std::to_string(spec.nchannels) +
                      " channel(s); an environment map needs at least 3 (R, G, B)");
  check_shape(name, spec.width, spec.height);
  if (spec.width > kMaxEnvWidth)
    throw EnvMapError(name + ": is " + std::to_string(spec.width) + "x" +
                      std::to_string(spec.height) + "; brdfnav reads environment maps up to " +
                      std::to_string(kMaxEnvWidth) + "x" + std::to_string(kMaxEnvWidth / 2) +
                      " (downsample it, e.g. oiiotool IN --resize 4096x2048 -o OUT)");
  RawMap map{spec.width, spec.height, {}};
  map.rgb.resize(static_cast<std::size_t>(spec.width) * spec.height * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, map.rgb.data()))
    throw EnvMapError(name + ": cannot read pixels: " + in->geterror());
  return map;
}

// Texels (not components) matching `bad`, each set to `replacement` componentwise where bad.
template <typename Bad>
std::size_t fix_texels(std::vector<float>& rgb, Bad bad, float replacement) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    bool any = false;
    for (std::size_t c = i; c < i + 3; ++c) {
      if (bad(rgb[c])) {
        rgb[c] = replacement;
        any = true;
      }
    }
    count += any;
  }
  return count;
}

}  // namespace

EnvMap EnvMap::load(const std::filesystem::path& path, const EnvLoadOptions& options,
                    const WarningSink& warn) {
  const std::string name = path.string();
  RawMap map = read_rgb(path);
  std::vector<float>& rgb = map.rgb;
  const std::size_t non_finite = fix_texels(
      rgb, [](float v) { return !std::isfinite(v); }, 0.f);
  if (non_finite > 0) {
    const std::string what = std::to_string(non_finite) + " texel(s) are NaN or infinite";
    if (!options.sanitize)
      throw EnvMapError(name + ": " + what +
                        " (the sanitize option, --sanitize-env, sets them to 0)");
    if (warn) warn(name + ": " + what + "; set to 0");
  }
  // Filtered and compressed maps ring slightly below 0 around their lamps (Blender's maps down
  // to -0.4% of their mean): clamped silently. A negative beyond kNegligibleNegative of the mean
  // says something is wrong with the map, and is warned of.
  double sum = 0, lowest = 0;
  for (float v : rgb) {
    sum += std::max(v, 0.f);
    lowest = std::min<double>(lowest, v);
  }
  const double mean = sum / double(rgb.size());
  const std::size_t negative = fix_texels(
      rgb, [](float v) { return v < 0; }, 0.f);
  if (negative > 0 && warn && lowest < -kNegligibleNegative * mean) {
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, " (down to %.3g, against a mean of %.3g)", lowest, mean);
    warn(name + ": clamped " + std::to_string(negative) +
         " texel(s) with negative components to 0" + numbers);
  }
  return EnvMap(map.width, map.height, std::move(rgb), name);
}

EnvMap::EnvMap(int width, int height, std::vector<float> rgb, std::string source)
    : width_(width), height_(height), rgb_(std::move(rgb)), source_(std::move(source)) {
  check_shape(source_, width, height);
  if (rgb_.size() != static_cast<std::size_t>(width) * height * 3)
    throw EnvMapError(source_ + ": expected " + std::to_string(width * height * 3) +
                      " floats, got " + std::to_string(rgb_.size()));
  for (float v : rgb_)
    if (!std::isfinite(v) || v < 0)
      throw EnvMapError(source_ + ": texels must be finite and non-negative");
  pixel_sha1_ = texels_sha1(rgb_);
}

Vec3 EnvMap::direction(double u, double v) {
  const double phi = 2 * kPi * (u - 0.5), theta = kPi * v;
  const double s = std::sin(theta);
  return {-s * std::sin(phi), std::cos(theta), s * std::cos(phi)};
}

Vec2 EnvMap::texcoord(const Vec3& d) {
  const double phi = std::atan2(-d.x(), d.z());
  const double v = std::acos(std::clamp(d.y() / d.norm(), -1.0, 1.0)) / kPi;
  return {0.5 + phi / (2 * kPi), v};
}

EnvMap load_recorded_env(const std::string& path, const std::string& pixel_sha1,
                         const std::string& recorder) {
  std::optional<EnvMap> env;
  try {
    env = EnvMap::load(path, {.sanitize = true}, [](const std::string&) {});
  } catch (const EnvMapError& e) {
    throw EnvMapError(e.what() + (" (the environment map " + recorder + " names)"),
                      ErrorCode::database);
  }
  if (env->pixel_sha1() != pixel_sha1)
    throw EnvMapError(path + ": changed since the database was built (pixel sha1 " +
                          env->pixel_sha1() + ", " + recorder + " says " + pixel_sha1 + ")",
                      ErrorCode::database);
  return std::move(*env);
}

}  // namespace brdfnav
