// The per-pixel quadrature (docs/RENDERER.md): integral of L_env(w) K(w) dw as
//   sum over the nodes of one grid inside the kernel's window of power * K(centroid), corrected
//   + sum over the hot texels of radiance * integral of K over the texel.
// The grid is the coarsest pyramid level whose nodes are at most 1 / texels_per_width of the
// kernel's narrowest width, or level 0 with every texel cut into equal pieces for kernels
// narrower than that. The window is the ellipse of `reach` widths around the kernel's peak, or
// of `reach` deviations in the half vector's slopes (Ward), enumerated as row segments. A heavy
// tail's (GGX's) nodes grow with their distance from the peak instead: the window's nodes are
// taken from coarser levels where the kernel is smooth at a larger scale (grown_window_sum()).
// Luminance-weighted centroids make the midpoint rule exact to first order; the second order is
// corrected with the grid's own second differences of K (the corrected midpoint rule,
// + (K_left + K_right + K_up + K_down - 4 K) / 24 per node), which summation by parts moves onto
// the powers: each node's K is weighed by EnvNode::weight. The hot texels (lamps), which lobes
// see far into their tails, are cut into pieces as fine as the lobe needs wherever it reaches
// them. No randomness and a fixed order of summation: results are deterministic.
#pragma once

#include "env_pyramid.h"
#include "kernels.h"
#include "quadrature_scratch.h"
#include "window_rows.h"

#include <brdfnav/renderer/render.h>

#include <algorithm>
#include <array>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace brdfnav {

// Visibility of the environment from the pixel: always true on the sphere.
struct AlwaysVisible {
  bool operator()(const Vec3&) const { return true; }
};

template <typename Kernel, typename Visible = AlwaysVisible>
class Quadrature {
  using Value = typename Kernel::Value;
  using Sum = decltype(weighted(Rgb(), Value()));  // Rgb, or one Rgb per lobe of a batch
  // Whether the kernel evaluates a window's nodes at once (slope_window_sum()).
  static constexpr bool kAtOnce = requires(const Kernel& k, const double* x, double* out) {
    k.values_local(x, 1, out);
  };
  static constexpr int kOutline = 32;  // vertices of the window's outline
  // ... of a slope window's: one per kSlopeVertexAngle of its extent (at most
  // kSlopeOutlineStart), then more where they are over kOutlineEdge apart in (phi, theta), as
  // near a pole, up to kSlopeOutline: straight lines in lat-long between them then stay close to
  // the true outline.
  static constexpr int kSlopeOutlineStart = 256;
  static constexpr int kSlopeOutline = 2048;
  static constexpr double kSlopeVertexAngle = 1.0 / 128;
  static constexpr double kOutlineEdge = 0.05;
  static constexpr double kPoleGap = 0.002;  // radians: nearer a pole, lat-long lines fold
  static constexpr double kPolygonCost = 2048;
  static constexpr double kMaxEllipseAspect = 4;
  static_assert(kOutline % 4 == 0 && kSlopeOutlineStart % 4 == 0 &&
                kSlopeOutlineStart <= kMaxOutlineAngles);  // outline_angles()

