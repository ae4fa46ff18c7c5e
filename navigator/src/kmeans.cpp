#include "kmeans.h"

#include <brdfnav/core/parallel_for.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>

namespace brdfnav::nav {

namespace {

// Uniform in [0, 1) from the top 53 bits: unlike std::uniform_real_distribution, the same
// numbers from every standard library.
double unit_random(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// Index of the centre nearest to point i (ties: the lower index) and its squared distance.
std::pair<int, double> nearest(const Eigen::MatrixXd& points, const Eigen::MatrixXd& centres,
                               Eigen::Index i) {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (Eigen::Index c = 0; c < centres.cols(); ++c) {
    const double d = (points.col(i) - centres.col(c)).squaredNorm();
    if (d < best_d) best = static_cast<int>(c), best_d = d;
  }
  return {best, best_d};
}

// k-means++ (Arthur & Vassilvitskii 2007): each next centre is a point drawn with probability
// proportional to its squared distance to the centres so far. Stops early when every point
// coincides with a centre (fewer distinct points than k).
Eigen::MatrixXd seed_centres(const Eigen::MatrixXd& points, int k, std::mt19937_64& rng) {
  const Eigen::Index n = points.cols();
  std::vector<Eigen::Index> chosen{
      static_cast<Eigen::Index>(rng() % static_cast<std::uint64_t>(n))};
  std::vector<double> d2(n, std::numeric_limits<double>::infinity());
  while (static_cast<int>(chosen.size()) < k) {
    for (Eigen::Index i = 0; i < n; ++i)
      d2[i] = std::min(d2[i], (points.col(i) - points.col(chosen.back())).squaredNorm());
    const double total = std::accumulate(d2.begin(), d2.end(), 0.0);
    if (!(total > 0)) break;
    const double target = unit_random(rng) * total;
    // The first point whose cumulative weight passes the target; the last point of positive
    // weight should rounding leave the target beyond the sum.
    double sum = 0;
    Eigen::Index pick = -1;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!(d2[i] > 0)) continue;
      pick = i;
      if ((sum += d2[i]) > target) break;
    }
    chosen.push_back(pick);
  }
  Eigen::MatrixXd centres(points.rows(), static_cast<Eigen::Index>(chosen.size()));
  for (std::size_t c = 0; c < chosen.size(); ++c) centres.col(c) = points.col(chosen[c]);
  return centres;
}

// Assigns every point to its nearest centre; points are split over threads in fixed ranges and
// each assignment depends only on its point, so the result is the same for any thread count.
void assign(const Eigen::MatrixXd& points, const Eigen::MatrixXd& centres, int threads,
            std::vector<int>& labels) {
  const Eigen::Index n = points.cols();
  const auto run = [&](Eigen::Index first, Eigen::Index last) {
    for (Eigen::Index i = first; i < last; ++i) labels[i] = nearest(points, centres, i).first;
  };
  const Eigen::Index workers = std::clamp<Eigen::Index>(threads, 1, n);
  parallel_for(std::size_t(workers), int(workers), [&](std::size_t w) {
    run(n * Eigen::Index(w) / workers, n * Eigen::Index(w + 1) / workers);
  });
}

// Centroids of the clusters, in point order; an empty cluster keeps its centre.
void update(const Eigen::MatrixXd& points, const std::vector<int>& labels,
            Eigen::MatrixXd& centres) {
  Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(centres.rows(), centres.cols());
  std::vector<int> counts(centres.cols(), 0);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    sums.col(labels[i]) += points.col(i);
    ++counts[labels[i]];
  }
  for (Eigen::Index c = 0; c < centres.cols(); ++c)
    if (counts[c] > 0) centres.col(c) = sums.col(c) / counts[c];
}

}  // namespace

std::vector<std::size_t> kmeans_representatives(const Eigen::MatrixXf& points_f,
                                                const KMeansOptions& options) {
  const Eigen::Index n = points_f.cols();
  std::vector<std::size_t> out;
  if (n <= options.k) {
    out.resize(n);
    std::iota(out.begin(), out.end(), 0);
    return out;
  }
  const Eigen::MatrixXd points = points_f.cast<double>();
  std::mt19937_64 rng(options.seed);
  Eigen::MatrixXd centres = seed_centres(points, options.k, rng);
  std::vector<int> labels(n, -1), previous;
  for (int it = 0; it < options.max_iterations && labels != previous; ++it) {
    previous = labels;
    assign(points, centres, options.threads, labels);
    update(points, labels, centres);
  }
  // The member nearest each centroid (ties: the lower index).
  std::vector<std::pair<double, Eigen::Index>> best(centres.cols(),
                                                    {std::numeric_limits<double>::infinity(), -1});
  for (Eigen::Index i = 0; i < n; ++i) {
    const double d = (points.col(i) - centres.col(labels[i])).squaredNorm();
    if (d < best[labels[i]].first) best[labels[i]] = {d, i};
  }
  for (const auto& [d, i] : best)
    if (i >= 0) out.push_back(static_cast<std::size_t>(i));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace brdfnav::nav
