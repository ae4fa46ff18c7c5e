#include <brdfnav/navigator/blend.h>

#include <brdfnav/core/cube_root.h>

#include <algorithm>
#include <cstdint>
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
  // Only the covered pixels' RGB carry the material: the others are transparent, and black. Their
  // values gathered into contiguous floats let the cube roots, most of the work (a He material
  // blends 64 corners), vectorise; on a 128-pixel sphere they are 59% of the image's floats.
  std::vector<std::uint32_t> covered;  // offsets of the covered pixels' first float
  for (int y = 0; y < diffuse.height; ++y)
    for (int x = 0; x < diffuse.width; ++x)
      if (diffuse.covered(x, y))
        covered.push_back(std::uint32_t(diffuse.pixel(x, y) - &diffuse.rgba[0]));
  const std::size_t m = 3 * covered.size();
  const float rd[3] = {float(rho_d[0]), float(rho_d[1]), float(rho_d[2])};
  const float rs[3] = {float(rho_s[0]), float(rho_s[1]), float(rho_s[2])};
  std::vector<float> root(m, 0.f), linear(m);
  for (std::size_t k = 0; k < specular.size(); ++k) {
    const float* d = diffuse.rgba.data();
    const float* sp = specular[k]->rgba.data();
    for (std::size_t j = 0; j < covered.size(); ++j)
      for (std::size_t c = 0; c < 3; ++c)
        linear[3 * j + c] = rd[c] * d[covered[j] + c] + rs[c] * sp[covered[j] + c];
    const auto w = static_cast<float>(corners[k].weight);
    for (std::size_t i = 0; i < m; ++i) root[i] += w * cube_root(linear[i]);
  }
  Image out(diffuse.width, diffuse.height);
  for (std::size_t p = 0; p < n / 4; ++p) out.rgba[4 * p + 3] = diffuse.rgba[4 * p + 3];
  for (std::size_t j = 0; j < covered.size(); ++j)
    for (std::size_t c = 0; c < 3; ++c) {
      const float r = std::max(root[3 * j + c], 0.f);
      out.rgba[covered[j] + c] = r * r * r;
    }
  return out;
}

}  // namespace brdfnav