 public:
  // `horizon` is the normal of the half space the kernel lives in (K = 0 below it), or zero for
  // a kernel without one (He's mirror filter, which is no BRDF).
  Quadrature(const EnvPyramid& env, const Kernel& kernel, const KernelShape& shape,
             const Vec3& horizon, const RenderQuality& quality, Visible visible = {})
      : env_(env),
        kernel_(kernel),
        peak_(shape.peak),
        major_(shape.major),
        minor_(shape.peak.cross(shape.major)),
        horizon_(horizon),
        visible_(visible) {
    const double wide = shape.channel_scale.maxCoeff();
    major_width_ = shape.major_width * wide;
    minor_width_ = shape.minor_width * wide;
    inv_major_ = 1 / major_width_, inv_minor_ = 1 / minor_width_;
    reach_ = quality.reach;
    slopes_ = shape.slopes;
    if (slopes_) {
      slopes_->sx *= wide, slopes_->sy *= wide;
      inv_sx_ = 1 / slopes_->sx, inv_sy_ = 1 / slopes_->sy;
    }
    extent_ = slopes_ ? outline_extent() : reach_ * major_width_;
    // Broad kernels too: the horizon cuts every lobe, and the second differences only correct
    // what is smooth at the scale of a node.
    const double wanted_step =
        std::min(shape.node_width / quality.texels_per_width, quality.max_node);
    // Nodes that grow with their distance from the peak: the window is enumerated at the
    // coarsest level its farthest nodes may have, each node refined while too wide for where it
    // is (grown_window_sum()).
    double top_step = wanted_step;
    if constexpr (kAtOnce)
      if (slopes_ && shape.node_growth > 0)
        top_step =
            std::min(quality.max_node, wanted_step * std::max(1.0, shape.node_growth * reach_));
    if (top_step >= 2 * wanted_step && env.level_count() <= kMaxLevels) growth_ = shape.node_growth;
    peak_theta_ = std::acos(std::clamp(peak_.y(), -1.0, 1.0));
    // Not a slope window over kMaxEllipseAspect times as long as wide either: ellipse_spans()
    // outlines it with kOutline points and widens it by the margin in its narrow deviations,
    // which lengthens it as much again. Ward 0.5 x 0.005 at 32 x 32 had accuracy ratios of
    // 0.52 / 0.79 that way, 0.033 / 0.047 through slope_spans().
    ellipse_ =
        ellipse_fits(0) && (!slopes_ || std::max(slopes_->sx, slopes_->sy) <=
                                            kMaxEllipseAspect * std::min(slopes_->sx, slopes_->sy));
    // A slope window too long for ellipse_spans() is a polygon, which costs about as much as
    // kPolygonCost nodes: not worth it for a small cap.
    if (slopes_ && !ellipse_ && cap_area(extent_) > kPolygonCost * top_step * top_step)
      slope_polygon();
    auto pieces_for = [&](double piece) {
      return std::clamp(static_cast<int>(std::ceil(env.node_angle(0) / piece)), 1,
                        quality.max_split);
    };
    if (growth_ > 0) {
      base_step_ = wanted_step;
      base_level_ = env.coarsest_level(wanted_step);
      base_split_ = base_level_ > 0 ? 1 : pieces_for(wanted_step);
      level_ = env.coarsest_level(top_step);
      split_ = 1;
      grow_levels();
    } else {
      const double step = coarsened_step(wanted_step, quality);
      level_ = env.coarsest_level(step);
      split_ = level_ > 0 ? 1 : pieces_for(step);
    }
    const double hot_step = shape.node_width / quality.hot_texels_per_width;
    hot_step_ = hot_step;
    hot_split_ = pieces_for(hot_step);
    // Hot texels merge into nodes half the size of the pieces the lobe would cut them into: at
    // the pieces' own size, Blinn-Phong n = 300's accuracy ratio rose from 0.030 to 0.034.
    hot_level_ = env.coarsest_level(hot_step / 2);
    grid_w_ = env.width(level_) * split_;
    grid_h_ = env.height(level_) * split_;
    node_angle_ = kPi / grid_h_;
  }

  Sum integrate(QuadratureScratch& scratch) const {
    Sum sum = window_sum(scratch);
    if (hot_level_ == 0) {
      for (const EnvPyramid::HotTexel& t : env_.hot()) sum += hot_sum(t);
    } else {
      for (const EnvPyramid::HotGroup& g : env_.hot_groups(hot_level_)) sum += hot_group_sum(g);
    }
    return sum;
  }

 private:
  // `step`, or the larger step that keeps the nodes the window enumerates within max_nodes: a
  // window that takes the cap (as wide as a hemisphere for a lobe long enough) would otherwise
  // enumerate it at the step of its narrow side. Such a lobe is then integrated a little blurred
  // across, in bounded time.
  double coarsened_step(double step, const RenderQuality& quality) const {
    const double a = extent_, b = reach_ * minor_width_;
    auto area = [&](double h) {  // what window_sum() enumerates, margins included
      if (ellipse_) return kPi * (a + 3 * h) * (b + 3 * h);
      if (outline_n_ > 0) return outline_area_ + 3 * h * outline_perimeter_;
      return cap_area(a + 3 * h);
    };
    for (int i = 0; i < 4 && area(step) > quality.max_nodes * step * step; ++i)
      step = std::sqrt(area(step) / quality.max_nodes);
    return step;
  }

  // Solid angle of the cap of that radius around the peak, or of the hemisphere if smaller.
  double cap_area(double radius) const {
    const double widest = horizon_.squaredNorm() > 0 ? kPi / 2 : kPi;
    return 2 * kPi * (1 - std::cos(std::min(radius, widest)));
  }

  // The point at angle t, given as (cos t, sin t), on the outline of the window in slope space,
  // `radius` deviations out, as an incident direction (world): wo reflected about that half
  // vector.
  Vec3 slope_outline(const Vec2& angle, double radius) const {
    const Vec3 h =
        Vec3(radius * slopes_->sx * angle.x(), radius * slopes_->sy * angle.y(), 1).normalized();
    return slopes_->frame.from_local(reflect(slopes_->wo, h));
  }
  // The largest angle between the peak and the outline of the slope window.
  double outline_extent() const {
    const Vec2* angles = outline_angles(kOutline);
    double extent = 0;
    for (int k = 0; k < kOutline; ++k)
      extent = std::max(
          extent, std::acos(std::clamp(slope_outline(angles[k], reach_).dot(peak_), -1.0, 1.0)));
    return extent;
  }

