// The per-pixel quadrature: integral of L_env(w) K(w) dw as a sum over a cut of the environment's
// quadtree, each node of the cut contributing power * K(centroid) (docs/RENDERER.md). The cut is
// chosen from the kernel's shape alone:
//   - in the core (the ellipse of core_reach standard deviations around the peak) nodes are
//     split until their radius is at most core_size narrow widths (and core_limit radians); the
//     midpoint rule's error there, spread : hessian(K) / 2, is corrected to first order with the
//     Gaussian of the shape;
//   - beyond it nodes are split until their radius is at most far_size times their distance
//     from the core. Centroids are luminance-weighted, so a bright lamp in a coarse far node is
//     still where it is, which is what the lobe's tail sees.
// The traversal order is fixed and depends only on the pixel: results are deterministic.
#pragma once

#include "env_tree.h"
#include "kernels.h"

#include <brdfnav/precompute/render.h>

#include <vector>

namespace brdfnav {

struct QuadratureNode {
  int level, x, y;
};

// Reused between pixels by one thread.
using QuadratureStack = std::vector<QuadratureNode>;

// Visibility of the environment from the pixel: always true on the sphere.
struct AlwaysVisible {
  bool operator()(const Vec3&) const { return true; }
};

template <typename Kernel, typename Visible = AlwaysVisible>
class Quadrature {
 public:
  // `horizon` is the normal of the half space where the kernel lives (nodes wholly below it are
  // skipped); `shape` is in world space.
  Quadrature(const EnvTree& tree, const Kernel& kernel, const KernelShape& shape,
             const Vec3& horizon, const RenderQuality& quality, Visible visible = {})
      : tree_(tree),
        kernel_(kernel),
        peak_(shape.peak),
        major_axis_(shape.major),
        minor_axis_(shape.peak.cross(shape.major)),
        major_width_(shape.major_width),
        minor_width_(shape.minor_width),
        inv_var_(1 / (shape.major_width * shape.major_width),
                 1 / (shape.minor_width * shape.minor_width)),
        horizon_(horizon),
        visible_(visible),
        min_level_(-quality.subtexel_levels),
        reach_(quality.core_reach),
        core_outer_(quality.core_reach * shape.major_width),
        core_radius_(core_radius(shape, quality)),
        far_ratio_(quality.far_size),
        max_nodes_(quality.max_nodes) {}

  Rgb integrate(QuadratureStack& stack) const {
    stack.clear();
    const int top = tree_.top_level();
    for (int y = tree_.height(top) - 1; y >= 0; --y)
      for (int x = tree_.width(top) - 1; x >= 0; --x) stack.push_back({top, x, y});
    Rgb sum = Rgb::Zero();
    int splits = 0;
    while (!stack.empty()) {
      const QuadratureNode n = stack.back();
      stack.pop_back();
      const EnvNode node = tree_.node(n.level, n.x, n.y);
      if (below_horizon(node)) continue;
      const Region region = classify(node);
      if (region == Region::split && n.level > min_level_ && ++splits < max_nodes_) {
        for (int cy = tree_.children_y(n.level, n.y) - 1; cy >= 0; --cy)
          for (int cx = tree_.children_x(n.level, n.x) - 1; cx >= 0; --cx)
            stack.push_back({n.level - 1, 2 * n.x + cx, 2 * n.y + cy});
        continue;
      }
      Rgb k = kernel_.value(node.centroid);
      if (!(k > 0).any() || !visible_(node.centroid)) continue;
      if (region != Region::far) k *= curvature_correction(node);
      sum += node.power * k;
    }
    return sum;
  }

 private:
  enum class Region { split, core, far };

  // The core is coarsened when it would need more than max_nodes / 16 nodes (very anisotropic
  // lobes at grazing angles), so that no pixel reaches the cap.
  static double core_radius(const KernelShape& shape, const RenderQuality& q) {
    const double budget = q.max_nodes / 16.0;
    const double radius = std::min(q.core_size * shape.minor_width, q.core_limit);
    const double area = std::min(2 * kPi, kPi * q.core_reach * q.core_reach * shape.major_width *
                                              shape.minor_width);
    const double nodes = area / (0.25 * radius * radius);
    return nodes > budget ? radius * std::sqrt(nodes / budget) : radius;
  }

  bool below_horizon(const EnvNode& node) const {
    return node.radius < kPi / 2 && node.centroid.dot(horizon_) < -std::sin(node.radius);
  }

  // A node is in the core when any point of the box of half-size `radius` around its centroid
  // (along the shape's axes) is in the ellipse.
  Region classify(const EnvNode& node) const {
    const Vec3 offset = node.centroid - peak_;
    const double r = node.radius;
    const double a = std::max(0.0, std::abs(offset.dot(major_axis_)) - r) / major_width_;
    const double b = std::max(0.0, std::abs(offset.dot(minor_axis_)) - r) / minor_width_;
    if (a * a + b * b < reach_ * reach_) return r > core_radius_ ? Region::split : Region::core;
    const double gap = std::max(0.0, offset.norm() - r - core_outer_);
    return r > far_ratio_ * gap + core_radius_ ? Region::split : Region::far;
  }

  // The midpoint rule's error on a node is about spread : hessian(K) / 2. With K locally the
  // Gaussian of the shape, hessian(K) / K = (A x)(A x)^T - A (A = diag(1 / width^2), x the
  // tangent offset from the peak along the axes), so the node's value is scaled by
  // 1 + ((A x).S.(A x) - tr(A S)) / 2, S its spread in the same axes.
  double curvature_correction(const EnvNode& node) const {
    const Vec3 offset = node.centroid - peak_;
    const Eigen::Vector2d ax =
        Eigen::Vector2d(offset.dot(major_axis_), offset.dot(minor_axis_)).cwiseProduct(inv_var_);
    const Vec3 s1 = node.spread * major_axis_, s2 = node.spread * minor_axis_;
    Eigen::Matrix2d s;
    s << major_axis_.dot(s1), major_axis_.dot(s2), minor_axis_.dot(s1), minor_axis_.dot(s2);
    const double c = 0.5 * (ax.dot(s * ax) - s(0, 0) * inv_var_[0] - s(1, 1) * inv_var_[1]);
    return std::clamp(1 + c, 0.5, 1.5);
  }

  const EnvTree& tree_;
  const Kernel& kernel_;
  Vec3 peak_, major_axis_, minor_axis_;
  double major_width_, minor_width_;
  Eigen::Vector2d inv_var_;
  Vec3 horizon_;
  Visible visible_;
  int min_level_;
  double reach_, core_outer_, core_radius_, far_ratio_;
  int max_nodes_;
};

}  // namespace brdfnav
