#include <brdfnav/precompute/pca.h>

#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <random>

namespace brdfnav {

namespace {

using MatrixXf = Eigen::MatrixXf;

// Calls `f(first, block)` for consecutive blocks of columns of the source matrix.
template <typename F>
void for_each_block(std::size_t rows, std::size_t cols, const ColumnBlockSource& source,
                    std::size_t block_columns, F&& f) {
  MatrixXf block;
  for (std::size_t first = 0; first < cols; first += block_columns) {
    const std::size_t n = std::min(block_columns, cols - first);
    block.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(n));
    source(first, block);
    f(first, block);
  }
}

// Orthonormal basis of the column space of `y` (thin QR).
MatrixXf orthonormalise(const MatrixXf& y) {
  Eigen::HouseholderQR<MatrixXf> qr(y);
  return qr.householderQ() * MatrixXf::Identity(y.rows(), y.cols());
}

// X * W, with W (cols x l) given; X streamed by blocks.
MatrixXf times_right(std::size_t rows, std::size_t cols, const ColumnBlockSource& source,
                     const PcaOptions& o, const MatrixXf& w) {
  MatrixXf y = MatrixXf::Zero(static_cast<Eigen::Index>(rows), w.cols());
  for_each_block(rows, cols, source, o.block_columns, [&](std::size_t first, const MatrixXf& b) {
    y.noalias() += b * w.middleRows(static_cast<Eigen::Index>(first), b.cols());
  });
  return y;
}

// Q^T X (l x cols); X streamed by blocks.
MatrixXf times_left(std::size_t rows, std::size_t cols, const ColumnBlockSource& source,
                    const PcaOptions& o, const MatrixXf& q) {
  MatrixXf z(q.cols(), static_cast<Eigen::Index>(cols));
  for_each_block(rows, cols, source, o.block_columns, [&](std::size_t first, const MatrixXf& b) {
    z.middleCols(static_cast<Eigen::Index>(first), b.cols()).noalias() = q.transpose() * b;
  });
  return z;
}

}  // namespace

PcaBasis uncentered_pca(std::size_t rows, std::size_t cols, const ColumnBlockSource& source,
                        const PcaOptions& options) {
  const auto k = static_cast<Eigen::Index>(
      std::min<std::size_t>({static_cast<std::size_t>(options.components), rows, cols}));
  const auto l = static_cast<Eigen::Index>(
      std::min<std::size_t>({static_cast<std::size_t>(k + options.oversample), rows, cols}));

  // Range finder: Y = X Omega with a seeded Gaussian Omega, then power iterations
  // (Y = X X^T Q), re-orthonormalised at each step for numerical stability.
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<float> gauss;
  MatrixXf omega(static_cast<Eigen::Index>(cols), l);
  for (Eigen::Index j = 0; j < l; ++j)
    for (Eigen::Index i = 0; i < omega.rows(); ++i) omega(i, j) = gauss(rng);
  MatrixXf q = orthonormalise(times_right(rows, cols, source, options, omega));
  for (int it = 0; it < options.power_iterations; ++it) {
    const MatrixXf z = orthonormalise(times_left(rows, cols, source, options, q).transpose());
    q = orthonormalise(times_right(rows, cols, source, options, z));
  }

  // B = Q^T X is small (l x cols): its SVD gives the leading singular vectors of X.
  const MatrixXf b = times_left(rows, cols, source, options, q);
  Eigen::BDCSVD<Eigen::MatrixXd> svd(b.cast<double>(), Eigen::ComputeThinU);
  PcaBasis basis;
  basis.vectors = q * svd.matrixU().leftCols(k).cast<float>();
  basis.singular_values = svd.singularValues().head(k);
  return basis;
}

}  // namespace brdfnav
