// Order statistics for the reports, tests and benchmarks: one definition of "median" and "p90"
// so that every figure in bench/RESULTS.md and docs/VALIDATION.md means the same thing.
#pragma once

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace brdfnav {

// The q-quantile (0..1) by linear interpolation between order statistics (R's type 7, NumPy's
// default). Throws std::invalid_argument for an empty sample: there is no honest answer.
inline double quantile(std::vector<double> v, double q) {
  if (v.empty()) throw std::invalid_argument("quantile of an empty sample");
  std::sort(v.begin(), v.end());
  const double pos = std::clamp(q, 0.0, 1.0) * double(v.size() - 1);
  const std::size_t i = static_cast<std::size_t>(pos);
  if (i + 1 >= v.size()) return v.back();
  return v[i] + (pos - double(i)) * (v[i + 1] - v[i]);
}

}  // namespace brdfnav
