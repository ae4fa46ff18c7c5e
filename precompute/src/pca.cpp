#include <brdfnav/precompute/pca.h>

#include <brdfnav/core/parallel_for.h>

#include <Eigen/QR>
#include <Eigen/SVD>

#include <cblas.h>

#include <algorithm>
#include <random>

namespace brdfnav {

namespace {

using MatrixXf = Eigen::MatrixXf;

Eigen::Index idx(std::size_t i) {
  return static_cast<Eigen::Index>(i);
}

// Number of blocks of `size` that cover `n`.
std::size_t blocks(std::size_t n, std::size_t size) {
  return (n + size - 1) / size;
}

// c = op(a) b + beta c, through OpenBLAS's sgemm: the products below are most of the embedding's
// cost, and its kernels, chosen for the CPU at run time, ran 2.5 times as fast as Eigen's
// (built for the baseline x86-64) on this machine (docs/DATABASE.md). The threads are
// parallel_for's, each product inside one task: OpenBLAS runs each call on its caller's thread
// (its pthreads build, which allows concurrent calls, with its own thread count set to 1).
void gemm(bool transpose_a, const Eigen::Ref<const MatrixXf>& a,
          const Eigen::Ref<const MatrixXf>& b, float beta, Eigen::Ref<MatrixXf> c) {
  [[maybe_unused]] static const bool single_threaded = (openblas_set_num_threads(1), true);
  const auto m = static_cast<int>(c.rows()), n = static_cast<int>(c.cols());
  const auto k = static_cast<int>(b.rows());
  if (m == 0 || n == 0) return;
  // Leading dimensions of at least 1, as BLAS requires even where a matrix is empty.
  const auto ld = [](const auto& x) { return std::max(1, static_cast<int>(x.outerStride())); };
  cblas_sgemm(CblasColMajor, transpose_a ? CblasTrans : CblasNoTrans, CblasNoTrans, m, n, k, 1.f,
              a.data(), ld(a), b.data(), ld(b), beta, c.data(), ld(c));
}

// Orthonormal basis of the column space of `y` (thin QR).
MatrixXf orthonormalise(const MatrixXf& y) {
  Eigen::HouseholderQR<MatrixXf> qr(y);
  return qr.householderQ() * MatrixXf::Identity(y.rows(), y.cols());
}

// X * W, with W (cols x l) given. Each slab of rows is one task: it streams its part of X block
// by block of columns, always in the same blocks, and sums into its own rows of the result.
MatrixXf times_right(std::size_t rows, std::size_t cols, const BlockSource& source,
                     const PcaOptions& o, const MatrixXf& w) {
  MatrixXf y = MatrixXf::Zero(idx(rows), w.cols());
  parallel_for(blocks(rows, o.block_rows), worker_threads(o.threads), [&](std::size_t slab) {
    const std::size_t first_row = slab * o.block_rows;
    const std::size_t n = std::min(o.block_rows, rows - first_row);
    MatrixXf block;
    for (std::size_t first = 0; first < cols; first += o.block_columns) {
      block.resize(idx(n), idx(std::min(o.block_columns, cols - first)));
      source(first_row, first, block);
      gemm(false, block, w.middleRows(idx(first), block.cols()), 1.f,
           y.middleRows(idx(first_row), idx(n)));
    }
  });
  return y;
}

// Q^T X (l x cols). Each block of columns is one task, whole in the rows.
MatrixXf times_left(std::size_t rows, std::size_t cols, const BlockSource& source,
                    const PcaOptions& o, const MatrixXf& q) {
  MatrixXf z(q.cols(), idx(cols));
  parallel_for(blocks(cols, o.block_columns), worker_threads(o.threads), [&](std::size_t b) {
    const std::size_t first = b * o.block_columns;
    MatrixXf block(idx(rows), idx(std::min(o.block_columns, cols - first)));
    source(0, first, block);
    gemm(true, q, block, 0.f, z.middleCols(idx(first), block.cols()));
  });
  return z;
}

}  // namespace

PcaBasis uncentered_pca(std::size_t rows, std::size_t cols, const BlockSource& source,
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

  // B = Q^T X is small (l x cols): its SVD B = U S V^T gives the leading singular vectors Q U of
  // X, and X's coefficients in them, (Q U)^T X = U^T B, without another pass over X.
  const MatrixXf b = times_left(rows, cols, source, options, q);
  Eigen::BDCSVD<Eigen::MatrixXd> svd(b.cast<double>(), Eigen::ComputeThinU);
  const MatrixXf u = svd.matrixU().leftCols(k).cast<float>();
  PcaBasis basis;
  basis.vectors = q * u;
  basis.singular_values = svd.singularValues().head(k);
  basis.coefficients = u.transpose() * b;
  return basis;
}

}  // namespace brdfnav
