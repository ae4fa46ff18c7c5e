#include <brdfnav/core/params.h>

#include <cmath>

namespace brdfnav {

double to_scale(const ParamSpec& spec, double value) {
  return spec.scale == Scale::log ? std::log(value) : value;
}

double from_scale(const ParamSpec& spec, double scaled) {
  return spec.scale == Scale::log ? std::exp(scaled) : scaled;
}

std::vector<double> grid_nodes(const ParamSpec& spec) {
  if (!spec.nodes.empty()) return {spec.nodes.begin(), spec.nodes.end()};
  std::vector<double> nodes(spec.grid_count);
  const double lo = to_scale(spec, spec.grid_min), hi = to_scale(spec, spec.grid_max);
  for (int i = 0; i < spec.grid_count; ++i) {
    const double t = spec.grid_count == 1 ? 0.0 : double(i) / (spec.grid_count - 1);
    nodes[i] = from_scale(spec, lo + t * (hi - lo));
  }
  // Pin the ends exactly: exp(log(x)) need not return x.
  nodes.front() = spec.grid_min;
  nodes.back() = spec.grid_max;
  return nodes;
}

bool in_valid_range(const ParamSpec& spec, double value) {
  return std::isfinite(value) && value >= spec.valid_min && value <= spec.valid_max;
}

}  // namespace brdfnav
