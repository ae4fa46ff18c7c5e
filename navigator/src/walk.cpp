#include "walk.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace brdfnav::nav {

namespace {

// The crossing is refined until the distance is within this fraction of the radius: far below
// the embedding's own accuracy (about 1e-2), and above the single-precision noise of embedded
// distances (about 1e-7 of an embedding's norm, up to 1e-5 of a small radius). The iteration
// bound keeps the answer a function of the inputs alone.
constexpr double kRadiusTolerance = 1e-4;
constexpr int kMaxRefinements = 60;

// One parameter a lobe path moves, in the parameter's own scale (log or linear).
struct MovingAxis {
  std::size_t index;
  ParamSpec spec;
  double front, back;              // the grid's ends, in scale units
  double front_value, back_value;  // ... and as values, to land on them exactly
  double start;                    // the current value in scale units, clamped to the grid
};

MovingAxis moving_axis(const Material& m, const ParamGrid& grid, std::size_t index) {
  const ParamSpec& spec = grid.specs()[index];
  const std::vector<double>& nodes = grid.axis(index);
  MovingAxis a{index,
               spec,
               to_scale(spec, nodes.front()),
               to_scale(spec, nodes.back()),
               nodes.front(),
               nodes.back(),
               0.0};
  // Outside the grid the embedding is clamped (flat): the walk starts where it ends.
  a.start = std::clamp(to_scale(spec, m.params[index]), a.front, a.back);
  return a;
}

// The value of axis `a` after moving `step` scale units; grid ends are hit exactly.
double moved_value(const MovingAxis& a, double step) {
  const double x = a.start + step;
  const double tolerance = 1e-12 * (std::abs(a.back - a.front) + 1);
  if (x >= a.back - tolerance) return a.back_value;
  if (x <= a.front + tolerance) return a.front_value;
  return from_scale(a.spec, x);
}

// Moves every axis of `indices` by sign * s scale units together, up to the first grid end.
Path scale_path(const Material& m, const ParamGrid& grid, const std::vector<std::size_t>& indices,
                double sign, std::string label) {
  std::vector<MovingAxis> axes;
  double end = std::numeric_limits<double>::infinity();
  std::vector<double> breaks;
  for (std::size_t index : indices) {
    const MovingAxis a = moving_axis(m, grid, index);
    end = std::min(end, sign > 0 ? a.back - a.start : a.start - a.front);
    // Every grid node ahead is a cell boundary of the path.
    for (double node : grid.axis(index))
      breaks.push_back(sign * (to_scale(a.spec, node) - a.start));
    axes.push_back(a);
  }
  end = std::max(end, 0.0);
  std::erase_if(breaks, [&](double s) { return !(s > 0 && s < end); });
  breaks.push_back(0.0);
  breaks.push_back(end);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  auto material = [m, axes, sign](double s) {
    Material out = m;
    if (s <= 0) return out;  // exactly the current material, even when it lies off the grid
    for (const MovingAxis& a : axes) out.params[a.index] = moved_value(a, sign * s);
    return out;
  };
  return {std::move(label), std::move(material), std::move(breaks)};
}

}  // namespace

Hit walk_to_sphere(const ModelEmbedding& embedding, const Eigen::VectorXf& centre, double radius,
                   const Path& path, double start_distance) {
  // The root of f(s) = distance(s) - radius, negative inside the sphere. A hit reports the
  // distance itself: distance - radius + radius would lose it to rounding when the radius is far
  // larger.
  const auto distance = [&](double s) {
    return embedding_distance(embedding.embed(path.material(s)), centre);
  };
  double lo = 0, f_lo = start_distance - radius;  // the walk starts inside
  for (std::size_t i = 1; i < path.breaks.size(); ++i) {
    double hi = path.breaks[i], d_hi = distance(hi), f_hi = d_hi - radius;
    if (f_hi < 0) {
      lo = hi, f_lo = f_hi;
      continue;
    }
    // Regula falsi, Illinois variant: when the same end survives twice in a row its value is
    // halved for the interpolation, so both ends close in superlinearly (plain regula falsi can
    // stall on one side); a few embeddings instead of the 50-odd of bisection. w_lo and w_hi are
    // those weighted values, f_hi the true one.
    double w_lo = f_lo, w_hi = f_hi;
    int last = 0;  // which end moved last: -1 lo, +1 hi
    for (int k = 0; k < kMaxRefinements && f_hi > kRadiusTolerance * radius; ++k) {
      const double s = hi - w_hi * (hi - lo) / (w_hi - w_lo);
      if (!(s > lo && s < hi)) break;  // the segment cannot shrink any further
      const double d_s = distance(s), f_s = d_s - radius;
      if (f_s < 0) {
        lo = s, w_lo = f_s;
        if (last == -1) w_hi *= 0.5;
        last = -1;
      } else {
        hi = s, d_hi = d_s, f_hi = w_hi = f_s;
        if (last == 1) w_lo *= 0.5;
        last = 1;
      }
    }
    return {path.material(hi), d_hi, true, hi};
  }
  const double end = path.breaks.back();
  return {path.material(end), distance(end), false, end};
}

