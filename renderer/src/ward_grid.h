// Ward lobes on a grid of (alpha_x, alpha_y), integrated together at each pixel (docs/RENDERER.md,
// "Ward's grid in one pass").
//
// In the half vector's slopes (sx, sy) = (h.x / h.z, h.y / h.z), h = wi + wo, the Ward lobe times
// the cosine is
//   K(wi) = exp(-(sx / alpha_x)^2) exp(-(sy / alpha_y)^2) sqrt(cos_i) / (4 pi alpha_x alpha_y
//           sqrt(cos_o)),
// a factor of sx alone, one of sy alone and one of wi alone. So for every pair of the grid the sum
// over the environment's nodes of power * K is one product of per-node factors,
//   sum_n power_n sqrt(cos_i,n) gx_n(alpha_x[i]) gy_n(alpha_y[j]),
// over one set of nodes per pixel fine enough for every lobe of the grid where that lobe reaches:
// a node is cut until its extent in slopes is at most 2.5 / texels_per_width of the slope deviation
// (alpha / sqrt(2)) of the narrowest lobe of the grid whose window (`reach` deviations) holds it.
// Near the lobes' peak that is the narrowest alpha; far out along one slope axis, only the alphas
// wide enough to reach there: the nodes grow with their distance from the peak. Each node's
// factors are the Gaussians averaged over its slopes, taken as Gaussian too, with the variances
// that the luminance-weighted spread of the node's directions (EnvPyramid::spread) gives them:
// exact to second order in the node's size, and keeping each node's integral, which lets the nodes
// be 2.5 times as wide as the per-lobe quadrature's (quadrature.h). The hot texels (lamps) are cut
// by the same rule with hot_texels_per_width within twice the window, and kept whole out to four
// times it.
//
// Nothing is random and the order of every sum is fixed: deterministic for the same inputs. The
// nodes depend on the smallest and largest alpha of each axis, so an image depends on the grid it
// is rendered with, within the accuracy of either.
#pragma once

#include "env_pyramid.h"

#include <brdfnav/renderer/render.h>

#include <array>
#include <functional>
#include <span>
#include <vector>

namespace brdfnav {

// Per-thread scratch space, reused from pixel to pixel.
struct WardGridScratch {
  std::vector<double> sx, sy;                 // per node: the half vector's slopes
  std::vector<double> vx, vy;                 // ... and their variances over the node
  std::array<std::vector<double>, 3> weight;  // per node and channel: power * sqrt(cos_i)
  std::vector<double> gx, gy;                 // a chunk of nodes' Gaussian factors
  std::vector<double> scratch;                // ... while they are computed
  std::vector<int> first;                     // ... and their first that is not negligible
  std::vector<double> sums;                   // 3 nx x padded(ny) (ward_grid_sums.h)
};

class WardGridQuadrature {
 public:
  // Each alpha list not empty, positive, finite and not decreasing (std::invalid_argument).
  WardGridQuadrature(const EnvPyramid& env, std::span<const double> alpha_x,
                     std::span<const double> alpha_y, const RenderQuality& quality);

  std::size_t nx() const { return alpha_x_.size(); }
  std::size_t ny() const { return alpha_y_.size(); }

  // The lobes with rho_s = 1 times cos(theta_i) integrated over the environment at one pixel:
  // out[3 (i ny + j) + c] for alpha_x[i], alpha_y[j] and channel c. `frame` is the pixel's
  // shading frame (local to world), wo the view direction in it; `visible` (may be empty) tells
  // whether the environment is seen in a world direction.
  void integrate(const Frame& frame, const Vec3& wo,
                 const std::function<bool(const Vec3&)>& visible, WardGridScratch& scratch,
                 double* out) const;

 private:
  class Pixel;

  const EnvPyramid& env_;
  std::vector<double> alpha_x_, alpha_y_;
  std::vector<float> inv_alpha2_x_, inv_alpha2_y_;  // 1 / alpha^2, padded (ward_grid_sums.h)
  double min_x_, max_x_, min_y_, max_y_, inv_max_x_, inv_max_y_;
  double node_steps_;  // nodes (and pieces of texels) per alpha
  double hot_steps_;   // ... for the pieces of the hot texels
  double reach2_;      // (reach / sqrt(2))^2: the window, in (slope / alpha)^2
  int max_split_;
  int top_level_;  // the coarsest level whose nodes are at most max_node
  // (sin, cos) of the polar angle of each row of corners of the level-0 texels, and of the
  // azimuth of each column of them.
  std::vector<Vec2> corner_rows_, corner_columns_;
};

}  // namespace brdfnav
