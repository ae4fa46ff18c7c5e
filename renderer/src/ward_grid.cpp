#include "ward_grid.h"

#include "ward_grid_sums.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace brdfnav {

namespace {

constexpr std::size_t kChunk = 128;  // nodes whose factors are computed together
// Nodes (and pieces of texels) may be this many times wider than the per-lobe quadrature's at the
// same RenderQuality: their spread counts to second order (emit()). The accuracy ratios and
// times that chose the factor are in docs/RENDERER.md (the quadrature, point 9).
constexpr double kSpreadRelief = 2.5;
// A few points bound a curved node only roughly: this share of its box's size is allowed for its
// bulge toward the peak.
constexpr double kBulge = 0.5;

double square(double x) {
  return x * x;
}

// The extent of a node in slopes: the bounding box of its corners' and centroid's.
struct SlopeBox {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  void add(const Vec2& s) {
    x0 = std::min(x0, s.x()), x1 = std::max(x1, s.x());
    y0 = std::min(y0, s.y()), y1 = std::max(y1, s.y());
  }
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  // How near the peak (the slopes' origin) the node comes along each axis.
  double near_x() const { return std::max(0.0, std::max(x0, -x1) - kBulge * width()); }
  double near_y() const { return std::max(0.0, std::max(y0, -y1) - kBulge * height()); }
};

}  // namespace

WardGridQuadrature::WardGridQuadrature(const EnvPyramid& env, std::span<const double> alpha_x,
                                       std::span<const double> alpha_y,
                                       const RenderQuality& quality)
    : env_(env),
      alpha_x_(alpha_x.begin(), alpha_x.end()),
      alpha_y_(alpha_y.begin(), alpha_y.end()) {
  for (auto [alphas, inverse] :
       {std::pair{&alpha_x_, &inv_alpha2_x_}, {&alpha_y_, &inv_alpha2_y_}}) {
    if (alphas->empty()) throw RenderError("Ward grid: an alpha axis is empty");
    for (double a : *alphas)
      if (!(a > 0) || !std::isfinite(a))
        throw RenderError("Ward grid: alpha must be positive and finite");
    if (!std::is_sorted(alphas->begin(), alphas->end()))
      throw RenderError("Ward grid: the alphas must not decrease");
    inverse->assign(std::size_t(ward_grid::padded(int(alphas->size()))), 0.f);
    for (std::size_t i = 0; i < alphas->size(); ++i)
      (*inverse)[i] = static_cast<float>(1 / ((*alphas)[i] * (*alphas)[i]));
  }
  min_x_ = alpha_x_.front(), max_x_ = alpha_x_.back();
  min_y_ = alpha_y_.front(), max_y_ = alpha_y_.back();
  inv_max_x_ = 1 / max_x_, inv_max_y_ = 1 / max_y_;
  // Per slope deviation (alpha / sqrt(2)) as RenderQuality counts them, per alpha here.
  node_steps_ = quality.texels_per_width * std::sqrt(2.0) / kSpreadRelief;
  hot_steps_ = quality.hot_texels_per_width * std::sqrt(2.0) / kSpreadRelief;
  reach2_ = square(quality.reach) / 2;
  max_split_ = quality.max_split;
  top_level_ = env.coarsest_level(quality.max_node);
  const int w = env.width(0), h = env.height(0);
  for (int y = 0; y <= h; ++y) {
    const double theta = kPi * y / h;
    corner_rows_.emplace_back(std::sin(theta), std::cos(theta));
  }
  for (int x = 0; x <= w; ++x) {
    const double phi = 2 * kPi * (double(x) / w - 0.5);
    corner_columns_.emplace_back(std::sin(phi), std::cos(phi));
  }
}