Hit refine_exactly(const Path& path, const Hit& hit, double radius, double start_exact,
                   const ExactSteps& steps) {
  const double end = path.breaks.back();
  const auto off = [&](double d) { return std::abs(d / radius - 1); };
  // The exact distance along the path is about linear in small steps but can turn sharply (a
  // Lafortune lobe across cz = 1/sqrt(3)): secant steps until the sphere is bracketed, then
  // regula falsi (Illinois) inside the bracket, which a sharp turn slows but cannot escape.
  double lo = 0, f_lo = start_exact - radius;  // inside the sphere
  double hi = -1, f_hi = 0;                    // outside, once found
  double prev = 0, f_prev = f_lo;              // the point before the last, for the secant
  double s = hit.s;
  Hit best = hit;             // replaced by the first render's answer
  std::optional<Hit> at_end;  // the path's end, once rendered
  int last = 0;               // which end of the bracket moved last: -1 lo, +1 hi
  for (int k = 0; k < steps.renders; ++k) {
    const Material m = path.material(s);
    const double d = steps.distance(m), f = d - radius;
    if (k == 0 || off(d) < off(best.distance)) best = {m, d, d >= radius || s < end, s};
    if (!(s < end)) at_end = Hit{m, d, d >= radius, s};
    if (off(d) <= steps.tolerance) break;
    if (f < 0) {
      if (hi >= 0 && last == -1) f_hi *= 0.5;
      prev = lo, f_prev = f_lo, lo = s, f_lo = f, last = -1;
      if (hi < 0 && !(s < end)) break;  // the path's end is inside the sphere
    } else {
      if (hi >= 0 && last == 1) f_lo *= 0.5;
      prev = hi >= 0 ? hi : lo, f_prev = hi >= 0 ? f_hi : f_lo, hi = s, f_hi = f, last = 1;
    }
    double next;
    if (hi >= 0) {
      next = hi - f_hi * (hi - lo) / (f_hi - f_lo);
      if (!(next > std::min(lo, hi) && next < std::max(lo, hi))) next = 0.5 * (lo + hi);
    } else {
      // Not yet outside: extrapolate the last two points, at most 4 times farther; the last
      // render goes to the end, so that an offer the budget leaves inside is the end, flagged.
      next = f != f_prev ? s + (0 - f) * (s - prev) / (f - f_prev) : 2 * s;
      // A distance that fell since the last render extrapolates backwards: go on toward the end
      // as on a flat stretch, so that the path's end is rendered before the budget runs out.
      if (!std::isfinite(next) || !(next > s)) next = 2 * s;
      next = std::clamp(next, s, std::min(end, std::max(4 * s, s + 1e-9)));
      if (k + 2 == steps.renders) next = end;
    }
    if (next == s) break;
    s = next;
  }
  // Never outside the sphere (the distance need not grow monotonically along the path): the
  // path's end, flagged as the embedding's walk flags it.
  if (hi < 0 && off(best.distance) > steps.tolerance && at_end) return *at_end;
  return best;
}

std::vector<Path> lobe_paths(const Material& m, const ParamGrid& grid, bool ward_isotropic) {
  std::vector<Path> paths;
  for (std::size_t d = 0; d < grid.dimensions(); ++d) {
    const std::string name(grid.specs()[d].name);
    paths.push_back(scale_path(m, grid, {d}, +1, name + "+"));
    paths.push_back(scale_path(m, grid, {d}, -1, name + "-"));
  }
  if (ward_isotropic && m.model == ModelId::ward) {
    paths.push_back(scale_path(m, grid, {0, 1}, +1, "alpha+"));
    paths.push_back(scale_path(m, grid, {0, 1}, -1, "alpha-"));
  }
  return paths;
}

}  // namespace brdfnav::nav
