#include "closest.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace brdfnav::nav {

namespace {

constexpr double kFirstStep = 0.5;        // grid cells (and octaves of rho_s)
constexpr double kLastStep = 1.0 / 32.0;  // the search stops below it
constexpr double kMaxOctaves = 4;         // rho_s scaled by at most 16 either way

}  // namespace

Closest closest_in_model(const ModelEmbedding& embedding, const Eigen::VectorXf& centre,
                         const Material& start, int max_evaluations) {
  const ParamGrid& grid = embedding.grid();
  const std::size_t dims = grid.dimensions();
  // Coordinates: the lobe parameters' grid coordinates, then log2 of rho_s's factor.
  std::vector<double> x(dims + 1, 0.0), high(dims + 1, kMaxOctaves), low(dims + 1, 0.0);
  for (std::size_t d = 0; d < dims; ++d) {
    x[d] = grid.grid_coordinate(d, start.params[d]);
    high[d] = double(grid.axis(d).size() - 1);
  }
  low[dims] = -kMaxOctaves;
  const auto material_at = [&](const std::vector<double>& c) {
    Material m = start;
    for (std::size_t d = 0; d < dims; ++d) m.params[d] = grid.value_at(d, c[d]);
    m.rho_s = (start.rho_s * std::exp2(c[dims])).min(kRhoSMax);
    return m;
  };
  int evaluations = 0;
  const auto distance_at = [&](const std::vector<double>& c) {
    ++evaluations;
    return embedding_distance(embedding.embed(material_at(c)), centre);
  };
  double best = distance_at(x);
  for (double step = kFirstStep; step >= kLastStep && evaluations < max_evaluations;) {
    bool closer = false;
    for (std::size_t k = 0; k <= dims && !closer && evaluations < max_evaluations; ++k) {
      for (const double sign : {1.0, -1.0}) {
        std::vector<double> y = x;
        y[k] = std::clamp(x[k] + sign * step, low[k], high[k]);
        if (y[k] == x[k]) continue;
        const double d = distance_at(y);
        if (d < best) {
          x = std::move(y), best = d, closer = true;
          break;
        }
      }
    }
    if (!closer) step /= 2;
  }
  return {material_at(x), best, evaluations};
}

}  // namespace brdfnav::nav
