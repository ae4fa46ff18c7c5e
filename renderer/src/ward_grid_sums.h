// The arithmetic of WardGridQuadrature (ward_grid.h) over a chunk of nodes: each node's Gaussian
// factors along one slope axis, and their products summed into the grid of lobes. With AVX2 and
// FMA (checked at run time) eight factors or four products at a time; otherwise one at a time in
// double precision. The same inputs on the same CPU give the same bits.
#pragma once

#include <cstddef>

namespace brdfnav::ward_grid {

// Rows of factors are padded to a multiple of this many.
inline constexpr int kRowMultiple = 8;
inline int padded(int m) {
  return (m + kRowMultiple - 1) / kRowMultiple * kRowMultiple;
}

// exp(-(s / alpha)^2) averaged over a node's slopes, taken as Gaussian with the node's variance
// v: exp(-s^2 / (alpha^2 + 2 v)) alpha / sqrt(alpha^2 + 2 v), which keeps its integral.
struct Factors {
  const double *slopes, *variances;  // per node
  const float* inv_alpha2;           // 1 / alpha^2 of each alpha, increasing alphas, padded
  int nodes, alphas;
  double* out;      // node-major, rows of padded(alphas): the factors (padding: anything finite)
  double* scratch;  // as large as out
  int* first;       // per node, its first alpha whose factor is not negligible
};
void gaussian_factors(const Factors& f);

// sums[(c nx + i) padded(ny) + j] += weight[c][k] gx[k][i] gy[k][j] over the nodes k, for every
// i >= first_x[k] and j >= first_y[k] (and perhaps a few j below, where gy is negligible).
struct Products {
  const double *gx, *gy;  // as Factors::out
  const double* const* weight;
  const int *first_x, *first_y;
  int nodes, nx, ny;
  double* sums;
};
void accumulate(const Products& p);

}  // namespace brdfnav::ward_grid