// One pixel's nodes: collect() gathers them, sum() weighs them for every lobe of the grid.
class WardGridQuadrature::Pixel {
 public:
  Pixel(const WardGridQuadrature& q, const Frame& frame, const Vec3& wo,
        const std::function<bool(const Vec3&)>& visible, WardGridScratch& s)
      : q_(q),
        env_(q.env_),
        frame_(frame),
        wo_(wo),
        x_(frame.to_local(Vec3(1, 0, 0))),
        y_(frame.to_local(Vec3(0, 1, 0))),
        z_(frame.to_local(Vec3(0, 0, 1))),
        visible_(visible),
        s_(s) {
    s.sx.clear(), s.sy.clear(), s.vx.clear(), s.vy.clear();
    for (std::vector<double>& w : s.weight) w.clear();
  }

  void collect() {
    for (int y = 0; y < env_.height(q_.top_level_); ++y)
      for (int x = 0; x < env_.width(q_.top_level_); ++x) visit(q_.top_level_, x, y);
    for (const EnvPyramid::HotTexel& t : env_.hot()) hot(t);
  }

  void sum(double* out) const;

 private:
  // Local direction of the corner (x, y) of the level-0 texels (EnvMap::direction).
  Vec3 corner(int x, int y) const {
    const Vec2& row = q_.corner_rows_[std::size_t(y)];
    const Vec2& column = q_.corner_columns_[std::size_t(x)];
    return row.x() * (column.y() * z_ - column.x() * x_) + row.y() * y_;
  }

  // The half vector's slopes for a local direction; one below the horizon counts where it meets
  // it (straight down onto it), where the lobe ends.
  Vec2 slopes_of(Vec3 p) const {
    if (p.z() < 0) {
      const double planar = std::hypot(p.x(), p.y());
      p = planar > 0 ? Vec3(p.x() / planar, p.y() / planar, 0) : Vec3(0, 0, 0);
    }
    const Vec3 h = p + wo_;
    return Vec2(h.x(), h.y()) / h.z();
  }

  // A node's corners, local, (x0, y0), (x1, y0), (x0, y1), (x1, y1), and their slopes.
  struct Corners {
    Vec3 point[4];
    Vec2 slopes[4];
  };
  Corners corners(int x0, int x1, int y0, int y1) const {
    Corners c;
    const int xs[2] = {x0, x1}, ys[2] = {y0, y1};
    for (int k = 0; k < 4; ++k) {
      c.point[k] = corner(xs[k % 2], ys[k / 2]);
      c.slopes[k] = slopes_of(c.point[k]);
    }
    return c;
  }

  // The slope box of a node given its corners and a point inside it (local), or nothing if the
  // node is below the horizon.
  bool box_of(const Corners& c, const Vec3& inside, SlopeBox& box) const {
    double radius = 0;
    for (const Vec3& p : c.point) radius = std::max(radius, (p - inside).norm());
    if (inside.z() + radius <= 0) return false;
    box.add(slopes_of(inside));
    for (const Vec2& s : c.slopes) box.add(s);
    return true;
  }

  // How many pieces per side the box needs for the lobes whose windows of reach2 hold it, given
  // `steps` pieces per alpha: -1 if no window holds it, at most 1 if it needs no cutting (then
  // not exact), else exact.
  double cuts(const SlopeBox& box, double reach2, double steps) const {
    const double near_x = box.near_x(), near_y = box.near_y();
    const double ux = near_x * q_.inv_max_x_, uy = near_y * q_.inv_max_y_;
    if (ux * ux + uy * uy > reach2) return -1;
    return std::max(
        axis_cuts(box.width() * steps, near_x, reach2 - uy * uy, q_.min_x_, q_.max_x_),
        axis_cuts(box.height() * steps, near_y, reach2 - ux * ux, q_.min_y_, q_.max_y_));
  }
  // `extent` over the narrowest alpha within [lo, hi] whose window reaches `near` along one axis
  // (`room`: reach2 less the other axis's share), or at most 1 where no alpha is narrower.
  static double axis_cuts(double extent, double near, double room, double lo, double hi) {
    if (extent <= lo) return extent / lo;
    return extent / (room > 0 ? std::clamp(near / std::sqrt(room), lo, hi) : hi);
  }

