// Statistical machinery for the closure tests: chi-square goodness of fit (after pbrt's
// bsdfs_test), the regularised incomplete gamma function for its p-value, and adaptive Simpson
// quadrature over (theta, phi) cells of the upper hemisphere. A header (not test_*.cpp) because
// tests/core turns every test_*.cpp into its own executable.
#pragma once

#include <brdfnav/core/math.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>
#include <string>
#include <vector>

namespace brdfnav::stats {

// ---------------------------------------------------------------------------------------------
// Regularised upper incomplete gamma Q(a, x) = Gamma(a, x) / Gamma(a) (Numerical Recipes 6.2:
// power series below x = a + 1, Lentz continued fraction above). Accurate to ~1e-14.

inline double gamma_p_series(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 10000 && std::abs(term) > std::abs(sum) * 1e-16; ++n) {
    term *= x / (a + n);
    sum += term;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

inline double gamma_q_continued_fraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double step = d * c;
    h *= step;
    if (std::abs(step - 1.0) < 1e-16) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

inline double regularized_gamma_q(double a, double x) {
  if (x <= 0) return 1.0;
  return x < a + 1.0 ? 1.0 - gamma_p_series(a, x) : gamma_q_continued_fraction(a, x);
}

// P(X >= statistic) for X ~ chi-square with `dof` degrees of freedom.
inline double chi_square_p_value(double statistic, int dof) {
  return regularized_gamma_q(0.5 * dof, 0.5 * statistic);
}

// Per-test significance level that keeps the family-wise level at `alpha` over `tests`
// independent tests (Sidak correction).
inline double sidak_level(double alpha, int tests) {
  return 1.0 - std::pow(1.0 - alpha, 1.0 / tests);
}

// ---------------------------------------------------------------------------------------------
// Pearson's chi-square test of observed against expected counts, pooling cells whose expected
// count is below `min_expected` (in increasing order of expectation, as pbrt does) so the
// chi-square approximation holds. Both spans must have the same total.

struct ChiSquareResult {
  double statistic = 0;
  int dof = 0;
  double p_value = 1;
  std::string error;  // non-empty when samples fall where nothing is expected
};

inline ChiSquareResult chi_square(std::span<const double> observed,
                                  std::span<const double> expected, double min_expected = 5.0) {
  ChiSquareResult r;
  const double total = std::accumulate(observed.begin(), observed.end(), 0.0);
  std::vector<std::size_t> order(expected.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
  double pooled_observed = 0, pooled_expected = 0;
  int cells = 0;
  for (const std::size_t i : order) {
    if (expected[i] == 0) {
      // A few stray samples are tolerated where the quadrature found exactly zero mass: cells
      // that a lobe barely touches between quadrature nodes (pbrt allows 1e-5 of the total).
      if (observed[i] > total * 1e-5)
        r.error = "cell " + std::to_string(i) + " has " + std::to_string(observed[i]) +
                  " samples but zero expected mass";
    } else if (expected[i] < min_expected ||
               (pooled_expected > 0 && pooled_expected < min_expected)) {
      pooled_observed += observed[i];
      pooled_expected += expected[i];
    } else {
      const double diff = observed[i] - expected[i];
      r.statistic += diff * diff / expected[i];
      ++cells;
    }
  }
  if (pooled_expected > 0) {
    const double diff = pooled_observed - pooled_expected;
    r.statistic += diff * diff / pooled_expected;
    ++cells;
  }
  // The totals agree by construction, so one degree of freedom is lost.
  r.dof = cells - 1;
  r.p_value = r.dof > 0 ? chi_square_p_value(r.statistic, r.dof) : 1.0;
  return r;
}

// ---------------------------------------------------------------------------------------------
// Adaptive Simpson quadrature of a vector-valued function (Eigen array) on [a, b]. The interval
// is always split `min_depth` times so that a narrow peak cannot hide between the first five
// nodes; refinement stops when the Richardson error estimate is below `eps` in every component
// or at `max_depth`.

struct SimpsonOptions {
  double eps = 1e-9;
  int min_depth = 1;
  int max_depth = 14;
};

template <typename F, typename V>
V adaptive_simpson_step(const F& f, double a, double b, const V& fa, const V& fm, const V& fb,
                        const V& whole, double eps, int depth, const SimpsonOptions& opt) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const V flm = f(lm), frm = f(rm);
  const V left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const V right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const V delta = left + right - whole;
  if (depth >= opt.max_depth || (depth >= opt.min_depth && delta.abs().maxCoeff() <= 15.0 * eps))
    return left + right + delta / 15.0;
  return adaptive_simpson_step(f, a, m, fa, flm, fm, left, 0.5 * eps, depth + 1, opt) +
         adaptive_simpson_step(f, m, b, fm, frm, fb, right, 0.5 * eps, depth + 1, opt);
}

template <typename F>
auto adaptive_simpson(const F& f, double a, double b, const SimpsonOptions& opt) {
  using V = decltype(f(a));
  const double m = 0.5 * (a + b);
  const V fa = f(a), fm = f(m), fb = f(b);
  const V whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
  return V(adaptive_simpson_step(f, a, b, fa, fm, fb, whole, opt.eps, 0, opt));
}

// ---------------------------------------------------------------------------------------------
// The upper hemisphere cut into theta_res x phi_res cells, uniform in theta (0..pi/2) and
// phi (0..2 pi). The horizon is a cell boundary, so no cell straddles the discontinuity of a
// lobe that is cut off there.

struct HemisphereGrid {
  int theta_res = 32;
  int phi_res = 64;

  int cells() const { return theta_res * phi_res; }
  double theta_step() const { return 0.5 * kPi / theta_res; }
  double phi_step() const { return 2.0 * kPi / phi_res; }

  // Cell index of a direction with w.z > 0.
  int cell_of(const Vec3& w) const {
    const double theta = std::acos(std::clamp(w.z(), -1.0, 1.0));
    double phi = std::atan2(w.y(), w.x());
    if (phi < 0) phi += 2.0 * kPi;
    const int t = std::clamp(static_cast<int>(theta / theta_step()), 0, theta_res - 1);
    const int p = std::clamp(static_cast<int>(phi / phi_step()), 0, phi_res - 1);
    return t * phi_res + p;
  }

  // Integral of g(w) d(omega) over every cell, g: Vec3 -> Eigen array. Nested adaptive Simpson
  // in phi (inner) and theta (outer); the inner tolerance is tighter so that its error does
  // not drive the outer refinement.
  template <typename G>
  auto integrate_cells(const G& g, const SimpsonOptions& opt) const {
    using V = decltype(g(Vec3::UnitZ()));
    std::vector<V> out;
    out.reserve(cells());
    SimpsonOptions inner = opt;
    inner.eps = 0.1 * opt.eps / theta_step();
    for (int t = 0; t < theta_res; ++t) {
      for (int p = 0; p < phi_res; ++p) {
        const double phi0 = p * phi_step(), phi1 = phi0 + phi_step();
        const auto over_phi = [&](double theta) {
          const double s = std::sin(theta), c = std::cos(theta);
          const auto at = [&](double phi) { return V(g(spherical_direction(s, c, phi))); };
          return V(s * adaptive_simpson(at, phi0, phi1, inner));
        };
        out.push_back(adaptive_simpson(over_phi, t * theta_step(), (t + 1) * theta_step(), opt));
      }
    }
    return out;
  }
};

}  // namespace brdfnav::stats
