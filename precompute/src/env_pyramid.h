// The environment as the renderer's quadrature sees it (docs/RENDERER.md):
//   - hot texels: the brightest texels (lamps, the sun), taken out of the map and kept as a list,
//     so that every lobe, however narrow, sees each of them exactly where it is;
//   - a pyramid of the rest: level 0 holds the texels, level l + 1 merges 2 x 2 blocks of level
//     l. Each node carries its power (sum of radiance * solid angle: exact for the piecewise
//     constant map) and its luminance-weighted centroid direction, so that summing
//     power * K(centroid) over the nodes of one level integrates a kernel K without first-order
//     error, at any level.
// Orientation is EnvMap's (env_map.h): u across the columns, v = theta / pi down the rows.
#pragma once

#include <brdfnav/precompute/env_map.h>

#include <vector>

namespace brdfnav {

struct EnvNode {
  Vec3 centroid;  // unit
  Rgb power;
};

class EnvPyramid {
 public:
  explicit EnvPyramid(const EnvMap& env);

  int level_count() const { return static_cast<int>(levels_.size()); }
  int width(int level) const { return levels_[level].width; }
  int height(int level) const { return levels_[level].height; }
  // Angular height of a node of `level` (the rows are uniform in theta).
  double node_angle(int level) const { return kPi / levels_[level].height; }
  EnvNode node(int level, int x, int y) const {
    const Level& l = levels_[level];
    const float* d = &l.data[kStride * (static_cast<std::size_t>(y) * l.width + x)];
    return {Vec3(d[0], d[1], d[2]), Rgb(d[3], d[4], d[5])};
  }
  struct HotTexel {
    int x, y;      // level-0 coordinates
    Rgb radiance;  // of the original map
    Vec3 centroid;
    double solid_angle;
  };
  const std::vector<HotTexel>& hot() const { return hot_; }

 private:
  // per node: centroid xyz, power rgb
  static constexpr int kStride = 6;
  struct Level {
    int width = 0, height = 0;
    std::vector<float> data;
    std::vector<double> luminance;  // of the node's power, while building
  };
  void build_texels(const EnvMap& env);
  Level half_of(const Level& fine) const;

  std::vector<HotTexel> hot_;
  std::vector<Level> levels_;
};

}  // namespace brdfnav
