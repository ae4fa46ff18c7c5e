// The environment as a quadtree of texel blocks, the data structure of the renderer's quadrature.
// Level 0 holds the texels; level l + 1 merges 2x2 blocks of level l up to a 2x1 (or 1x1) top.
// Negative levels split a texel into 2^-l x 2^-l equal-angle pieces of the same radiance, for
// lobes narrower than a texel. Each node carries
//   - its power: sum of radiance * solid angle over its texels (exact for piecewise-constant
//     texels), RGB;
//   - its centroid: the direction of the luminance-weighted first moment of its directions, so
//     that a node holding one bright lamp is represented at the lamp, whatever the node's size;
//   - its radius: an upper bound of the angle between the centroid and any direction in it;
//   - its spread: the luminance-weighted covariance of its directions about the centroid
//     (projected onto the tangent plane there, radians^2), which sets the error of representing
//     the node by its centroid: about spread : hessian(K) / 2.
#pragma once

#include <brdfnav/precompute/env_map.h>

#include <Eigen/Core>

#include <vector>

namespace brdfnav {

struct EnvNode {
  Vec3 centroid;
  Rgb power;
  double radius;
  Eigen::Matrix3d spread;
};

// Geometry of the lat-long rectangle spanning texel coordinates [x0, x1] x [y0, y1] of a
// width x height map: the first moment (integral of the direction over it; |moment| <= solid
// angle), its solid angle, its centre (the direction at the middle of its angle ranges) and its
// half diagonal (angle from the centre to its farthest point, for small rectangles).
struct LatLongRect {
  Vec3 moment;
  double solid_angle;
  Vec3 centre;
  double half_extent;
};
LatLongRect lat_long_rect(double x0, double x1, double y0, double y1, int width, int height);

class EnvTree {
 public:
  explicit EnvTree(const EnvMap& env);

  int top_level() const { return static_cast<int>(levels_.size()) - 1; }
  int width(int level) const { return levels_[level].width; }
  int height(int level) const { return levels_[level].height; }
  int texel_width() const { return levels_[0].width; }
  int texel_height() const { return levels_[0].height; }

  // Node (x, y) of `level`; a negative level is a piece of a texel, computed on the fly.
  EnvNode node(int level, int x, int y) const;
  // Number of children of node (x, y) of `level` along x and y (1 or 2; always 2 below level 1).
  int children_x(int level, int x) const {
    return level <= 0 ? 2 : std::min(2, levels_[level - 1].width - 2 * x);
  }
  int children_y(int level, int y) const {
    return level <= 0 ? 2 : std::min(2, levels_[level - 1].height - 2 * y);
  }

 private:
  struct Level {
    int width = 0, height = 0;
    // per node: centroid xyz, power rgb, radius, spread xx yy zz xy xz yz
    std::vector<float> data;
  };
  static constexpr int kStride = 13;
  // Zeroth, first and second moments of a node's directions, weighted by luminance and (for
  // black nodes) by solid angle, while building.
  struct Moments {
    double weight = 0;
    Vec3 first = Vec3::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    Moments& operator+=(const Moments& o);
  };
  struct NodeMoments {
    Moments lit, geometric;
  };
  EnvNode node_from(const Moments& m, const Rgb& power, int level, int x, int y) const;
  std::vector<NodeMoments> build_first_level(const EnvMap& env);
  std::vector<NodeMoments> build_parent(const std::vector<NodeMoments>& child);
  void store_level(int width, int height, const std::vector<NodeMoments>& moments,
                   const std::vector<Rgb>& power);
  EnvNode piece(int level, int x, int y) const;

  std::vector<Level> levels_;
  std::vector<float> radiance_;  // texel radiance, RGB, row 0 first
};

}  // namespace brdfnav
