// Uncentered PCA (paper, section 3.2) of a matrix too large to hold: its entries (cube roots of
// images, one channel per column, masked pixels only) are produced block by block on demand. Not
// centring keeps the embedding linear: a scaled image has scaled coefficients, which is what
// lets rho_s^(1/3) factor out of the cube root.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <functional>

namespace brdfnav {

// Fills `block` with the block.rows() x block.cols() entries of the matrix from row `first_row`
// and column `first_col` on. Called from several threads at once.
using BlockSource = std::function<void(std::size_t first_row, std::size_t first_col,
                                       Eigen::Ref<Eigen::MatrixXf> block)>;

struct PcaOptions {
  int components = 200;
  int oversample = 16;       // extra random directions, for the randomised range finder
  int power_iterations = 2;  // sharpen the spectrum: accuracy of the trailing components
  std::size_t block_columns = 256;
  std::size_t block_rows = 2048;
  std::uint64_t seed = 1;  // the basis is deterministic for a given seed
  // Threads (0: one per hardware thread). Every product is split into blocks of a fixed size
  // whose sums never cross threads, so the result does not depend on the thread count.
  int threads = 0;
};

struct PcaBasis {
  Eigen::MatrixXf vectors;          // rows x k, orthonormal columns, by decreasing singular value
  Eigen::VectorXd singular_values;  // k
  Eigen::MatrixXf coefficients;     // k x cols: vectors^T times each column of the matrix
};

// Randomised SVD (Halko, Martinsson & Tropp 2011, algorithms 4.4 and 5.1) of the rows x cols
// matrix, without centring. k = min(components, rows, cols). The coefficients come from the last
// pass over the matrix, which the range finder needs anyway.
PcaBasis uncentered_pca(std::size_t rows, std::size_t cols, const BlockSource& source,
                        const PcaOptions& options = {});

}  // namespace brdfnav