  void visit(int level, int x, int y) {
    if (level == 0) return texel(x, y, corners(x, x + 1, y, y + 1));
    const Rgb power = env_.power(level, x, y);
    if (!(power.maxCoeff() > 0)) return;  // black, or hot texels only (hot())
    const int x0 = x << level, x1 = std::min((x + 1) << level, env_.width(0));
    const int y0 = y << level, y1 = std::min((y + 1) << level, env_.height(0));
    const Vec3 centroid = frame_.to_local(env_.centroid(level, x, y));
    SlopeBox box;
    if (!box_of(corners(x0, x1, y0, y1), centroid, box)) return;
    const double n = cuts(box, q_.reach2_, q_.node_steps_);
    if (n < 0) return;
    if (n <= 1) return emit(centroid, power, env_.spread(level, x, y));
    if (level > 1) {
      for (int cy = 2 * y; cy < std::min(2 * y + 2, env_.height(level - 1)); ++cy)
        for (int cx = 2 * x; cx < std::min(2 * x + 2, env_.width(level - 1)); ++cx)
          visit(level - 1, cx, cy);
      return;
    }
    // The texels of a level-1 node share a lattice of 3 x 3 corners.
    Vec3 point[3][3];
    Vec2 slopes[3][3];
    const int xs[3] = {x0, std::min(x0 + 1, x1), x1}, ys[3] = {y0, std::min(y0 + 1, y1), y1};
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) slopes[j][i] = slopes_of(point[j][i] = corner(xs[i], ys[j]));
    for (int j = 0; j < 2 && ys[j] < ys[j + 1]; ++j)
      for (int i = 0; i < 2 && xs[i] < xs[i + 1]; ++i)
        texel(xs[i], ys[j],
              {{point[j][i], point[j][i + 1], point[j + 1][i], point[j + 1][i + 1]},
               {slopes[j][i], slopes[j][i + 1], slopes[j + 1][i], slopes[j + 1][i + 1]}});
  }

  void texel(int x, int y, const Corners& c) {
    const Rgb power = env_.power(0, x, y);
    if (!(power.maxCoeff() > 0)) return;
    const Vec3 centre = (c.point[0] + c.point[1] + c.point[2] + c.point[3]).normalized();
    SlopeBox box;
    if (!box_of(c, centre, box)) return;
    const double n = cuts(box, q_.reach2_, q_.node_steps_);
    if (n < 0) return;
    if (n <= 1) return emit(centre, power, env_.spread(0, x, y));
    pieces(x, y, n, power);
  }

  // A level-0 texel cut into ceil(cuts)^2 pieces (at most max_split^2) of equal shares.
  void pieces(int x, int y, double cuts, const Rgb& power) {
    const int n = std::clamp(static_cast<int>(std::ceil(cuts)), 1, q_.max_split_);
    const Rgb share = power / double(n * n);
    const TexelFrame t = env_.frame_of_texel(x, y);
    const Eigen::Matrix3d spread = EnvPyramid::texel_spread(t) / double(n * n);
    for_each_texel_piece(t, n, [&](const Vec3& w) { emit(frame_.to_local(w), share, spread); });
  }

  // A hot texel: cut where a window twice the lobes' reaches it, whole out to four times it.
  void hot(const EnvPyramid::HotTexel& t) {
    SlopeBox box;
    const Vec3 centroid = frame_.to_local(t.centroid);
    if (!box_of(corners(t.x, t.x + 1, t.y, t.y + 1), centroid, box)) return;
    if (cuts(box, 16 * q_.reach2_, q_.hot_steps_) < 0) return;
    const double n = cuts(box, 4 * q_.reach2_, q_.hot_steps_);
    if (n <= 1)
      return emit(centroid, t.radiance * t.solid_angle,
                  EnvPyramid::texel_spread(env_.frame_of_texel(t.x, t.y)));
    pieces(t.x, t.y, n, t.radiance * t.solid_angle);
  }

  // A node in the local direction w with its power, spread over directions with that covariance
  // (world). To first order a direction's offset d (local) moves the slopes by
  // (d.x - sx d.z, d.y - sy d.z) / h.z: their variances follow.
  void emit(const Vec3& w, const Rgb& power, const Eigen::Matrix3d& spread) {
    if (w.z() <= 0 || (visible_ && !visible_(frame_.from_local(w)))) return;
    const Vec3 h = w + wo_;
    const double inv_hz = 1 / h.z(), sx = h.x() * inv_hz, sy = h.y() * inv_hz;
    const Vec3 along_x = frame_.x - sx * frame_.z, along_y = frame_.y - sy * frame_.z;
    s_.sx.push_back(sx);
    s_.sy.push_back(sy);
    s_.vx.push_back(along_x.dot(spread * along_x) * inv_hz * inv_hz);
    s_.vy.push_back(along_y.dot(spread * along_y) * inv_hz * inv_hz);
    const double cos_factor = std::sqrt(w.z());
    for (int c = 0; c < 3; ++c) s_.weight[c].push_back(power[c] * cos_factor);
  }

  const WardGridQuadrature& q_;
  const EnvPyramid& env_;
  const Frame& frame_;
  Vec3 wo_;
  Vec3 x_, y_, z_;  // the world axes in the local frame
  const std::function<bool(const Vec3&)>& visible_;
  WardGridScratch& s_;
};

