#include <brdfnav/core/grid.h>

#include <algorithm>
#include <cmath>

namespace brdfnav {

namespace {
std::vector<std::vector<double>> table_axes(std::span<const ParamSpec> specs) {
  std::vector<std::vector<double>> axes;
  for (const ParamSpec& p : specs) axes.push_back(grid_nodes(p));
  return axes;
}
}  // namespace

ParamGrid::ParamGrid(std::span<const ParamSpec> specs) : ParamGrid(specs, table_axes(specs)) {}

ParamGrid::ParamGrid(std::span<const ParamSpec> specs, std::vector<std::vector<double>> axes)
    : specs_(specs), axes_(std::move(axes)) {
  for (const std::vector<double>& axis : axes_) {
    strides_.push_back(node_count_);
    node_count_ *= axis.size();
  }
}

std::size_t ParamGrid::node_index(std::span<const std::size_t> multi) const {
  std::size_t node = 0;
  for (std::size_t d = 0; d < axes_.size(); ++d) node += multi[d] * strides_[d];
  return node;
}

std::vector<std::size_t> ParamGrid::multi_index(std::size_t node) const {
  std::vector<std::size_t> multi(axes_.size());
  for (std::size_t d = 0; d < axes_.size(); ++d) multi[d] = node / strides_[d] % axes_[d].size();
  return multi;
}

std::vector<double> ParamGrid::node_values(std::size_t node) const {
  const auto multi = multi_index(node);
  std::vector<double> values(axes_.size());
  for (std::size_t d = 0; d < axes_.size(); ++d) values[d] = axes_[d][multi[d]];
  return values;
}

double ParamGrid::grid_coordinate(std::size_t d, double value) const {
  const std::vector<double>& nodes = axes_[d];
  if (value <= nodes.front()) return 0.0;
  if (value >= nodes.back()) return static_cast<double>(nodes.size() - 1);
  const std::size_t i = std::upper_bound(nodes.begin(), nodes.end(), value) - nodes.begin() - 1;
  const ParamSpec& spec = specs_[d];
  const double lo = to_scale(spec, nodes[i]), hi = to_scale(spec, nodes[i + 1]);
  return static_cast<double>(i) + (to_scale(spec, value) - lo) / (hi - lo);
}

double ParamGrid::value_at(std::size_t d, double coordinate) const {
  const std::vector<double>& nodes = axes_[d];
  const double c = std::clamp(coordinate, 0.0, static_cast<double>(nodes.size() - 1));
  const std::size_t i = std::min(static_cast<std::size_t>(c), nodes.size() - 2);
  const ParamSpec& spec = specs_[d];
  const double lo = to_scale(spec, nodes[i]), hi = to_scale(spec, nodes[i + 1]);
  return from_scale(spec, lo + (c - static_cast<double>(i)) * (hi - lo));
}

std::vector<ParamGrid::Corner> ParamGrid::corners(std::span<const double> values) const {
  std::vector<Corner> out{{0, 1.0}};
  for (std::size_t d = 0; d < axes_.size(); ++d) {
    const double c = grid_coordinate(d, values[d]);
    const std::size_t i = std::min(static_cast<std::size_t>(c), axes_[d].size() - 2);
    const double t = c - static_cast<double>(i);
    std::vector<Corner> next;
    for (const Corner& k : out) {
      if (t < 1) next.push_back({k.node + i * strides_[d], k.weight * (1 - t)});
      if (t > 0) next.push_back({k.node + (i + 1) * strides_[d], k.weight * t});
    }
    out = std::move(next);
  }
  return out;
}

}  // namespace brdfnav
