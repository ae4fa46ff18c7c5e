// Cubic Hermite tables of the smooth functions inside He::eval (see he_tables.h). Each node holds
// exact values and analytic derivatives, so the interpolation error is O(h^4) with no
// boundary effects; the node spacings below were chosen by measuring that error against the
// exact functions (tests/core/test_he.cpp checks it over dense sweeps).
#include "he_tables.h"

#include <brdfnav/core/cpu.h>
#include <brdfnav/core/he.h>

#include <immintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace brdfnav::he_detail {

namespace {

constexpr double kSqrtPi = 1.7724538509055160273;

// Cubic Hermite basis on [0, 1] at x; the derivative weights are scaled by the node spacing h.
struct HermiteWeights {
  double v0, v1, d0, d1;
  HermiteWeights(double x, double h) {
    const double x2 = x * x, x3 = x2 * x;
    v0 = 2 * x3 - 3 * x2 + 1;
    v1 = 3 * x2 - 2 * x3;
    d0 = (x3 - 2 * x2 + x) * h;
    d1 = (x3 - x2) * h;
  }
  double operator()(double f0, double f1, double df0, double df1) const {
    return v0 * f0 + v1 * f1 + d0 * df0 + d1 * df1;
  }
};

// N functions of x on [0, (n - 1) h], each node holding (value, derivative) per function.
template <int N>
class HermiteTable1D {
 public:
  using Node = std::array<double, 2 * N>;
  template <typename Fn>
  HermiteTable1D(int n, double h, Fn&& node_at) : h_(h), inv_h_(1 / h), nodes_(n) {
    for (int i = 0; i < n; ++i) nodes_[i] = node_at(i * h);
  }
  double end() const { return (static_cast<double>(nodes_.size()) - 1) * h_; }
  // x in [0, end()].
  std::array<double, N> operator()(double x) const {
    const double s = x * inv_h_;
    const int i = std::min(static_cast<int>(s), static_cast<int>(nodes_.size()) - 2);
    const HermiteWeights w(s - i, h_);
    const Node &a = nodes_[i], &b = nodes_[i + 1];
    std::array<double, N> out;
    for (int k = 0; k < N; ++k) out[k] = w(a[2 * k], b[2 * k], a[2 * k + 1], b[2 * k + 1]);
    return out;
  }

