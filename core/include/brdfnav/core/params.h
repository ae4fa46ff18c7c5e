// The typed parameter table: one row per non-linear parameter of a model. This table is the only
// place a parameter's name, unit, valid range, default and the paper's grid (Table 1) are written
// down; YAML, the inline spec, the C ABI, the CLI and docs/MODELS.md are all driven from it. The
// builder's other profiles choose their own grids (precompute/src/profile.cpp): the test and
// default profiles over these ranges (denser where a model needs it), the smoke profile from a
// few nodes written out per model.
#pragma once

#include <limits>
#include <span>
#include <string_view>
#include <vector>

namespace brdfnav {

// How a parameter is perceived and interpolated: grid nodes are evenly spaced in this scale
// (unless explicit nodes are given) and multilinear interpolation works in it.
enum class Scale { linear, log };

struct ParamSpec {
  std::string_view name;         // canonical name (YAML key, C ABI, CLI)
  std::string_view unit;         // "1" for dimensionless, "um" for micrometres
  std::string_view description;  // one line for --help and the docs
  double valid_min;              // inclusive range accepted on input
  double valid_max;
  double default_value;
  double grid_min;  // precompute grid (Table 1 of the paper); ignored when `nodes` is set
  double grid_max;
  int grid_count;
  Scale scale;
  std::span<const double> nodes = {};  // explicit, increasing grid nodes (overrides min/max/count)
  // What an increase and a decrease look like, in an artist's words ("rougher", "sharper"): the
  // navigator names its lobe variations with them.
  std::string_view more = {};
  std::string_view less = {};
  // A value where the model's images are continuous but not smooth, NaN where there is none:
  // Lafortune's normalisation max(|cxy|, cz)^n switches terms at cz = 1/sqrt(3), so the images'
  // slope along cz jumps there by about 2.6 n (in log scale). A spline through nodes on both
  // sides rounds that corner off, the error growing with n; a grid node on the kink lets
  // ParamGrid::cubic_corners() interpolate each side on its own.
  double kink = std::numeric_limits<double>::quiet_NaN();
};

// The grid nodes of one parameter, increasing.
std::vector<double> grid_nodes(const ParamSpec& spec);

// Value mapped into the parameter's interpolation scale (identity or natural log).
double to_scale(const ParamSpec& spec, double value);
double from_scale(const ParamSpec& spec, double scaled);

// True when value is finite and inside [valid_min, valid_max].
bool in_valid_range(const ParamSpec& spec, double value);

}  // namespace brdfnav
