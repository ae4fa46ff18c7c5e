// The embedding's matrix products (precompute/src/pca.cpp) on their block shapes at the default
// profile's size, through Eigen and through OpenBLAS's sgemm, one thread each: the ratio behind
// pca.cpp's use of OpenBLAS. Then the whole uncentered PCA on a synthetic matrix of that height.
// No target of its own; figures in docs/DATABASE.md, Build time and memory.
#include <benchmark/benchmark.h>
#include <brdfnav/precompute/pca.h>
#include <cblas.h>

#include <cmath>

namespace brdfnav {
namespace {

using MatrixXf = Eigen::MatrixXf;

// The default profile: 128 x 128 sphere images (12,868 covered pixels), blocks of pca.h's
// PcaOptions, 200 components + 16 oversampled.
constexpr int kPixels = 12868, kBlockRows = 2048, kBlockColumns = 256, kVectors = 216;

// The product's label and its rate, for the report.
void report(benchmark::State& state, bool blas, double flops) {
  state.SetLabel(blas ? "OpenBLAS sgemm" : "Eigen");
  state.counters["GFLOP/s"] =
      benchmark::Counter(flops, benchmark::Counter::kIsIterationInvariantRate);
}

// One thread for OpenBLAS too, as pca.cpp runs it (its pthreads build would use every core).
const bool kOneBlasThread = (openblas_set_num_threads(1), true);

// Y += X W, one slab of rows (times_right() in pca.cpp).
void BM_ProductRight(benchmark::State& state) {
  const bool blas = state.range(0) != 0;
  const MatrixXf x = MatrixXf::Random(kBlockRows, kBlockColumns);
  const MatrixXf w = MatrixXf::Random(kBlockColumns, kVectors);
  MatrixXf y = MatrixXf::Zero(kBlockRows, kVectors);
  for (auto _ : state) {
    if (blas)
      cblas_sgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, kBlockRows, kVectors, kBlockColumns,
                  1.f, x.data(), kBlockRows, w.data(), kBlockColumns, 1.f, y.data(), kBlockRows);
    else
      y.noalias() += x * w;
    benchmark::DoNotOptimize(y.data());
  }
  report(state, blas, 2.0 * kBlockRows * kBlockColumns * kVectors);
}
BENCHMARK(BM_ProductRight)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Z = Q^T X, one block of columns whole in the rows (times_left() in pca.cpp).
void BM_ProductLeft(benchmark::State& state) {
  const bool blas = state.range(0) != 0;
  const MatrixXf q = MatrixXf::Random(kPixels, kVectors);
  const MatrixXf x = MatrixXf::Random(kPixels, kBlockColumns);
  MatrixXf z(kVectors, kBlockColumns);
  for (auto _ : state) {
    if (blas)
      cblas_sgemm(CblasColMajor, CblasTrans, CblasNoTrans, kVectors, kBlockColumns, kPixels, 1.f,
                  q.data(), kPixels, x.data(), kPixels, 0.f, z.data(), kVectors);
    else
      z.noalias() = q.transpose() * x;
    benchmark::DoNotOptimize(z.data());
  }
  report(state, blas, 2.0 * kPixels * kBlockColumns * kVectors);
}
BENCHMARK(BM_ProductLeft)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// uncentered_pca() on one thread over a 12,868 x 4,096 matrix of smooth entries computed on
// demand, as the embedding's cube roots are.
void BM_UncenteredPca(benchmark::State& state) {
  constexpr std::size_t kColumns = 4096;
  const BlockSource source = [](std::size_t row0, std::size_t col0,
                                Eigen::Ref<Eigen::MatrixXf> block) {
    for (Eigen::Index j = 0; j < block.cols(); ++j)
      for (Eigen::Index i = 0; i < block.rows(); ++i)
        block(i, j) = std::cbrt(1.0f + std::sin(0.001f * float(row0 + i) * float(col0 + j % 7)));
  };
  PcaOptions options;
  options.threads = 1;
  for (auto _ : state) {
    const PcaBasis basis = uncentered_pca(kPixels, kColumns, source, options);
    benchmark::DoNotOptimize(basis.vectors.data());
  }
}
BENCHMARK(BM_UncenteredPca)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace brdfnav
