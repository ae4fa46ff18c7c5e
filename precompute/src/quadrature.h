// The per-pixel quadrature (docs/RENDERER.md): integral of L_env(w) K(w) dw as
//   sum over the pyramid nodes of one level inside the kernel's window of power * K(centroid)
//   + sum over the hot texels of radiance * integral of K over the texel.
// The level is the coarsest whose nodes are at most 1 / texels_per_width of the kernel's narrowest
// width (pieces of texels below level 0); the window is the ellipse of `reach` widths around the
// kernel's peak. Luminance-weighted centroids make the rule exact to first order in the kernel;
// the hot texels (lamps), which lobes see far into their tails, are integrated over pieces as
// fine as the lobe needs wherever it reaches them. No randomness, a fixed order of summation:
// results are deterministic and continuous in the kernel's parameters.
#pragma once

#include "env_pyramid.h"
#include "kernels.h"

#include <brdfnav/precompute/render.h>

#include <array>
#include <utility>
#include <vector>

namespace brdfnav {

// Visibility of the environment from the pixel: always true on the sphere.
struct AlwaysVisible {
  bool operator()(const Vec3&) const { return true; }
};

template <typename Kernel, typename Visible = AlwaysVisible>
class Quadrature {
 public:
  Quadrature(const EnvPyramid& env, const Kernel& kernel, const KernelShape& shape,
             const RenderQuality& quality, Visible visible = {})
      : env_(env), kernel_(kernel), peak_(shape.peak), major_(shape.major),
        minor_(shape.peak.cross(shape.major)), visible_(visible) {
    const double wide = shape.channel_scale.maxCoeff();
    major_width_ = shape.major_width * wide;
    minor_width_ = shape.minor_width * wide;
    reach_ = quality.reach;
    const double step = shape.minor_width / quality.texels_per_width;
    level_ = 0;
    while (level_ + 1 < env.level_count() && env.node_angle(level_ + 1) <= step) ++level_;
    auto split = [&](double piece) {
      return std::clamp(static_cast<int>(std::ceil(env.node_angle(0) / piece)), 1,
                        quality.max_split);
    };
    split_ = level_ > 0 ? 1 : split(step);
    hot_split_ = split(step / 2);
  }

  Rgb integrate() const {
    Rgb sum = window_sum();
    for (const EnvPyramid::HotTexel& t : env_.hot()) sum += hot_sum(t);
    return sum;
  }

 private:
  // Whether a direction within `margin` radians of `w` can be inside the window.
  bool in_window(const Vec3& w, double margin, double reach) const {
    const Vec3 offset = w - peak_;
    if (offset.squaredNorm() > 2 && reach * major_width_ < kPi / 2) return false;  // far side
    const double a = std::max(0.0, std::abs(offset.dot(major_)) - margin) / major_width_;
    const double b = std::max(0.0, std::abs(offset.dot(minor_)) - margin) / minor_width_;
    return a * a + b * b <= reach * reach;
  }

  Rgb value(const Vec3& w) const {
    const Rgb k = kernel_.value(w);
    if (!(k > 0).any() || !visible_(w)) return Rgb::Zero();
    return k;
  }

  // Level-0 texel (x, y) of solid angle `omega` split into split x split pieces of its
  // radiance, each at the texel's centre moved along the tangents of theta and phi (exact to
  // second order in the texel's size) and worth an equal share of the solid angle.
  Rgb pieces(int x, int y, const Rgb& radiance, double omega, int split) const {
    const int w = env_.width(0), h = env_.height(0);
    const double theta = kPi * (y + 0.5) / h, phi = 2 * kPi * ((x + 0.5) / w - 0.5);
    const double st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
    const Vec3 centre(-st * sp, ct, st * cp), e_theta(-ct * sp, -st, ct * cp), e_phi(-cp, 0, -sp);
    const double d_theta = kPi / h / split, d_phi = 2 * kPi / w * st / split;
    Rgb sum = Rgb::Zero();
    for (int j = 0; j < split; ++j) {
      const Vec3 row = centre + ((j + 0.5) - 0.5 * split) * d_theta * e_theta;
      for (int i = 0; i < split; ++i)
        sum += value((row + ((i + 0.5) - 0.5 * split) * d_phi * e_phi).normalized());
    }
    return sum * radiance * (omega / (split * split));
  }

  // The nodes of the window: rows, then the span of columns each row's band reaches.
  Rgb window_sum() const {
    const int w = env_.width(level_);
    const double node = env_.node_angle(level_), margin = 1.5 * node;
    int y0 = 0;
    std::vector<std::pair<int, int>> spans;
    if (!ellipse_spans(margin, y0, spans)) cap_spans(margin, y0, spans);
    Rgb sum = Rgb::Zero();
    for (std::size_t r = 0; r < spans.size(); ++r) {
      const int y = y0 + static_cast<int>(r);
      for (int xs = spans[r].first; xs <= spans[r].second; ++xs) {
        const int x = ((xs % w) + w) % w;
        const EnvNode n = env_.node(level_, x, y);
        if (!(n.power > 0).any() || !in_window(n.centroid, margin, reach_)) continue;
        if (split_ == 1) {
          sum += n.power * value(n.centroid);
        } else {
          const double omega = env_.texel_solid_angle(y);
          sum += pieces(x, y, n.power / omega, omega, split_);
        }
      }
    }
    return sum;
  }