  // Whether the half vector between w and wo is within `radius` deviations in slope space.
  bool within_slopes(const Vec3& w, double radius) const {
    return within_local_slopes(slopes_->frame.to_local(w), radius);
  }
  // ... for w in the slopes' frame.
  bool within_local_slopes(const Vec3& w, double radius) const {
    const Vec3 h = w + slopes_->wo;
    if (h.z() <= 0) return false;
    // (h.x / (h.z sx))^2 + (h.y / (h.z sy))^2 <= radius^2, without dividing (once per node).
    const double u = h.x() * inv_sx_, v = h.y() * inv_sy_, r = radius * h.z();
    return u * u + v * v <= r * r;
  }

  // Whether a direction within `margin` radians of `w` can be inside the window.
  bool in_window(const Vec3& w, double margin, double reach) const {
    if (slopes_) return within_slopes(w, reach + margin * inv_minor_);
    const Vec3 offset = w - peak_;
    if (offset.squaredNorm() > 2 && reach * major_width_ < kPi / 2) return false;  // far side
    const double a = std::max(0.0, std::abs(offset.dot(major_)) - margin) * inv_major_;
    const double b = std::max(0.0, std::abs(offset.dot(minor_)) - margin) * inv_minor_;
    return a * a + b * b <= reach * reach;
  }

  Value value(const Vec3& w) const { return checked(kernel_.value(w), w); }
  // K, or zero where it is not positive or the environment is hidden in direction w.
  Value checked(const Value& k, const Vec3& w) const {
    return positive(k) && visible_(w) ? k : zero<Value>();
  }

  // Whether w is in the window (`margin` wider), with K there in `k` (zero outside). A slope
  // window is tested in the lobe's frame, which is the kernel's: a kernel that takes a local
  // direction is handed it rather than transforming w again.
  bool window_value(const Vec3& w, double margin, Value& k) const {
    if constexpr (requires { kernel_.value_local(w); }) {
      if (slopes_) {
        const Vec3 local = slopes_->frame.to_local(w);
        const bool inside = within_local_slopes(local, reach_ + margin * inv_minor_);
        k = inside ? checked(kernel_.value_local(local), w) : zero<Value>();
        return inside;
      }
    }
    const bool inside = in_window(w, margin, reach_);
    k = inside ? value(w) : zero<Value>();
    return inside;
  }

  // Pieces of the level-0 texels along one row of the grid (split_ > 1), texel by texel from
  // (tx, ty), in the sub_y-th row of pieces of its texels: each an equal share of its texel's
  // power, with the weight EnvNode has on the grid of pieces, where only the pieces on a
  // texel's edge have neighbours of another power.
  class PieceRow {
   public:
    PieceRow(const EnvPyramid& env, int tx, int ty, int sub_y, int split)
        : env_(env), w_(env.width(0)), tx_(tx), ty_(ty), split_(split) {
      vy_ = sub_y == 0 ? ty - 1 : sub_y == split - 1 ? ty + 1 : -1;
      if (vy_ >= env.height(0)) vy_ = -1;
      share_ = 1.0 / (split * split), edge_share_ = share_ * kSecondDifferenceFactor;
      power_ = env.power(0, tx, ty);
      right_ = env.power(0, tx + 1 < w_ ? tx + 1 : 0, ty);
      weigh(env.power(0, tx > 0 ? tx - 1 : w_ - 1, ty));
    }
    // Piece `sub` (0 .. split - 1 from the left) of the current texel.
    const Rgb& weight(int sub) const {
      return sub == 0 ? left_weight_ : sub == split_ - 1 ? right_weight_ : centre_;
    }
    void next_texel() {
      tx_ = tx_ + 1 == w_ ? 0 : tx_ + 1;
      const Rgb left = power_;
      power_ = right_;
      right_ = env_.power(0, tx_ + 1 < w_ ? tx_ + 1 : 0, ty_);
      weigh(left);
    }

   private:
    // Scalar loops: Eigen left these small expressions as calls, a tenth of a Ward sliver's time.
    void weigh(const Rgb& left) {
      const Rgb up_or_down = vy_ >= 0 ? env_.power(0, tx_, vy_) : power_;
      for (int c = 0; c < 3; ++c) {
        const double p = power_[c], centre = p * share_ + (up_or_down[c] - p) * edge_share_;
        centre_[c] = centre;
        left_weight_[c] = centre + (left[c] - p) * edge_share_;
        right_weight_[c] = centre + (right_[c] - p) * edge_share_;
      }
    }
    const EnvPyramid& env_;
    int w_, tx_, ty_, vy_, split_;
    double share_, edge_share_;  // of a texel's power in each piece; that / 24 (the rule's)
    Rgb power_, right_, centre_, left_weight_, right_weight_;
  };

