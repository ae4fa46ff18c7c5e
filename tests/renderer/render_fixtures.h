// What the renderer's tests share: interior.exr, a constant environment, channel means, a concave
// mesh and the accuracy target. interior.exr is a specific map here, not the default one (which
// is kDefaultEnvPath): its lamps, about 100 texels holding 40% of its power, are the hardest case
// of the renderer's hot texels, which these tests measure.
#pragma once

#include <brdfnav/studies/render_accuracy.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace brdfnav::test {

inline constexpr const char* kInterior =
    "/usr/share/blender/datafiles/studiolights/world/interior.exr";

inline const EnvMap& interior() {
  static const EnvMap env = EnvMap::load(kInterior, {}, [](const std::string&) {});
  return env;
}

inline EnvMap constant_env(float radiance) {
  return EnvMap(64, 32, std::vector<float>(64 * 32 * 3, radiance), "constant");
}

// Mean of channel c over the covered pixels.
inline double mean(const Image& image, int c) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.covered(x, y)) sum += image.pixel(x, y)[c], ++n;
  return sum / n;
}

// A hemispherical bowl open toward the camera: from its bottom, the rim hides every direction
// below 45 degrees of elevation, so under a constant sky a Lambertian bottom receives
// sin^2(45 deg) = 1/2 of what the sphere's centre does. Written to a temporary OBJ file.
inline std::filesystem::path write_bowl() {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("brdfnav_bowl_" + std::to_string(::getpid()) + ".obj");
  std::ofstream obj(path);
  const int rings = 24, segments = 48;
  obj << "v 0 0 -1\n";
  for (int r = 1; r <= rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double t = 0.5 * kPi * r / rings, p = 2 * kPi * s / segments;
      obj << "v " << std::sin(t) * std::cos(p) << " " << std::sin(t) * std::sin(p) << " "
          << -std::cos(t) << "\n";
    }
  auto v = [&](int r, int s) { return r == 0 ? 1 : 2 + (r - 1) * segments + s % segments; };
  for (int s = 0; s < segments; ++s) obj << "f 1 " << v(1, s) << " " << v(1, s + 1) << "\n";
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s)
      obj << "f " << v(r, s) << " " << v(r + 1, s) << " " << v(r + 1, s + 1) << " " << v(r, s + 1)
          << "\n";
  return path;
}

// A renderer at the reference quality (reference_quality()) of the default one.
inline Renderer reference_renderer(const EnvMap& env, const Scene& scene, int resolution) {
  RenderOptions o;
  o.quality = reference_quality(RenderQuality{});
  return Renderer(env, scene, resolution, o);
}

// The Ward lobes that bend: the anisotropic settings and the sliver 0.5 x 0.005.
inline std::vector<AccuracySetting> bending_ward_settings() {
  std::vector<AccuracySetting> settings = anisotropic_settings();
  settings.push_back(sliver_setting());
  return settings;
}

// The pre-renderer's accuracy target: the error at most a tenth of the change a 10% step makes, for
// every parameter of the setting.
inline void expect_a_tenth_of_a_step(const std::vector<AccuracyResult>& results,
                                     const std::string& setting) {
  for (const AccuracyResult& r : results) {
    EXPECT_GT(r.step, 0) << setting << " " << r.param;
    EXPECT_LE(r.ratio(), 0.1) << setting << " " << r.param << ": error " << r.error << ", step "
                              << r.step;
  }
}

}  // namespace brdfnav::test
