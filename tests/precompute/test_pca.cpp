#include <brdfnav/precompute/pca.h>

#include <gtest/gtest.h>
#include <Eigen/SVD>

#include <random>

namespace brdfnav {
namespace {

// A rows x cols matrix of exact rank `rank` plus a small full-rank perturbation.
Eigen::MatrixXf low_rank_matrix(int rows, int cols, int rank, float noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> g;
  Eigen::MatrixXf a(rows, rank), b(rank, cols), n(rows, cols);
  for (int i = 0; i < a.size(); ++i) a.data()[i] = g(rng);
  for (int i = 0; i < b.size(); ++i) b.data()[i] = g(rng) / float(1 + i % rank);
  for (int i = 0; i < n.size(); ++i) n.data()[i] = noise * g(rng);
  return a * b + n;
}

BlockSource source_of(const Eigen::MatrixXf& m) {
  return [&m](std::size_t first_row, std::size_t first_col, Eigen::Ref<Eigen::MatrixXf> block) {
    block = m.block(static_cast<Eigen::Index>(first_row), static_cast<Eigen::Index>(first_col),
                    block.rows(), block.cols());
  };
}

TEST(Pca, MatchesTheExactSingularValues) {
  const Eigen::MatrixXf m = low_rank_matrix(400, 300, 25, 1e-3f, 1);
  PcaOptions o;
  o.components = 25;
  o.block_columns = 64;  // several blocks, one partial
  const PcaBasis basis = uncentered_pca(400, 300, source_of(m), o);
  const Eigen::JacobiSVD<Eigen::MatrixXd> exact(m.cast<double>());
  ASSERT_EQ(basis.singular_values.size(), 25);
  for (int i = 0; i < 25; ++i)
    EXPECT_NEAR(basis.singular_values[i], exact.singularValues()[i],
                1e-3 * exact.singularValues()[0]);
  const Eigen::MatrixXf gram = basis.vectors.transpose() * basis.vectors;
  EXPECT_TRUE(gram.isApprox(Eigen::MatrixXf::Identity(25, 25), 1e-4f));
}

// What the embedding is for: distances between columns survive the projection.
TEST(Pca, PreservesDistancesBetweenColumns) {
  const Eigen::MatrixXf m = low_rank_matrix(300, 200, 12, 1e-4f, 2);
  PcaOptions o;
  o.components = 12;
  const PcaBasis basis = uncentered_pca(300, 200, source_of(m), o);
  const Eigen::MatrixXf& coeffs = basis.coefficients;
  ASSERT_EQ(coeffs.cols(), 200);
  EXPECT_TRUE(coeffs.isApprox(basis.vectors.transpose() * m, 1e-4f));
  for (int a = 0; a < 200; a += 17)
    for (int b = a + 1; b < 200; b += 23) {
      const float exact = (m.col(a) - m.col(b)).norm();
      const float embedded = (coeffs.col(a) - coeffs.col(b)).norm();
      EXPECT_NEAR(embedded, exact, 1e-3f * exact + 1e-4f);
    }
}

TEST(Pca, IsDeterministicForASeed) {
  const Eigen::MatrixXf m = low_rank_matrix(120, 90, 10, 1e-2f, 3);
  PcaOptions o;
  o.components = 8;
  const PcaBasis a = uncentered_pca(120, 90, source_of(m), o);
  const PcaBasis b = uncentered_pca(120, 90, source_of(m), o);
  EXPECT_EQ(a.vectors, b.vectors);
}

// Blocks of rows and columns of a fixed size, whatever the threads: the same basis to the bit.
TEST(Pca, DoesNotDependOnTheThreadCount) {
  const Eigen::MatrixXf m = low_rank_matrix(700, 500, 30, 1e-2f, 5);
  PcaOptions o;
  o.components = 20;
  o.block_rows = 128;  // several slabs of rows, one partial
  o.block_columns = 96;
  o.threads = 1;
  const PcaBasis one = uncentered_pca(700, 500, source_of(m), o);
  o.threads = 3;
  const PcaBasis three = uncentered_pca(700, 500, source_of(m), o);
  EXPECT_EQ(one.vectors, three.vectors);
  EXPECT_EQ(one.coefficients, three.coefficients);
}

TEST(Pca, ClampsTheComponentCountToTheMatrix) {
  const Eigen::MatrixXf m = low_rank_matrix(50, 20, 5, 0.1f, 4);
  const PcaBasis basis = uncentered_pca(50, 20, source_of(m));  // asks for 200
  EXPECT_EQ(basis.vectors.cols(), 20);
}

}  // namespace
}  // namespace brdfnav