  // The corrected midpoint rule over the window: weight * K summed over its nodes (EnvNode).
  Sum window_sum(QuadratureScratch& s) const {
    const double margin = 1.5 * node_angle_;
    s.segments.clear();
    if (!ellipse_spans(margin, s) && !slope_spans(margin, s)) cap_spans(margin, s.segments);
    if constexpr (kAtOnce)
      if (slopes_) return growth_ > 0 ? grown_window_sum(s) : slope_window_sum(s, margin);
    Sum sum = zero<Sum>();
    for_each_node(s, [&](const Vec3& centroid, const Rgb& weight) {
      Value k;
      if (window_value(centroid, margin, k)) sum += weighted(weight, k);
    });
    return sum;
  }

  // visit(centroid, weight) for every node of the window's segments, row by row, left to right.
  template <typename Visit>
  void for_each_node(QuadratureScratch& s, Visit&& visit) const {
    // Pieces step along a row by the angle `turn` in phi: their sine and cosine follow by that
    // rotation rather than by a sincos per piece (a fifth of the time of a narrow anisotropic
    // Ward lobe); the rounding drifts by a few 1e-12 at most over a row of 16384 pieces.
    const double turn = 2 * kPi / grid_w_, sin_turn = std::sin(turn), cos_turn = std::cos(turn);
    if (split_ > 1) s.angles.use(grid_w_, grid_h_);
    for (const auto& [y, x0, x1] : s.segments) {
      const int first = wrap(x0);
      if (split_ == 1) {
        for (int xs = x0, x = first; xs <= x1; ++xs, x = x + 1 == grid_w_ ? 0 : x + 1) {
          const EnvNode n = env_.node(level_, x, y);
          visit(n.centroid, n.weight);
        }
        continue;
      }
      const Vec2 theta = s.angles.row(y), phi = s.angles.column(first);
      const double st = theta.x(), ct = theta.y();
      double sp = phi.x(), cp = phi.y();
      // The texel of piece x is (tx, y / split_), x = tx * split_ + sub: counted, not divided.
      int sub = first % split_;
      PieceRow texels(env_, first / split_, y / split_, y % split_, split_);
      for (int xs = x0; xs <= x1; ++xs) {
        visit(Vec3(-st * sp, ct, st * cp), texels.weight(sub));
        // On to the next piece's angle and texel.
        const double next_sp = sp * cos_turn + cp * sin_turn;
        cp = cp * cos_turn - sp * sin_turn, sp = next_sp;
        if (++sub == split_) sub = 0, texels.next_texel();
      }
    }
  }

  // window_sum() for kernels that take arrays of directions (Ward's): K at the nodes of a slope
  // window kChunk at a time, by array expressions and the exponentials four at a time
  // (vector_exp.h). A sliver's window has up to max_nodes nodes, whose arrays at once would not
  // stay in the cache.
  static constexpr Eigen::Index kChunk = 256;
  Sum slope_window_sum(QuadratureScratch& s, double margin) const {
    static_assert(std::is_same_v<Value, double>, "K of the nodes at once is grey");
    s.directions.resize(6 * kChunk);
    s.weight.resize(kChunk);
    s.kernel.resize(kChunk);
    Sum sum = zero<Sum>();
    Eigen::Index n = 0;
    for_each_node(s, [&](const Vec3& centroid, const Rgb& weight) {
      for (int c = 0; c < 3; ++c) s.directions[c * kChunk + n] = centroid[c];
      s.weight[n] = weight;
      if (++n == kChunk) add_chunk(s, n, margin, sum), n = 0;
    });
    add_chunk(s, n, margin, sum);
    return sum;
  }

  // Adds weight * K of the first n nodes in the scratch's arrays to `sum`, in their order.
  void add_chunk(QuadratureScratch& s, Eigen::Index n, double margin, Sum& sum) const {
    using Column = Eigen::Map<Eigen::ArrayXd>;
    double* world = s.directions.data();
    const Column x(world, n), y(world + kChunk, n), z(world + 2 * kChunk, n);
    double* local = world + 3 * kChunk;  // x[0..n), y = x + n, z = x + 2n: values_local()'s
    const Frame& f = slopes_->frame;     // to_local(), column by column
    for (int c = 0; c < 3; ++c) {
      const Vec3& axis = c == 0 ? f.x : c == 1 ? f.y : f.z;
      Column(local + c * n, n) = axis.x() * x + axis.y() * y + axis.z() * z;
    }
    double* k = s.kernel.data();
    kernel_.values_local(local, n, k);
    const double radius = reach_ + margin * inv_minor_;
    Sum total = sum;  // in registers: `sum` may alias the arrays as far as the compiler knows
    for (Eigen::Index i = 0; i < n; ++i) {
      const Vec3 w(local[i], local[n + i], local[2 * n + i]);
      if (within_local_slopes(w, radius) && positive(k[i]) && visible_(Vec3(x[i], y[i], z[i])))
        total += weighted(s.weight[i], k[i]);
    }
    sum = total;
  }

