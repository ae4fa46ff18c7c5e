// Deterministic k-means over embedding vectors (paper, section 4): the models tab and the start
// gallery show one material per cluster.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace brdfnav::nav {

struct KMeansOptions {
  int k = 8;
  int threads = 1;            // workers for the assignment step; the result does not depend on it
  std::uint64_t seed = 2006;  // k-means++ seeding
  int max_iterations = 100;
};

// Clusters the columns of `points` (k-means++ seeding from a fixed-seed generator, then Lloyd
// iterations until no assignment changes) and returns, for each non-empty cluster, the column
// nearest its centroid (ties: the lower index), in increasing order. With k >= columns every
// column is its own cluster. The paper picks a random member per cluster; the nearest to the
// centroid is as representative and makes the answer a function of the inputs.
std::vector<std::size_t> kmeans_representatives(const Eigen::MatrixXf& points,
                                                const KMeansOptions& options);

}  // namespace brdfnav::nav
