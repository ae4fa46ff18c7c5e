// Uncentered PCA (paper, section 3.2) of a matrix too large to hold: its columns (cube-root
// images, one channel each, masked pixels only) are produced block by block on demand. Not
// centring keeps the embedding linear: a scaled image has scaled coefficients, which is what
// lets rho_s^(1/3) factor out of the cube root.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <functional>

namespace brdfnav {

// Fills `block` (rows x block.cols()) with columns first, first + 1, ... of the matrix.
using ColumnBlockSource = std::function<void(std::size_t first, Eigen::Ref<Eigen::MatrixXf> block)>;

struct PcaOptions {
  int components = 200;
  int oversample = 16;       // extra random directions, for the randomised range finder
  int power_iterations = 2;  // sharpen the spectrum: accuracy of the trailing components
  std::size_t block_columns = 256;
  std::uint64_t seed = 1;  // the basis is deterministic for a given seed
};

struct PcaBasis {
  Eigen::MatrixXf vectors;          // rows x k, orthonormal columns, by decreasing singular value
  Eigen::VectorXd singular_values;  // k
};

// Randomised SVD (Halko, Martinsson & Tropp 2011, algorithms 4.4 and 5.1) of the rows x cols
// matrix, without centring. k = min(components, rows, cols).
PcaBasis uncentered_pca(std::size_t rows, std::size_t cols, const ColumnBlockSource& source,
                        const PcaOptions& options = {});

}  // namespace brdfnav
