#include "walk.h"

#include <algorithm>
#include <limits>

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
    return {path.material(hi), d_hi, true};
  }
  const double end = path.breaks.back();
  return {path.material(end), distance(end), false};
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