 private:
  double h_, inv_h_;
  std::vector<Node> nodes_;
};

// S1 = sqrt(pi) a (1 + erf a) / (exp(-a^2) + sqrt(pi) a (1 + erf a)): He et al.'s
// (1 - erfc/2) / (1 + L) with numerator and denominator times 2 sqrt(pi) a, free of the 1/a pole,
// hence smooth down to a = 0 (grazing). Spacing 1/64: interpolation error < 1e-9.
const HermiteTable1D<2>& shadowing_table() {
  static const HermiteTable1D<2> table(385, kShadowTableEnd / 384, [](double a) {
    const double e = std::exp(-a * a), erfc_a = std::erfc(a);
    const double n = kSqrtPi * a * (2 - erfc_a), dn = kSqrtPi * (2 - erfc_a) + 2 * a * e;
    const double s1 = n / (n + e), ds1 = e * (dn + 2 * a * n) / ((n + e) * (n + e));
    return HermiteTable1D<2>::Node{s1, ds1, erfc_a, -2 / kSqrtPi * e};
  });
  return table;
}

// Root x >= 0 of x exp(x^2 / 2) = y: x <= y always, and x <= sqrt(2 ln y) once the root is >= 1
// (when y >= exp(1/2)), so Newton started there converges monotonically, the left side being
// increasing and convex.
double solve_x_exp_half_x2(double y) {
  if (!(y > 0)) return 0.0;
  double x = y <= std::exp(0.5) ? y : std::sqrt(2.0 * std::log(y));
  for (int i = 0; i < 40; ++i) {
    const double step = (x - y * std::exp(-0.5 * x * x)) / (1.0 + x * x);
    x -= step;
    if (std::abs(step) <= 1e-13 * x) break;
  }
  return x;
}

// q = 1 / sqrt(1 + x^2) for y in [0, 8] (K_i + K_o up to 40: both directions below ~87 degrees
// for the grid's sigma / tau); dq/dy = -x q^3 dx/dy, dx/dy = exp(-x^2/2) / (1 + x^2).
// Spacing 1/64: interpolation error about 1e-9 (relative).
const HermiteTable1D<1>& sigma0_ratio_table() {
  static const HermiteTable1D<1> table(513, 8.0 / 512, [](double y) {
    const double x = solve_x_exp_half_x2(y), q = 1 / std::sqrt(1 + x * x);
    const double dx = std::exp(-0.5 * x * x) / (1 + x * x);
    return HermiteTable1D<1>::Node{q, -x * q * q * q * dx};
  });
  return table;
}

// --- The series S(g, t) = sum_{m>=1} exp(-g) g^m / (m! m) exp(-t/m), tabulated as
// F = ln S + ln g + w^2 over a row coordinate s(g) and w = sqrt(t / (g + 1)). In w the lobe's
// Gaussian-like fall-off exp(-c t) is a parabola, and w = 10 is past 1e-15 of the peak for every
// g (a t of about 100 for small g, of 100 g for large g). Below g = 0.01 four terms suffice.
//
// The rows are uniform in s. Up to kTableRoughFrom (~18), s = u = ln g; beyond it
// s = u1 + 4 (1 - (kTableRoughFrom / g)^(1/4)), u1 = ln kTableRoughFrom, which reaches g = infinity
// at the last row; the two meet with ds/du = 1 at a node. For large g the sum is
// exp(-t/g) / g (1 + O(1/g)) (the rough-surface limit times its corrections), so F = O(1/g), a
// smooth function of s (1/g is a quartic in s) that vanishes with its derivatives at g = infinity:
// no g is outside the table. Below the seam, ln g + w^2 is linear in s and quadratic in w, which
// the bicubic interpolation reproduces exactly: there it interpolates ln S as it would alone.
constexpr double kTableLoG = 0.01;
constexpr double kTableW = 10.0;
constexpr double kU0 = -4.605170185988091;  // ln kTableLoG
constexpr double kHu = 0.125;
constexpr int kLogRows = 61, kRoughRows = 32;
constexpr double kU1 = kU0 + (kLogRows - 1) * kHu;  // ln kTableRoughFrom
constexpr double kRoughSpan = kRoughRows * kHu;     // the 4 of s beyond the seam
static_assert(kRoughSpan == 4.0, "ds/du = 1 on both sides of the seam");
constexpr int kNu = kLogRows + kRoughRows, kNw = 121;
constexpr double kHw = kTableW / (kNw - 1);

// s of g > 0, log_g = ln g.
double row_coordinate(double g, double log_g) {
  if (g <= kTableRoughFrom) return log_g;
  return kU1 + kRoughSpan * (1 - std::sqrt(std::sqrt(kTableRoughFrom / g)));
}

// F, dF/ds, dF/dw and d2F/dsdw at one node.
using SeriesNode = std::array<double, 4>;

// ln m and ln(m! m) for small m (entry 0 unused).
struct SmallLogs {
  std::vector<double> log, log_factorial_times_m;
};

// The node at g (u = ln g, du_ds = du/ds there) and w, from the terms a_m of the series, which
// are log-concave in m: all those within exp(-50) of the largest or, where the largest is at
// m >= 32, every h-th of them times h, h = floor(sigma / 3) for the terms' spread sigma (h >= 2
// from g ~ 36 on). The terms are then a smooth bell in m, and by Poisson summation the sum over
// every h-th m differs from h times the integral, as does the sum over every m, by about
// exp(-2 pi^2 sigma^2 / h^2) = exp(-178) relative: some 60 terms per node at any g, with nodes
// equal to those of the sums over every m to 1e-12 (measured for g from 7 to 3000).
// With E[.] the average over m weighted by a_m and d ln a_m = (m - g - g w^2 / m) du
// - 2 (g + 1) w / m dw (t = (g + 1) w^2): F_u = E[m - g - g w^2 / m] + 1,
// F_w = 2 w (1 - (g + 1) E[1/m]), F_uw = -2 g w E[1/m] - 2 (g + 1) w Cov(m - g w^2 / m, 1/m).
SeriesNode series_node(const SmallLogs& small, double u, double g, double du_ds, double w) {
  const double w2 = w * w, t = (g + 1) * w2;
  const double small_terms = static_cast<double>(small.log.size());
  auto log_of = [&](double m) {
    return m < small_terms ? small.log[static_cast<std::size_t>(m)] : std::log(m);
  };
  auto log_term = [&](double m) {
    if (m < small_terms)
      return -g + m * u - small.log_factorial_times_m[static_cast<std::size_t>(m)] - t / m;
    return log_poisson(m, g, u) - std::log(m) - t / m;
  };
  // The largest term, by bisection on the sign of ln a_{m+1} - ln a_m
  // = ln g + ln m - 2 ln(m + 1) + t / (m (m + 1)), decreasing in m. Beyond 3 g + sqrt(t) + 10 it
  // is negative: ln g + ln m - 2 ln(m + 1) < -ln 3 and t / (m (m + 1)) < 1.
  double lo = 1, hi = std::ceil(3 * g + std::sqrt(t) + 10);
  while (lo < hi) {
    const double mid = std::floor(0.5 * (lo + hi));
    if (u + log_of(mid) - 2 * log_of(mid + 1) + t / (mid * (mid + 1)) > 0) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  const double m_peak = lo, log_max = log_term(m_peak);
  // Spread from the curvature of ln a_m at its peak, -1/m - 2 t / m^3.
  const double sigma = 1 / std::sqrt(1 / m_peak + 2 * t / (m_peak * m_peak * m_peak));
  constexpr double kLogIgnored = -50;        // a term this far below the largest moves no sum
  std::vector<std::array<double, 2>> terms;  // (m, a_m / a_max)
  auto collect = [&](double h) {
    terms.clear();
    for (double m = m_peak; m >= 1; m -= h) {
      const double l = log_term(m) - log_max;
      if (l < kLogIgnored) return true;
      terms.push_back({m, std::exp(l)});
    }
    return h == 1;  // with h > 1 the terms had not yet faded at m = 1
  };
  double h = m_peak >= 32 ? std::max(1.0, std::floor(sigma / 3)) : 1.0;
  if (!collect(h)) collect(h = 1);
  for (double m = m_peak + h;; m += h) {
    const double l = log_term(m) - log_max;
    if (l < kLogIgnored) break;
    terms.push_back({m, std::exp(l)});
  }
  double s = 0, e_inv = 0, e_x = 0;  // sum, then E[1/m] and E[m - g - g w^2 / m]
  for (const auto& [m, a] : terms) {
    s += a;
    e_inv += a / m;
    e_x += a * ((m - g) - g * w2 / m);
  }
  e_inv /= s;
  e_x /= s;
  double cov = 0;
  for (const auto& [m, a] : terms) cov += a * (((m - g) - g * w2 / m) - e_x) * (1 / m - e_inv);
  cov /= s;
  const double f_u = e_x + 1;
  const double f_uw = -2 * g * w * e_inv - 2 * (g + 1) * w * cov;
  return {log_max + std::log(h * s) + u + w2, f_u * du_ds, 2 * w * (1 - (g + 1) * e_inv),
          f_uw * du_ds};
}

class SeriesTable {
 public:
  SeriesTable() : nodes_(kNu * kNw) {
    // ln m and ln(m! m) for m < 1024 (entry 0 unused): the terms of g up to ~250, where every m
    // is summed, without logs, to 1e-12 (rounding of terms of up to ~1e4).
    SmallLogs small;
    small.log.resize(1024);
    small.log_factorial_times_m.resize(1024);
    double log_factorial = 0;
    for (std::size_t m = 1; m < small.log.size(); ++m) {
      small.log[m] = std::log(static_cast<double>(m));
      log_factorial += small.log[m];
      small.log_factorial_times_m[m] = log_factorial + small.log[m];
    }
    for (int i = 0; i < kNu; ++i) {
      // g = infinity at the last row: F = 0 with its derivatives (the nodes' zero).
      if (i == kNu - 1) break;
      double u = kU0 + i * kHu, du_ds = 1;
      if (i >= kLogRows) {
        // 1 - (kTableRoughFrom / g)^(1/4) = x, x = (s - u1) / 4, and du/ds = (g / g1)^(1/4).
        const double x = static_cast<double>(i - (kLogRows - 1)) / kRoughRows;
        u = kU1 - 4 * std::log1p(-x);
        du_ds = 1 / (1 - x);
      }
      const double g = std::exp(u);
      for (int j = 0; j < kNw; ++j) nodes_[i * kNw + j] = series_node(small, u, g, du_ds, j * kHw);
    }
  }
  // log_sum() of three (s, w) at once, four lanes wide (the fourth a copy of the third): the
  // weights of all three in one pass, then per lane one 4-wide load of each of the four nodes,
  // whose (F, dF/ds, dF/dw, d2F/dsdw) the w-weights combine in one go. The same interpolation as
  // log_sum(), its sums in another order and fused: equal to rounding.
  __attribute__((target("avx2,fma"))) std::array<double, 3> log_sums(const Rgb& s,
                                                                     const Rgb& w) const {
    const __m256d su =
        _mm256_mul_pd(_mm256_sub_pd(_mm256_setr_pd(s[0], s[1], s[2], s[2]), _mm256_set1_pd(kU0)),
                      _mm256_set1_pd(1 / kHu));
    const __m256d sw =
        _mm256_mul_pd(_mm256_setr_pd(w[0], w[1], w[2], w[2]), _mm256_set1_pd(1 / kHw));
    const __m128i i = _mm_min_epi32(_mm_max_epi32(_mm256_cvttpd_epi32(su), _mm_setzero_si128()),
                                    _mm_set1_epi32(kNu - 2));
    const __m128i j = _mm_min_epi32(_mm256_cvttpd_epi32(sw), _mm_set1_epi32(kNw - 2));
    alignas(32) std::array<double, 4> xu, xw, v0u, v1u, d0u, d1u, v0w, v1w, d0w, d1w;
    _mm256_store_pd(xu.data(), _mm256_sub_pd(su, _mm256_cvtepi32_pd(i)));
    _mm256_store_pd(xw.data(), _mm256_sub_pd(sw, _mm256_cvtepi32_pd(j)));
    hermite_weights(xu, kHu, v0u, v1u, d0u, d1u);
    hermite_weights(xw, kHw, v0w, v1w, d0w, d1w);
    alignas(16) std::array<int, 4> is, js;
    _mm_store_si128(reinterpret_cast<__m128i*>(is.data()), i);
    _mm_store_si128(reinterpret_cast<__m128i*>(js.data()), j);
    std::array<double, 3> out;
    for (int c = 0; c < 3; ++c) {
      const double* n0 = nodes_[is[c] * kNw + js[c]].data();
      const double* n1 = n0 + 4 * kNw;  // (F, dF/ds) at s nodes i and i + 1:
      const __m128d row0 = along_w(n0, v0w[c], v1w[c], d0w[c], d1w[c]);
      const __m128d row1 = along_w(n1, v0w[c], v1w[c], d0w[c], d1w[c]);
      const __m128d sum = _mm_fmadd_pd(row1, _mm_setr_pd(v1u[c], d1u[c]),
                                       _mm_mul_pd(row0, _mm_setr_pd(v0u[c], d0u[c])));
      out[c] = _mm_cvtsd_f64(_mm_add_sd(sum, _mm_unpackhi_pd(sum, sum)));
    }
    return out;
  }

  // F at s in [kU0, kU1 + 4], w in [0, kTableW).
  double log_sum(double s, double w) const {
    const double su = (s - kU0) * (1 / kHu), sw = w * (1 / kHw);
    const int i = std::clamp(static_cast<int>(su), 0, kNu - 2);
    const int j = std::min(static_cast<int>(sw), kNw - 2);
    const HermiteWeights wu(su - i, kHu), ww(sw - j, kHw);
    const SeriesNode* n0 = &nodes_[i * kNw + j];
    const SeriesNode* n1 = n0 + kNw;
    // Along w at both s nodes (F and dF/ds), then along s.
    const double f0 = ww(n0[0][0], n0[1][0], n0[0][2], n0[1][2]);
    const double fu0 = ww(n0[0][1], n0[1][1], n0[0][3], n0[1][3]);
    const double f1 = ww(n1[0][0], n1[1][0], n1[0][2], n1[1][2]);
    const double fu1 = ww(n1[0][1], n1[1][1], n1[0][3], n1[1][3]);
    return wu(f0, f1, fu0, fu1);
  }

 private:
  // HermiteWeights of four x at once, each node spacing h.
  __attribute__((target("avx2,fma"))) static void hermite_weights(
      const std::array<double, 4>& at, double h, std::array<double, 4>& v0,
      std::array<double, 4>& v1, std::array<double, 4>& d0, std::array<double, 4>& d1) {
    const __m256d x = _mm256_load_pd(at.data());
    const __m256d x2 = _mm256_mul_pd(x, x), x3 = _mm256_mul_pd(x2, x), hh = _mm256_set1_pd(h);
    const __m256d two = _mm256_set1_pd(2), three = _mm256_set1_pd(3);
    const __m256d c3 = _mm256_fmsub_pd(three, x2, _mm256_mul_pd(two, x3));  // 3 x^2 - 2 x^3
    _mm256_store_pd(v1.data(), c3);
    _mm256_store_pd(v0.data(), _mm256_sub_pd(_mm256_set1_pd(1), c3));
    const __m256d x3_x2 = _mm256_sub_pd(x3, x2);
    _mm256_store_pd(d0.data(), _mm256_mul_pd(_mm256_add_pd(_mm256_sub_pd(x3_x2, x2), x), hh));
    _mm256_store_pd(d1.data(), _mm256_mul_pd(x3_x2, hh));
  }

  // Along w between the nodes at n and n + 1 (n's row of s), given the w-weights:
  // a = v0 n[0] + v1 n[1] and b = d0 n[0] + d1 n[1] over (F, dF/ds, dF/dw, d2F/dsdw), then
  // (F, dF/ds) = (a.F + b.Fw, a.Fs + b.Fsw): a's lanes 0, 1 plus b's lanes 2, 3.
  __attribute__((target("avx2,fma"))) static __m128d along_w(const double* n, double v0, double v1,
                                                             double d0, double d1) {
    const __m256d lo = _mm256_loadu_pd(n), hi = _mm256_loadu_pd(n + 4);
    const __m256d a =
        _mm256_fmadd_pd(_mm256_set1_pd(v1), hi, _mm256_mul_pd(_mm256_set1_pd(v0), lo));
    const __m256d b =
        _mm256_fmadd_pd(_mm256_set1_pd(d1), hi, _mm256_mul_pd(_mm256_set1_pd(d0), lo));
    return _mm_add_pd(_mm256_castpd256_pd128(a), _mm256_extractf128_pd(b, 1));
  }

  std::vector<SeriesNode> nodes_;
};

const SeriesTable& series_table() {
  static const SeriesTable table;
  return table;
}

// Terms m = 1..4, with exp(-t/m) as powers of exp(-t/12): the terms left out are below
// g^4 / 600 < 2e-11 of the sum at t = 0 (about g) for g < kTableLoG.
double small_g_series_sum(double g, double t) {
  const double p = std::exp(-t * (1.0 / 12)), p2 = p * p, p3 = p2 * p, p6 = p3 * p3;
  const double poly = g * (p6 * p6 + g * (0.25 * p6 + g * (p2 * p2 / 18 + g * (p3 / 96))));
  return std::exp(-g) * poly;
}

}  // namespace

Shadowing tabulated_shadowing(double a) {
  const auto v = shadowing_table()(a);
  return {v[0], v[1]};
}

Shadowing exact_shadowing(double a) {
  const double erfc_a = std::erfc(a);
  const double l = 0.5 * (std::exp(-a * a) / (kSqrtPi * a) - erfc_a);
  return {(1.0 - 0.5 * erfc_a) / (1.0 + l), erfc_a};
}

double sigma0_ratio(double y) {
  const double x = solve_x_exp_half_x2(y);
  return 1 / std::sqrt(1 + x * x);
}

double tabulated_sigma0_ratio(double y) {
  const HermiteTable1D<1>& table = sigma0_ratio_table();
  return y <= table.end() ? table(y)[0] : sigma0_ratio(y);
}

Rgb tabulated_series_sums(const Rgb& g, const Rgb& log_g, const Rgb& t) {
  static const bool avx2 = cpu_has_avx2_fma();
  const Rgb w2 = t.max(0.0) / (g + 1);
  const bool in_table = (g >= kTableLoG).all() && (w2 < kTableW * kTableW).all();
  if (!avx2 || !in_table)
    return Rgb(tabulated_series_sum(g[0], log_g[0], t[0]),
               tabulated_series_sum(g[1], log_g[1], t[1]),
               tabulated_series_sum(g[2], log_g[2], t[2]));
  const Rgb s(row_coordinate(g[0], log_g[0]), row_coordinate(g[1], log_g[1]),
              row_coordinate(g[2], log_g[2]));
  const std::array<double, 3> f = series_table().log_sums(s, w2.sqrt());
  return (Rgb(f[0], f[1], f[2]) - log_g - w2).exp();
}

double tabulated_series_sum(double g, double log_g, double t) {
  if (!(g > 0)) return 0.0;
  t = std::max(t, 0.0);
  if (g < kTableLoG) return small_g_series_sum(g, t);
  const double w2 = t / (g + 1);
  if (!(w2 < kTableW * kTableW)) return 0.0;
  return std::exp(series_table().log_sum(row_coordinate(g, log_g), std::sqrt(w2)) - log_g - w2);
}

double log_poisson(double m, double g, double log_g) {
  // ln m! for m < 20, summed once.
  static const std::array<double, 20> log_factorial = [] {
    std::array<double, 20> out{};
    for (int k = 2; k < 20; ++k) out[k] = out[k - 1] + std::log(static_cast<double>(k));
    return out;
  }();
  if (m < 20) return -g + m * log_g - log_factorial[static_cast<int>(m)];
  // ln m! = m ln m - m + ln(2 pi m) / 2 + 1/(12 m) - 1/(360 m^3) + 1/(1260 m^5) - 1/(1680 m^7)
  // (the next, 1/(1188 m^9), is 2e-15 at m = 20), with -g + m ln g - m ln m + m formed as
  // d - m ln(1 + d / g), d = m - g: no large terms that cancel.
  const double d = m - g, inv = 1 / m, inv2 = inv * inv;
  const double stirling = inv * (1.0 / 12 - inv2 * (1.0 / 360 - inv2 * (1.0 / 1260 - inv2 / 1680)));
  return d - m * std::log1p(d / g) - 0.5 * std::log(2 * kPi * m) - stirling;
}

}  // namespace brdfnav::he_detail
