// A model's parameter grid (the cartesian product of its parameters' grid nodes) and multilinear
// or cubic interpolation over it in each parameter's own scale (log or linear, as the table says).
#pragma once

#include <brdfnav/core/params.h>

#include <cstddef>
#include <span>
#include <vector>

namespace brdfnav {

class ParamGrid {
 public:
  // The table's own grid (Table 1 of the paper).
  explicit ParamGrid(std::span<const ParamSpec> specs);
  // Other increasing nodes per parameter (a coarser or denser precompute profile).
  ParamGrid(std::span<const ParamSpec> specs, std::vector<std::vector<double>> axes);

  std::size_t dimensions() const { return axes_.size(); }
  std::size_t node_count() const { return node_count_; }
  const std::vector<double>& axis(std::size_t d) const { return axes_[d]; }
  std::span<const ParamSpec> specs() const { return specs_; }

  // Node index of a multi-index (first parameter fastest) and back.
  std::size_t node_index(std::span<const std::size_t> multi) const;
  std::vector<std::size_t> multi_index(std::size_t node) const;
  // Parameter values at a node, in table order.
  std::vector<double> node_values(std::size_t node) const;

  // Continuous grid coordinate of `value` on axis d: i + t means t of the way from node i to
  // node i + 1 in the parameter's scale; values outside the grid are clamped to its ends.
  double grid_coordinate(std::size_t d, double value) const;
  // The inverse of grid_coordinate for coordinates in [0, size - 1].
  double value_at(std::size_t d, double coordinate) const;

  // Cells: the boxes between neighbouring nodes, (size - 1) per axis, numbered like the nodes
  // (first parameter fastest). The cell holding `values` (clamped into the grid; a value on a
  // node belongs to the cell above it, the last node to the cell below), and the parameter
  // values at a cell's centre in grid coordinates, where interpolation is farthest from nodes.
  std::size_t cell_count() const;
  std::size_t cell_index(std::span<const double> values) const;
  std::vector<double> cell_midpoint(std::size_t cell) const;

  struct Corner {
    std::size_t node;
    double weight;
  };
  // The up to 2^d nodes and weights (summing to 1) that multilinearly interpolate at `values`;
  // corners with zero weight are left out.
  std::vector<Corner> corners(std::span<const double> values) const;
  // The up to 4^d nodes and weights (summing to 1, some negative) of the tensor-product cubic
  // spline in each parameter's scale: smooth across nodes, where multilinear interpolation kinks,
  // and exact for functions quadratic in the scaled parameter, ends included. Its slopes follow
  // the nodes' spacing, so a graded axis interpolates as smoothly as an even one (on evenly spaced
  // nodes it is Catmull-Rom). What the embedding and the thumbnails' blend use between nodes.
  // Across a node on a parameter's kink (ParamSpec::kink) it is only continuous, as the images
  // are: each side is interpolated as if the axis ended there.
  std::vector<Corner> cubic_corners(std::span<const double> values) const;

  // The node of axis d on its parameter's kink, or kNoKink.
  static constexpr std::size_t kNoKink = static_cast<std::size_t>(-1);
  std::size_t kink_node(std::size_t d) const { return kinks_[d]; }

 private:
  template <typename AxisRule>
  std::vector<Corner> tensor_corners(std::span<const double> values, AxisRule rule) const;

  std::span<const ParamSpec> specs_;
  std::vector<std::vector<double>> axes_;
  std::vector<std::size_t> strides_;
  std::vector<std::size_t> kinks_;           // per axis: kink_node()
  std::vector<std::vector<double>> scaled_;  // per axis: its nodes in the parameter's scale
  std::size_t node_count_ = 1;
};

}  // namespace brdfnav
