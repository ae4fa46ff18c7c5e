#include <brdfnav/core/grid.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace brdfnav {

namespace {
std::vector<std::vector<double>> table_axes(std::span<const ParamSpec> specs) {
  std::vector<std::vector<double>> axes;
  for (const ParamSpec& p : specs) axes.push_back(grid_nodes(p));
  return axes;
}
}  // namespace

ParamGrid::ParamGrid(std::span<const ParamSpec> specs) : ParamGrid(specs, table_axes(specs)) {}

namespace {
// The node of `axis` on the spec's kink, if any: within 1e-6 of it, so that the table's own
// five-digit 0.57735 counts as Lafortune's 1/sqrt(3).
std::size_t node_on_kink(const ParamSpec& spec, const std::vector<double>& axis) {
  for (std::size_t i = 0; i < axis.size(); ++i)
    if (std::abs(axis[i] - spec.kink) <= 1e-6) return i;  // false for a NaN kink
  return ParamGrid::kNoKink;
}
}  // namespace

ParamGrid::ParamGrid(std::span<const ParamSpec> specs, std::vector<std::vector<double>> axes)
    : specs_(specs), axes_(std::move(axes)) {
  for (std::size_t d = 0; d < axes_.size(); ++d) {
    strides_.push_back(node_count_);
    node_count_ *= axes_[d].size();
    kinks_.push_back(node_on_kink(specs_[d], axes_[d]));
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

std::size_t ParamGrid::cell_count() const {
  std::size_t n = 1;
  for (const std::vector<double>& axis : axes_) n *= axis.size() - 1;
  return n;
}

std::size_t ParamGrid::cell_index(std::span<const double> values) const {
  std::size_t cell = 0, stride = 1;
  for (std::size_t d = 0; d < axes_.size(); ++d) {
    const std::size_t cells = axes_[d].size() - 1;
    cell += std::min(static_cast<std::size_t>(grid_coordinate(d, values[d])), cells - 1) * stride;
    stride *= cells;
  }
  return cell;
}

std::vector<double> ParamGrid::cell_midpoint(std::size_t cell) const {
  std::vector<double> values(axes_.size());
  for (std::size_t d = 0; d < axes_.size(); ++d) {
    const std::size_t cells = axes_[d].size() - 1;
    values[d] = value_at(d, static_cast<double>(cell % cells) + 0.5);
    cell /= cells;
  }
  return values;
}

namespace {
using AxisWeights = std::vector<std::pair<std::size_t, double>>;  // (node on the axis, weight)

// Linear interpolation at grid coordinate c of an axis of n nodes.
AxisWeights linear_weights(double c, std::size_t n, std::size_t /*kink: a cell is one side*/) {
  const std::size_t i = std::min(static_cast<std::size_t>(c), n - 2);
  const double t = c - static_cast<double>(i);
  return {{i, 1 - t}, {i + 1, t}};
}

// Catmull-Rom at grid coordinate c of an axis of n nodes: the cubic through nodes i - 1 .. i + 2
// with central-difference slopes. Beyond the ends the missing node is the linear extrapolation
// of the last two (2 p_0 - p_1), so a two-node axis interpolates linearly. A kink node is an end
// for the cells on either side of it: neither reaches across.
AxisWeights cubic_weights(double c, std::size_t n, std::size_t kink) {
  const std::size_t i = std::min(static_cast<std::size_t>(c), n - 2);
  const double t = c - static_cast<double>(i), t2 = t * t, t3 = t2 * t;
  double w[4] = {0.5 * (-t3 + 2 * t2 - t), 0.5 * (3 * t3 - 5 * t2 + 2),
                 0.5 * (-3 * t3 + 4 * t2 + t), 0.5 * (t3 - t2)};
  if (i == 0 || i == kink) w[1] += 2 * w[0], w[2] -= w[0], w[0] = 0;
  if (i + 2 == n || i + 1 == kink) w[2] += 2 * w[3], w[1] -= w[3], w[3] = 0;
  AxisWeights out;
  for (int k = 0; k < 4; ++k)
    if (w[k] != 0) out.push_back({i + k - 1, w[k]});  // i + k - 1 >= 0 whenever w[k] != 0
  return out;
}
}  // namespace

template <typename AxisRule>
std::vector<ParamGrid::Corner> ParamGrid::tensor_corners(std::span<const double> values,
                                                         AxisRule rule) const {
  std::vector<Corner> out{{0, 1.0}};
  for (std::size_t d = 0; d < axes_.size(); ++d) {
    std::vector<Corner> next;
    for (const auto& [node, weight] :
         rule(grid_coordinate(d, values[d]), axes_[d].size(), kinks_[d])) {
      if (weight == 0) continue;
      for (const Corner& k : out) next.push_back({k.node + node * strides_[d], k.weight * weight});
    }
    out = std::move(next);
  }
  return out;
}

std::vector<ParamGrid::Corner> ParamGrid::corners(std::span<const double> values) const {
  return tensor_corners(values, linear_weights);
}

std::vector<ParamGrid::Corner> ParamGrid::cubic_corners(std::span<const double> values) const {
  return tensor_corners(values, cubic_weights);
}

}  // namespace brdfnav