  // The local direction w, or the half vector's slopes to wo scaled to deviations and its
  // height: the node is rho = sqrt(u^2 + v^2) / hz deviations from the peak (hz > 0).
  struct SlopeOffset {
    Vec3 local;
    double uv2, hz;
  };
  SlopeOffset slope_offset(const Vec3& world) const {
    const Frame& f = slopes_->frame;  // to_local(), inline: once per node visited
    const Vec3 local(f.x.dot(world), f.y.dot(world), f.z.dot(world));
    const Vec3 h = local + slopes_->wo;
    const double u = h.x() * inv_sx_, v = h.y() * inv_sy_;
    return {local, u * u + v * v, h.z()};
  }
  // Per level of grown_window_sum(), in deviations: a node is fine enough for where it is
  // (at most base_step_ times max(1, growth_ * its distance from the peak, from its side nearest
  // the peak)) beyond `fine`, and in the window within `window`; squared.
  struct LevelReach {
    double fine2, window2;
  };
  void grow_levels() {
    for (int l = base_level_; l <= level_; ++l) {
      const double angle = env_.node_angle(l), margin = angle * inv_minor_;
      const double fine = angle <= base_step_ ? 0.0 : margin + angle / (base_step_ * growth_);
      const double window = reach_ + 1.5 * margin;
      levels_[l] = {fine * fine, window * window};
    }
  }

  // window_sum() with nodes that grow with their distance from the peak (KernelShape::
  // node_growth): each node of the window's segments (level_, the coarsest the window needs) is
  // refined into its children, down to base_level_ (and the pieces of its texels), while it is
  // wider than LevelReach::fine allows. The nodes kept are in a fixed order; K at them kChunk at
  // a time as in slope_window_sum().
  Sum grown_window_sum(QuadratureScratch& s) const {
    s.directions.resize(6 * kChunk);
    s.weight.resize(kChunk);
    s.kernel.resize(kChunk);
    if (base_split_ > 1) s.angles.use(env_.width(0) * base_split_, env_.height(0) * base_split_);
    Grown g{s, zero<Sum>(), 0};
    for (const RowSegment& segment : s.segments)
      for (int xs = segment.x0; xs <= segment.x1; ++xs)
        visit_grown(level_, wrap(xs), segment.row, g);
    add_local_chunk(g);
    return g.sum;
  }
  struct Grown {
    QuadratureScratch& s;
    Sum sum;
    Eigen::Index n;  // nodes in the chunk
  };
  void visit_grown(int l, int x, int y, Grown& g) const {
    const Vec3 c = env_.centroid(l, x, y);
    const SlopeOffset o = slope_offset(c);
    if (o.hz <= 0) return;  // no half vector: outside any window
    const double hz2 = o.hz * o.hz;
    const bool finest = l == base_level_ && (l > 0 || base_split_ == 1);
    if (!finest && o.uv2 < levels_[l].fine2 * hz2) {
      if (l == 0) return visit_pieces(x, y, g);
      for (int fy = 2 * y; fy < std::min(2 * y + 2, env_.height(l - 1)); ++fy)
        for (int fx = 2 * x; fx < std::min(2 * x + 2, env_.width(l - 1)); ++fx)
          visit_grown(l - 1, fx, fy, g);
      return;
    }
    if (o.uv2 <= levels_[l].window2 * hz2) push_node(c, o.local, env_.weight(l, x, y), g);
  }
  // The base_split_^2 pieces of texel (x, y) in the window, as for_each_node() cuts them.
  void visit_pieces(int x, int y, Grown& g) const {
    const int n = base_split_;
    const double radius = reach_ + 1.5 * env_.node_angle(0) / n * inv_minor_;
    for (int sub_y = 0; sub_y < n; ++sub_y) {
      const PieceRow texel(env_, x, y, sub_y, n);
      const Vec2 theta = g.s.angles.row(y * n + sub_y);
      for (int sub = 0; sub < n; ++sub) {
        const Vec2 phi = g.s.angles.column(x * n + sub);
        const Vec3 w(-theta.x() * phi.x(), theta.y(), theta.x() * phi.y());
        const SlopeOffset o = slope_offset(w);
        if (o.hz > 0 && o.uv2 <= radius * radius * o.hz * o.hz)
          push_node(w, o.local, texel.weight(sub), g);
      }
    }
  }
  void push_node(const Vec3& world, const Vec3& local, const Rgb& weight, Grown& g) const {
    double* d = g.s.directions.data();
    for (int c = 0; c < 3; ++c)
      d[c * kChunk + g.n] = world[c], d[(3 + c) * kChunk + g.n] = local[c];
    g.s.weight[g.n] = weight;
    if (++g.n == kChunk) add_local_chunk(g);
  }
  // Adds weight * K of the chunk's nodes, whose local directions are known, to the sum.
  void add_local_chunk(Grown& g) const {
    const Eigen::Index n = g.n;
    double* world = g.s.directions.data();
    double* local = world + 3 * kChunk;
    if (n < kChunk) {  // values_local() takes y at local + n, z at local + 2n
      std::copy(local + kChunk, local + kChunk + n, local + n);
      std::copy(local + 2 * kChunk, local + 2 * kChunk + n, local + 2 * n);
    }
    double* k = g.s.kernel.data();
    kernel_.values_local(local, n, k);
    Sum total = g.sum;
    for (Eigen::Index i = 0; i < n; ++i)
      if (positive(k[i]) && visible_(Vec3(world[i], world[kChunk + i], world[2 * kChunk + i])))
        total += weighted(g.s.weight[i], k[i]);
    g.sum = total, g.n = 0;
  }

