#include <brdfnav/navigator/blend.h>

#include <brdfnav/core/cube_root.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace brdfnav {

Image blend_images(const Image& diffuse, std::span<const ParamGrid::Corner> corners,
                   std::span<const Image* const> specular, const Rgb& rho_d, const Rgb& rho_s) {
  if (specular.size() != corners.size())
    throw std::invalid_argument("blend: " + std::to_string(specular.size()) + " images for " +
                                std::to_string(corners.size()) + " corners");
  const std::size_t n = diffuse.rgba.size();
  for (const Image* image : specular)
    if (image->rgba.size() != n)
      throw ImageError("blend: an image of " + std::to_string(image->width) + "x" +
                       std::to_string(image->height) + " with a diffuse image of " +
                       std::to_string(diffuse.width) + "x" + std::to_string(diffuse.height));
  // Per RGBA lane: the alpha lane gets 0 from both terms and is set from the mask at the end.
  const float d_lane[4] = {float(rho_d[0]), float(rho_d[1]), float(rho_d[2]), 0.f};
  const float s_lane[4] = {float(rho_s[0]), float(rho_s[1]), float(rho_s[2]), 0.f};
  // Single precision in flat loops the compiler vectorises: a He material blends 64 corners.
  std::vector<float> root(n, 0.f), linear(n);
  for (std::size_t k = 0; k < specular.size(); ++k) {
    const float* d = diffuse.rgba.data();
    const float* sp = specular[k]->rgba.data();
    for (std::size_t i = 0; i < n; ++i) linear[i] = d_lane[i % 4] * d[i] + s_lane[i % 4] * sp[i];
    const auto w = static_cast<float>(corners[k].weight);
    for (std::size_t i = 0; i < n; ++i) root[i] += w * cube_root(linear[i]);
  }
  Image out(diffuse.width, diffuse.height);
  for (std::size_t i = 0; i < n; ++i) {
    const float r = std::max(root[i], 0.f);
    out.rgba[i] = i % 4 == 3 ? diffuse.rgba[i] : r * r * r;
  }
  return out;
}

}  // namespace brdfnav
