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
    scaled_.emplace_back();
    for (double v : axes_[d]) scaled_.back().push_back(to_scale(specs_[d], v));
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
AxisWeights linear_weights(double c, std::span<const double> x,
                           std::size_t /*a cell is one side*/) {
  const std::size_t i = std::min(static_cast<std::size_t>(c), x.size() - 2);
  const double t = c - static_cast<double>(i);
  return {{i, 1 - t}, {i + 1, t}};
}

// The slope at node j of the axis's nodes x (in the parameter's scale) as weights of the node
// values, added into w[k] for node i - 1 + k: the slope at x_j of the parabola through three
// neighbouring nodes of [lo, hi], centred on j inside, the two beside it at an end; the secant
// when [lo, hi] has two nodes.
void add_slope(std::span<const double> x, std::size_t j, std::size_t lo, std::size_t hi,
               std::size_t i, double scale, double w[4]) {
  const auto add = [&](std::size_t node, double weight) { w[node + 1 - i] += scale * weight; };
  if (hi - lo == 1) {
    const double h = x[hi] - x[lo];
    add(lo, -1 / h), add(hi, 1 / h);
  } else if (j == lo) {
    const double h0 = x[j + 1] - x[j], h1 = x[j + 2] - x[j + 1];
    add(j, -(2 * h0 + h1) / (h0 * (h0 + h1)));
    add(j + 1, (h0 + h1) / (h0 * h1));
    add(j + 2, -h0 / (h1 * (h0 + h1)));
  } else if (j == hi) {
    const double h0 = x[j] - x[j - 1], h1 = x[j - 1] - x[j - 2];
    add(j, (2 * h0 + h1) / (h0 * (h0 + h1)));
    add(j - 1, -(h0 + h1) / (h0 * h1));
    add(j - 2, h0 / (h1 * (h0 + h1)));
  } else {
    const double a = x[j] - x[j - 1], b = x[j + 1] - x[j];
    add(j - 1, -b / (a * (a + b)));
    add(j, (b - a) / (a * b));
    add(j + 1, a / (b * (a + b)));
  }
}

// The cubic Hermite spline at grid coordinate c, in the parameter's scale, with each node's
// slope from the parabola through it and its neighbours (add_slope). On evenly spaced nodes this
// is Catmull-Rom; on graded ones (Lafortune's cz, He's eta) it follows the nodes' true spacing,
// where Catmull-Rom in grid coordinates put a kink at every node (0.04-0.05 eps in the blend along
// a graded eta axis, 0.001-0.007 with these slopes). At the ends, and either side of a kink node,
// the slope is the parabola's through the three nodes on that side: exact for quadratics there
// too (He's first eta cell: 0.27 eps with a linear end, 0.17 with this one).
AxisWeights cubic_weights(double c, std::span<const double> x, std::size_t kink) {
  const std::size_t n = x.size(), i = std::min(static_cast<std::size_t>(c), n - 2);
  const std::size_t lo = kink != ParamGrid::kNoKink && kink <= i ? kink : 0;
  const std::size_t hi = kink != ParamGrid::kNoKink && kink > i ? kink : n - 1;
  const double t = c - static_cast<double>(i), t2 = t * t, t3 = t2 * t, h = x[i + 1] - x[i];
  double w[4] = {0, 2 * t3 - 3 * t2 + 1, -2 * t3 + 3 * t2, 0};
  add_slope(x, i, lo, hi, i, (t3 - 2 * t2 + t) * h, w);
  add_slope(x, i + 1, lo, hi, i, (t3 - t2) * h, w);
  AxisWeights out;
  for (std::size_t k = 0; k < 4; ++k)
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
    for (const auto& [node, weight] : rule(grid_coordinate(d, values[d]), scaled_[d], kinks_[d])) {
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