  int wrap(int xs) const {
    const int x = xs % grid_w_;
    return x < 0 ? x + grid_w_ : x;
  }

  // Spans of the spherical cap of the window's major radius (any window, but loose for narrow
  // ellipses), or of the hemisphere above the horizon when that is smaller.
  void cap_spans(double margin, std::vector<RowSegment>& segments) const {
    double radius = std::min(kPi, extent_ + margin);
    Vec3 centre = peak_;
    if (horizon_.squaredNorm() > 0 && radius > kPi / 2 + 2 * margin)
      radius = kPi / 2 + 2 * margin, centre = horizon_;
    const double theta_p = std::acos(std::clamp(centre.y(), -1.0, 1.0));
    const double u_p = EnvMap::texcoord(centre).x();
    const int y0 = std::max(0, static_cast<int>(std::floor((theta_p - radius) / node_angle_)));
    const int y1 =
        std::min(grid_h_ - 1, static_cast<int>(std::floor((theta_p + radius) / node_angle_)));
    for (int y = y0; y <= y1; ++y) {
      const double half = half_width(theta_p, radius, y * node_angle_, (y + 1) * node_angle_);
      int x0 = 0, x1 = grid_w_ - 1;
      if (half < kPi) {
        x0 = static_cast<int>(std::floor((u_p - half / (2 * kPi)) * grid_w_));
        x1 = std::min(x0 + grid_w_ - 1,
                      static_cast<int>(std::floor((u_p + half / (2 * kPi)) * grid_w_)));
      }
      segments.push_back({y, x0, x1});
    }
  }

  // Whether the window's ellipse, `margin` wider, is small and far enough from the poles for
  // ellipse_spans().
  bool ellipse_fits(double margin) const {
    const double extent = extent_ + margin;
    return extent <= 1.0 && peak_theta_ - 1.2 * extent > 0 && peak_theta_ + 1.2 * extent < kPi;
  }

  // Spans of a polygon around the window's ellipse (or the slope window's outline, then as wide
  // as the margin in its narrowest deviations) in grid coordinates (columns unwrapped around
  // the peak's), scan-converted row by row. False when the window is too wide or reaches a pole,
  // where lat-long coordinates fold: slope_spans() or cap_spans() then.
  bool ellipse_spans(double margin, QuadratureScratch& s) const {
    if (!ellipse_) return false;
    const double a = reach_ * major_width_ + margin, b = reach_ * minor_width_ + margin;
    if (!ellipse_fits(margin)) return false;
    const double x_p = EnvMap::texcoord(peak_).x() * grid_w_;
    // Circumscribed: the polygon's edges stay outside the ellipse.
    const double grow = 1 / std::cos(kPi / kOutline);
    std::array<Vec2, kOutline + 1> p;
    const Vec2* angles = outline_angles(kOutline);
    for (int k = 0; k < kOutline; ++k) {
      const Vec2& t = angles[k];
      const Vec3 d = slopes_ ? slope_outline(t, grow * (reach_ + margin * inv_minor_))
                             : peak_ + grow * (a * t.x() * major_ + b * t.y() * minor_);
      const Vec2 uv = EnvMap::texcoord(d);
      double x = uv.x() * grid_w_ - x_p;
      x -= grid_w_ * std::round(x / grid_w_);
      p[k] = Vec2(x_p + x, uv.y() * grid_h_);
    }
    p[kOutline] = p[0];
    convex_polygon_rows(p.data(), kOutline, {grid_w_, grid_h_, node_angle_}, s.segments, s.polygon);
    return true;
  }