void WardGridQuadrature::Pixel::sum(double* out) const {
  const int nx = int(q_.nx()), ny = int(q_.ny());
  const int stride_x = ward_grid::padded(nx), stride_y = ward_grid::padded(ny);
  const std::size_t count = s_.sx.size();
  s_.gx.resize(kChunk * stride_x), s_.gy.resize(kChunk * stride_y);
  s_.scratch.resize(kChunk * std::max(stride_x, stride_y));
  s_.first.resize(2 * kChunk);
  s_.sums.assign(std::size_t(3 * nx * stride_y), 0.0);
  for (std::size_t start = 0; start < count; start += kChunk) {
    const int c = int(std::min(kChunk, count - start));
    ward_grid::gaussian_factors({s_.sx.data() + start, s_.vx.data() + start,
                                 q_.inv_alpha2_x_.data(), c, nx, s_.gx.data(), s_.scratch.data(),
                                 s_.first.data()});
    ward_grid::gaussian_factors({s_.sy.data() + start, s_.vy.data() + start,
                                 q_.inv_alpha2_y_.data(), c, ny, s_.gy.data(), s_.scratch.data(),
                                 s_.first.data() + kChunk});
    const double* weight[3] = {s_.weight[0].data() + start, s_.weight[1].data() + start,
                               s_.weight[2].data() + start};
    ward_grid::accumulate({s_.gx.data(), s_.gy.data(), weight, s_.first.data(),
                           s_.first.data() + kChunk, c, nx, ny, s_.sums.data()});
  }
  const double norm = 1 / (4 * kPi * std::sqrt(wo_.z()));
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double scale = norm / (q_.alpha_x_[std::size_t(i)] * q_.alpha_y_[std::size_t(j)]);
      for (int c = 0; c < 3; ++c)
        out[3 * (i * ny + j) + c] = s_.sums[std::size_t((c * nx + i) * stride_y + j)] * scale;
    }
}

void WardGridQuadrature::integrate(const Frame& frame, const Vec3& wo,
                                   const std::function<bool(const Vec3&)>& visible,
                                   WardGridScratch& scratch, double* out) const {
  if (wo.z() <= 0) {
    std::fill(out, out + 3 * nx() * ny(), 0.0);
    return;
  }
  Pixel pixel(*this, frame, wo, visible, scratch);
  pixel.collect();
  pixel.sum(out);
}

}  // namespace brdfnav
