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

#include <brdfnav/renderer/env_map.h>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace brdfnav {

// The corrected midpoint rule's factor of the second differences: the error of the midpoint rule
// over a cell is its second derivatives times the cell's size squared over 24.
inline constexpr double kSecondDifferenceFactor = 1.0 / 24;

// Texel (x, y) of a map width x height, flat in its tangent plane: its centre, the unit tangents
// of theta and phi there, and its extent along each.
struct TexelFrame {
  Vec3 centre, e_theta, e_phi;
  double d_theta, d_phi;
};
// The sine and cosine of a texel centre's theta (of its row) or phi (of its column).
struct SinCos {
  double sin, cos;
};
inline SinCos texel_theta(int y, int height) {
  const double theta = kPi * (y + 0.5) / height;
  return {std::sin(theta), std::cos(theta)};
}
inline SinCos texel_phi(int x, int width) {
  const double phi = 2 * kPi * ((x + 0.5) / width - 0.5);
  return {std::sin(phi), std::cos(phi)};
}
// From its row's and its column's angles (tables of them spare a map's texels the sines).
inline TexelFrame texel_frame(SinCos theta, SinCos phi, int width, int height) {
  const double st = theta.sin, ct = theta.cos, sp = phi.sin, cp = phi.cos;
  return {Vec3(-st * sp, ct, st * cp), Vec3(-ct * sp, -st, ct * cp), Vec3(-cp, 0, -sp),
          kPi / height, 2 * kPi / width * st};
}
inline TexelFrame texel_frame(int x, int y, int width, int height) {
  return texel_frame(texel_theta(y, height), texel_phi(x, width), width, height);
}

// The directions of the n x n pieces of the texel of frame t, rows then columns, each with an
// equal share of its solid angle: the texel's centre moved along the tangents of theta and phi
// (exact to second order in the texel's size), f(direction) for each. Then the same of texel
// (x, y) of a map width x height.
template <typename F>
void for_each_texel_piece(const TexelFrame& t, int n, F&& f) {
  const double d_theta = t.d_theta / n, d_phi = t.d_phi / n;
  for (int j = 0; j < n; ++j) {
    const Vec3 row = t.centre + ((j + 0.5) - 0.5 * n) * d_theta * t.e_theta;
    for (int i = 0; i < n; ++i) f((row + ((i + 0.5) - 0.5 * n) * d_phi * t.e_phi).normalized());
  }
}
template <typename F>
void for_each_texel_piece(int x, int y, int width, int height, int n, F&& f) {
  for_each_texel_piece(texel_frame(x, y, width, height), n, std::forward<F>(f));
}

struct EnvNode {
  Vec3 centroid;  // unit
  Rgb power;
  // What the corrected midpoint rule weighs K(centroid) with: the power plus the second
  // differences of the level's powers, power + sum over the neighbours of (theirs - power) / 24.
  // Summed by parts, sum of weight * K equals the rule's sum of power * (K + its second
  // differences / 24) (docs/RENDERER.md), without reading K at the neighbours.
  Rgb weight;
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
    const std::size_t i = l.index(x, y);
    return {l.centroid_at(i), rgb(l.power, i), rgb(l.weight, i)};
  }
  // The luminance-weighted covariance of the directions within a node about its centroid
  // (world): how its power is spread, to second order. A texel's is its own extent's.
  Eigen::Matrix3d spread(int level, int x, int y) const {
    if (level == 0) return rounded_texel_spread(x, y);
    const Level& l = levels_[level];
    return l.spread_at(l.index(x, y));
  }
  // ... of texel (x, y) of a map width x height, as a flat rectangle in its tangent plane.
  static Eigen::Matrix3d texel_spread(int x, int y, int width, int height);
  static Eigen::Matrix3d texel_spread(const TexelFrame& t);
  // texel_frame() of level-0 texel (x, y), from the tables of its row's and column's angles.
  TexelFrame frame_of_texel(int x, int y) const {
    return texel_frame(texel_thetas_[std::size_t(y)], texel_phis_[std::size_t(x)], width(0),
                       height(0));
  }
  Vec3 centroid(int level, int x, int y) const {
    const Level& l = levels_[level];
    return l.centroid_at(l.index(x, y));
  }
  Rgb power(int level, int x, int y) const {
    const Level& l = levels_[level];
    return rgb(l.power, l.index(x, y));
  }
  Rgb weight(int level, int x, int y) const {
    const Level& l = levels_[level];
    return rgb(l.weight, l.index(x, y));
  }
  struct HotTexel {
    int x, y;      // level-0 coordinates
    Rgb radiance;  // of the original map
    Vec3 centroid;
    double solid_angle;
  };
  const std::vector<HotTexel>& hot() const { return hot_; }
  // The hot texels merged by the nodes of one level, for lobes broad enough not to tell them
  // apart: their summed power, their luminance-weighted centroid and the largest angle from it
  // to a point of a member texel.
  struct HotGroup {
    Vec3 centroid;
    Rgb power;
    double radius;
  };
  // Level >= 1, in node order (level 0 is hot() itself).
  const std::vector<HotGroup>& hot_groups(int level) const { return hot_groups_[level]; }
  // The coarsest level whose nodes are at most `step` radians high (0 if none is).
  int coarsest_level(double step) const {
    int level = 0;
    while (level + 1 < level_count() && node_angle(level + 1) <= step) ++level;
    return level;
  }

 private:
  // Per node three floats in each array (six in spread: xx, xy, xz, yy, yz, zz): the pieces of
  // split texels read the power alone. Level 0 keeps no spreads: a texel's is a function of its
  // row's and its column's angles, computed when asked for (24 of its 60 bytes per texel).
  struct Level {
    int width = 0, height = 0;
    std::vector<float> centroid, power, weight, spread;
    std::vector<double> luminance;  // of the node's power, while building
    std::size_t index(int x, int y) const { return 3 * (static_cast<std::size_t>(y) * width + x); }
    Vec3 centroid_at(std::size_t i) const {
      return Vec3(centroid[i], centroid[i + 1], centroid[i + 2]);
    }
    Eigen::Matrix3d spread_at(std::size_t i) const { return unpack_spread(&spread[2 * i]); }
  };
  // A spread as the pyramid keeps it: the six entries of its upper triangle as floats.
  static std::array<float, 6> pack_spread(const Eigen::Matrix3d& m) {
    return {float(m(0, 0)), float(m(0, 1)), float(m(0, 2)),
            float(m(1, 1)), float(m(1, 2)), float(m(2, 2))};
  }
  static Eigen::Matrix3d unpack_spread(const float* s) {
    Eigen::Matrix3d m;
    m << s[0], s[1], s[2], s[1], s[3], s[4], s[2], s[4], s[5];
    return m;
  }
  // Texel (x, y)'s spread, rounded as every other level's are.
  Eigen::Matrix3d rounded_texel_spread(int x, int y) const;
  static Rgb rgb(const std::vector<float>& values, std::size_t i) {
    return Rgb(values[i], values[i + 1], values[i + 2]);
  }
  void build_texels(const EnvMap& env);
  Level half_of(int fine_level) const;
  static void weigh(Level& level);
  std::vector<HotGroup> group_hot_texels(int level) const;

  std::vector<SinCos> texel_thetas_, texel_phis_;  // of level 0's rows and columns
  std::vector<HotTexel> hot_;
  std::vector<std::vector<HotGroup>> hot_groups_;  // per level; level 0 empty
  std::vector<Level> levels_;
};

}  // namespace brdfnav