  // The outline of a slope window (reach deviations, circumscribed) as outline_n_ points in
  // lat-long coordinates, (phi, theta) in radians, columns unwrapped from point to point, with
  // its area and perimeter there. None (outline_n_ = 0) where lat-long coordinates fold: the
  // window contains both poles, or its outline comes within kPoleGap of one or folds too fast to
  // follow (cap_spans() then).
  void slope_polygon() {
    const int n = std::clamp(static_cast<int>(std::ceil(extent_ / kSlopeVertexAngle / 4)) * 4,
                             kOutline, kSlopeOutlineStart);
    const double radius = reach_ / std::cos(kPi / n);  // circumscribed, as in ellipse_spans()
    // A window around a pole winds around it: the polygon is then closed along the pole's row
    // (theta = 0 or pi). A window around both would not wind: cap_spans() then.
    const bool north = within_slopes(Vec3(0, 1, 0), radius);
    const bool south = within_slopes(Vec3(0, -1, 0), radius);
    if (north && south) return;
    const Vec2* angles = outline_angles(n);
    const Vec2 uv = EnvMap::texcoord(slope_outline(angles[0], radius));
    if (kPi * std::min(uv.y(), 1 - uv.y()) < kPoleGap) return;
    outline_[0] = Vec2(2 * kPi * uv.x(), kPi * uv.y());
    int count = 1;
    for (int k = 0; k < n; ++k)
      if (!append_outline(2 * kPi * k / n, 2 * kPi * (k + 1) / n, angles[k + 1], radius, 10, count))
        return;
    if (north || south) {  // the last point is the first one turn along: to the pole and back
      if (count + 3 > kSlopeOutline + 1) return;
      const double theta = north ? 0.0 : kPi;
      outline_[count] = Vec2(outline_[count - 1].x(), theta);
      outline_[count + 1] = Vec2(outline_[0].x(), theta);
      count += 3;
    }
    const int points = count - 1;  // the last is the first again
    outline_[points] = outline_[0];
    double area = 0, perimeter = 0;
    for (int k = 0; k < points; ++k) {
      area += outline_[k].x() * outline_[k + 1].y() - outline_[k + 1].x() * outline_[k].y();
      perimeter += (outline_[k + 1] - outline_[k]).norm();
    }
    outline_n_ = points, outline_area_ = std::abs(area) / 2, outline_perimeter_ = perimeter;
  }

  // Appends the outline's points after angle t0 (the last appended) up to t1 (whose cosine and
  // sine are `at_t1`), halving the step (at most `depth` times, else false) where consecutive
  // points are more than kOutlineEdge apart in (phi, theta), as near a pole, so that straight
  // lines between them follow the outline.
  bool append_outline(double t0, double t1, const Vec2& at_t1, double radius, int depth,
                      int& count) {
    const Vec2 uv = EnvMap::texcoord(slope_outline(at_t1, radius));
    if (kPi * std::min(uv.y(), 1 - uv.y()) < kPoleGap) return false;
    double x = 2 * kPi * uv.x();
    x -= 2 * kPi * std::round((x - outline_[count - 1].x()) / (2 * kPi));
    const Vec2 p(x, kPi * uv.y());
    if ((p - outline_[count - 1]).norm() > kOutlineEdge) {
      if (depth == 0) return false;  // folded too fast to follow, right by a pole
      const double mid = (t0 + t1) / 2;
      return append_outline(t0, mid, Vec2(std::cos(mid), std::sin(mid)), radius, depth - 1,
                            count) &&
             append_outline(mid, t1, at_t1, radius, depth - 1, count);
    }
    if (count > kSlopeOutline) return false;
    outline_[count++] = p;
    return true;
  }

  // Spans of a slope window too long for ellipse_spans(): its outline scan-converted, then
  // widened by the margin in lat-long, such as the sliver of an anisotropic lobe as long as a
  // hemisphere, whose cap would be a hemisphere. (Widening in slope space, as ellipse_spans()
  // does, would lengthen a long sliver by the margin in its narrow deviations.)
  bool slope_spans(double margin, QuadratureScratch& s) const {
    if (outline_n_ == 0) return false;
    std::array<Vec2, kSlopeOutline + 1> p;
    for (int k = 0; k <= outline_n_; ++k) p[k] = outline_[k] / node_angle_;
    polygon_segments(p.data(), outline_n_, static_cast<int>(std::ceil(margin / node_angle_)),
                     std::sin(kPoleGap / 2), {grid_w_, grid_h_, node_angle_}, s.segments,
                     s.polygon);
    return true;
  }

