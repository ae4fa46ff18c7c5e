#include <brdfnav/lookdev/database_env.h>

#include <brdfnav/core/math.h>
#include <brdfnav/navigator/database_format.h>

#include <cstdint>
#include <string>
#include <vector>

namespace brdfnav {

EnvMap load_database_env(const Database& db) {
  const Manifest& m = db.manifest();
  return load_recorded_env(m.env_path, m.env_pixel_sha1, (db.dir() / db::kManifestFile).string());
}

Image environment_picture(const EnvMap& env, int width) {
  if (width < 2 || width > env.width())
    throw Error(ErrorCode::invalid_argument, "environment picture: width " + std::to_string(width) +
                                                 " of a map " + std::to_string(env.width()) +
                                                 " wide (" + env.source() + ")");
  const int height = width / 2;
  std::vector<Rgb> sum(std::size_t(width) * height, Rgb::Zero());
  std::vector<int> count(sum.size(), 0);
  for (int y = 0; y < env.height(); ++y) {
    const std::size_t row = std::size_t(std::int64_t(y) * height / env.height()) * width;
    for (int x = 0; x < env.width(); ++x) {
      const std::size_t i = row + std::size_t(std::int64_t(x) * width / env.width());
      sum[i] += env.texel(x, y);
      ++count[i];
    }
  }
  const double mean = luminance_power(env) / (4 * kPi);
  const double exposure = mean > 0 ? 0.18 / mean : 1;
  Image picture(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * width + x;
      float* out = picture.pixel(x, y);
      for (int c = 0; c < 3; ++c) out[c] = float(exposure * sum[i][c] / count[i]);
      out[3] = 1.f;
    }
  }
  return picture;
}

}  // namespace brdfnav