  // Spans of the spherical cap of the window's major radius (any window, but loose for narrow
  // ellipses); whole rows where the cap reaches a pole.
  void cap_spans(double margin, int& y0, std::vector<std::pair<int, int>>& spans) const {
    const int w = env_.width(level_), h = env_.height(level_);
    const double node = env_.node_angle(level_);
    const double radius = std::min(kPi, reach_ * major_width_ + margin);
    const double theta_p = std::acos(std::clamp(peak_.y(), -1.0, 1.0));
    const double u_p = EnvMap::texcoord(peak_).x();
    y0 = std::max(0, static_cast<int>(std::floor((theta_p - radius) / node)));
    const int y1 = std::min(h - 1, static_cast<int>(std::floor((theta_p + radius) / node)));
    for (int y = y0; y <= y1; ++y) {
      const double half = half_width(theta_p, radius, y * node, (y + 1) * node);
      int x0 = 0, x1 = w - 1;
      if (half < kPi) {
        x0 = static_cast<int>(std::floor((u_p - half / (2 * kPi)) * w));
        x1 = std::min(x0 + w - 1, static_cast<int>(std::floor((u_p + half / (2 * kPi)) * w)));
      }
      spans.emplace_back(x0, x1);
    }
  }

  // Spans of a polygon around the window's ellipse in texel coordinates (columns unwrapped around
  // the peak's), scan-converted row by row. False when the window is too wide or reaches a pole,
  // where lat-long coordinates fold: cap_spans() then.
  bool ellipse_spans(double margin, int& y0, std::vector<std::pair<int, int>>& spans) const {
    constexpr int kVertices = 32;
    const double a = reach_ * major_width_ + margin, b = reach_ * minor_width_ + margin;
    const double theta_p = std::acos(std::clamp(peak_.y(), -1.0, 1.0));
    if (a > 1.0 || theta_p - 1.2 * a <= 0 || theta_p + 1.2 * a >= kPi) return false;
    const int w = env_.width(level_), h = env_.height(level_);
    const double x_p = EnvMap::texcoord(peak_).x() * w;
    // Circumscribed: the polygon's edges stay outside the ellipse.
    const double grow = 1 / std::cos(kPi / kVertices);
    std::array<Vec2, kVertices + 1> p;
    double y_min = h, y_max = 0;
    for (int k = 0; k < kVertices; ++k) {
      const double t = 2 * kPi * k / kVertices;
      const Vec3 d = (peak_ + grow * (a * std::cos(t) * major_ + b * std::sin(t) * minor_));
      const Vec2 uv = EnvMap::texcoord(d);
      double x = uv.x() * w - x_p;
      x -= w * std::round(x / w);
      p[k] = Vec2(x_p + x, uv.y() * h);
      y_min = std::min(y_min, p[k].y()), y_max = std::max(y_max, p[k].y());
    }
    p[kVertices] = p[0];
    y0 = std::max(0, static_cast<int>(std::floor(y_min)));
    const int y1 = std::min(h - 1, static_cast<int>(std::floor(y_max)));
    for (int y = y0; y <= y1; ++y) {
      double lo = 1e300, hi = -1e300;
      for (int k = 0; k < kVertices; ++k) {
        const Vec2 &e0 = p[k], &e1 = p[k + 1];
        const double t0 = std::max<double>(y, std::min(e0.y(), e1.y()));
        const double t1 = std::min(y + 1.0, std::max(e0.y(), e1.y()));
        if (t0 > t1) continue;
        const double dy = e1.y() - e0.y();
        for (double t : {t0, t1}) {
          const double x = dy == 0 ? e0.x() : e0.x() + (t - e0.y()) / dy * (e1.x() - e0.x());
          lo = std::min(lo, x), hi = std::max(hi, x);
        }
      }
      if (lo > hi) lo = hi = x_p;
      const int x0 = static_cast<int>(std::floor(lo));
      spans.emplace_back(x0, std::min(x0 + w - 1, static_cast<int>(std::floor(hi))));
    }
    return true;
  }

  // Largest azimuth difference from the peak (at polar angle theta_p) of the directions within
  // `radius` of it whose polar angle is in [t0, t1]; pi when the cap reaches a pole.
  static double half_width(double theta_p, double radius, double t0, double t1) {
    if (theta_p - radius <= 0 || theta_p + radius >= kPi) return kPi;
    double best = 0;
    auto at = [&](double t) {
      const double s = std::sin(t) * std::sin(theta_p);
      if (s <= 0) return kPi;
      const double c = (std::cos(radius) - std::cos(t) * std::cos(theta_p)) / s;
      return c <= -1 ? kPi : c >= 1 ? 0.0 : std::acos(c);
    };
    best = std::max(at(t0), at(t1));
    // The widest latitude of the cap, cos(t) = cos(theta_p) / cos(radius), when in the band.
    if (radius < kPi / 2) {
      const double t = std::acos(std::clamp(std::cos(theta_p) / std::cos(radius), -1.0, 1.0));
      if (t0 < t && t < t1) best = std::max(best, at(t));
    }
    return best;
  }

  // A hot texel, in pieces twice as fine as the window's step wherever a wider window reaches
  // it (the lobe's tails see lamps from afar, where the kernel falls fastest); whole elsewhere.
  Rgb hot_sum(const EnvPyramid::HotTexel& t) const {
    if (hot_split_ > 1 && in_window(t.centroid, env_.node_angle(0), 2 * reach_))
      return pieces(t.x, t.y, t.radiance, t.solid_angle, hot_split_);
    return value(t.centroid) * (t.radiance * t.solid_angle);
  }

  const EnvPyramid& env_;
  const Kernel& kernel_;
  Vec3 peak_, major_, minor_;
  double major_width_, minor_width_, reach_;
  int level_, split_, hot_split_;
  Visible visible_;
};

}  // namespace brdfnav