  // Largest azimuth difference from the peak (at polar angle theta_p) of the directions within
  // `radius` of it whose polar angle is in [t0, t1]; pi in a band that reaches a pole inside the
  // cap. Caps containing a pole (every hemisphere) are still partial in the rows away from it.
  static double half_width(double theta_p, double radius, double t0, double t1) {
    auto at = [&](double t) {
      const double s = std::sin(t) * std::sin(theta_p);
      if (s <= 0) return kPi;
      const double c = (std::cos(radius) - std::cos(t) * std::cos(theta_p)) / s;
      return c <= -1 ? kPi : c >= 1 ? 0.0 : std::acos(c);
    };
    double best = std::max(at(t0), at(t1));
    // The widest latitude of the cap, cos(t) = cos(theta_p) / cos(radius), when in the band.
    if (radius < kPi / 2) {
      const double t = std::acos(std::clamp(std::cos(theta_p) / std::cos(radius), -1.0, 1.0));
      if (t0 < t && t < t1) best = std::max(best, at(t));
    }
    return best;
  }

  // A hot texel, in pieces of hot_split_^2 wherever a window twice as wide reaches it (the
  // lobe's tails see lamps from afar, where the kernel falls fastest); whole farther out.
  Sum hot_sum(const EnvPyramid::HotTexel& t) const {
    // Beyond four times the window even a lamp 10^5 times the map's mean adds nothing: the
    // lobes fall at least like Gaussians of their width there (exp(-98) at the default reach).
    const double margin = env_.node_angle(0);
    if (!in_window(t.centroid, margin, 4 * reach_)) return zero<Sum>();
    int n = hot_split_;
    if (growth_ > 0) {  // as fine as the nodes there, hot_texels_per_width times
      const SlopeOffset o = slope_offset(t.centroid);
      const double rho =
          o.hz > 0 ? std::sqrt(o.uv2) / o.hz : std::numeric_limits<double>::infinity();
      const double near = std::max(0.0, rho - margin * inv_minor_);
      n = std::clamp(
          static_cast<int>(std::ceil(margin / (hot_step_ * std::max(1.0, growth_ * near)))), 1, n);
    }
    if (n == 1 || !in_window(t.centroid, margin, 2 * reach_))
      return weighted(t.radiance, Value(value(t.centroid) * t.solid_angle));
    Value sum = zero<Value>();
    for_each_texel_piece(env_.frame_of_texel(t.x, t.y), n, [&](const Vec3& w) { sum += value(w); });
    return weighted(t.radiance, Value(sum * (t.solid_angle / (n * n))));
  }

  // The hot texels of one node of hot_level_ as one: a lobe that needs no finer pieces than that
  // node sees them at their centroid, as it sees the nodes of the rest of the map. The 106 hot
  // texels of interior.exr, a few lamps, fall into 21 nodes of level 2 and 11 of level 4.
  Sum hot_group_sum(const EnvPyramid::HotGroup& g) const {
    if (!in_window(g.centroid, g.radius, 4 * reach_)) return zero<Sum>();
    return weighted(g.power, value(g.centroid));
  }

  const EnvPyramid& env_;
  const Kernel& kernel_;
  double peak_theta_;  // the peak's polar angle
  bool ellipse_;       // a window ellipse_spans() takes, margins aside
  // slope_polygon(): points, their count (0: none), area and perimeter in (phi, theta) radians.
  std::array<Vec2, kSlopeOutline + 1> outline_;
  int outline_n_ = 0;
  double outline_area_ = 0, outline_perimeter_ = 0;
  Vec3 peak_, major_, minor_, horizon_;
  std::optional<KernelShape::Slopes> slopes_;
  double inv_sx_ = 0, inv_sy_ = 0;  // 1 / slopes_->sx, 1 / slopes_->sy
  double extent_;                   // largest angle between the peak and the window's edge
  double major_width_, minor_width_, inv_major_, inv_minor_, reach_, node_angle_;
  int level_, split_, hot_split_, grid_w_, grid_h_;
  int hot_level_;  // hot texels merged by the nodes of this level (0: one by one)
  double hot_step_;
  // Nodes grown with their distance from the peak (grown_window_sum(); growth_ = 0: not): the
  // node_growth, the finest nodes (a level, then pieces of texels) and their size.
  double growth_ = 0, base_step_ = 0;
  int base_level_ = 0, base_split_ = 1;
  static constexpr int kMaxLevels = 24;        // pyramids of maps up to 2^24 texels wide
  std::array<LevelReach, kMaxLevels> levels_;  // grow_levels(), base_level_ to level_
  Visible visible_;
};

}  // namespace brdfnav
