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

// S1 = sqrt(pi) a (1 + erf a) / (exp(-a^2) + sqrt(pi) a (1 + erf a)): the sheet's
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

// --- The series, as f = ln S over u = ln g and w = sqrt(t / (g + 1)). In w the lobe's
// Gaussian-like fall-off exp(-c t) is a parabola, and w = 10 is past 1e-15 of the peak for every
// g (a t of about 100 for small g, of 100 g for large g). Below g = 0.01 four terms suffice.
constexpr double kTableLoG = 0.01;
constexpr double kTableW = 10.0;
constexpr int kNu = 61, kNw = 121;
// Terms kept when building the nodes: every term above 1e-300 of the largest for t <= 100 (g + 1).
constexpr int kNodeTerms = 200;

// f, df/du, df/dw and d2f/dudw at one node.
using SeriesNode = std::array<double, 4>;

// With a_m the terms and S, S_t, S_g, S_tt, S_tg the sum and its derivatives (sums of a_m times
// -1/m, m/g - 1, 1/m^2, 1/m - 1/g), by the chain rule through t = (g + 1) w^2, g = e^u.
// ln(m! m) for m = 1..kNodeTerms (entry 0 unused).
std::array<double, kNodeTerms + 1> log_factorial_times_m() {
  std::array<double, kNodeTerms + 1> out{};
  double log_factorial = 0;
  for (int m = 1; m <= kNodeTerms; ++m) {
    const double log_m = std::log(static_cast<double>(m));
    log_factorial += log_m;
    out[m] = log_factorial + log_m;
  }
  return out;
}

SeriesNode series_node(const std::array<double, kNodeTerms + 1>& log_denominator, double u,
                       double w) {
  const double g = std::exp(u), w2 = w * w, t = (g + 1) * w2;
  std::array<double, kNodeTerms + 1> log_a;
  double log_max = -HUGE_VAL;
  for (int m = 1; m <= kNodeTerms; ++m) {
    log_a[m] = -g + m * u - log_denominator[m] - t / m;
    log_max = std::max(log_max, log_a[m]);
  }
  // Terms below exp(-50) of the largest change no sum by more than 2e-20 (of 200 terms).
  constexpr double kLogIgnored = -50;
  double s = 0, st = 0, sg = 0, stt = 0, stg = 0;
  for (int m = 1; m <= kNodeTerms; ++m) {
    if (log_a[m] - log_max < kLogIgnored) continue;
    const double a = std::exp(log_a[m] - log_max), inv_m = 1.0 / m;
    s += a;
    st -= a * inv_m;
    sg += a * (m / g - 1);
    stt += a * inv_m * inv_m;
    stg += a * (inv_m - 1 / g);
  }
  const double rt = st / s, rg = sg / s;
  // d(S_t / S)/dg along fixed w, where dt/dg = w^2.
  const double drt = (stg + stt * w2) / s - rt * (sg + st * w2) / s;
  return {log_max + std::log(s), g * (rg + rt * w2), 2 * (g + 1) * w * rt,
          2 * w * g * rt + 2 * (g + 1) * w * g * drt};
}

class SeriesTable {
 public:
  SeriesTable() : nodes_(kNu * kNw) {
    const auto log_denominator = log_factorial_times_m();
    for (int i = 0; i < kNu; ++i) {
      for (int j = 0; j < kNw; ++j) {
        nodes_[i * kNw + j] = series_node(log_denominator, kU0 + i * kHu, j * kHw);
      }
    }
  }
  // log_sum() of three (u, w) at once, four lanes wide (the fourth a copy of the third): the
  // weights of all three in one pass, then per lane one 4-wide load of each of the four nodes,
  // whose (f, df/du, df/dw, d2f/dudw) the w-weights combine in one go. The same interpolation as
  // log_sum(), its sums in another order and fused: equal to rounding.
  __attribute__((target("avx2,fma"))) std::array<double, 3> log_sums(const Rgb& u,
                                                                     const Rgb& w) const {
    const __m256d su =
        _mm256_mul_pd(_mm256_sub_pd(_mm256_setr_pd(u[0], u[1], u[2], u[2]), _mm256_set1_pd(kU0)),
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
      const double* n1 = n0 + 4 * kNw;  // (f, df/du) at u nodes i and i + 1:
      const __m128d row0 = along_w(n0, v0w[c], v1w[c], d0w[c], d1w[c]);
      const __m128d row1 = along_w(n1, v0w[c], v1w[c], d0w[c], d1w[c]);
      const __m128d sum = _mm_fmadd_pd(row1, _mm_setr_pd(v1u[c], d1u[c]),
                                       _mm_mul_pd(row0, _mm_setr_pd(v0u[c], d0u[c])));
      out[c] = _mm_cvtsd_f64(_mm_add_sd(sum, _mm_unpackhi_pd(sum, sum)));
    }
    return out;
  }

  // u in [kU0, ln kBlendHi], w in [0, kTableW).
  double log_sum(double u, double w) const {
    const double su = (u - kU0) * (1 / kHu), sw = w * (1 / kHw);
    const int i = std::clamp(static_cast<int>(su), 0, kNu - 2);
    const int j = std::min(static_cast<int>(sw), kNw - 2);
    const HermiteWeights wu(su - i, kHu), ww(sw - j, kHw);
    const SeriesNode* n0 = &nodes_[i * kNw + j];
    const SeriesNode* n1 = n0 + kNw;
    // Along w at both u nodes (f and df/du), then along u.
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

  // Along w between the nodes at n and n + 1 (n's row of u), given the w-weights:
  // a = v0 n[0] + v1 n[1] and b = d0 n[0] + d1 n[1] over (f, df/du, df/dw, d2f/dudw), then
  // (f, df/du) = (a.f + b.fw, a.fu + b.fuw): a's lanes 0, 1 plus b's lanes 2, 3.
  __attribute__((target("avx2,fma"))) static __m128d along_w(const double* n, double v0, double v1,
                                                             double d0, double d1) {
    const __m256d lo = _mm256_loadu_pd(n), hi = _mm256_loadu_pd(n + 4);
    const __m256d a =
        _mm256_fmadd_pd(_mm256_set1_pd(v1), hi, _mm256_mul_pd(_mm256_set1_pd(v0), lo));
    const __m256d b =
        _mm256_fmadd_pd(_mm256_set1_pd(d1), hi, _mm256_mul_pd(_mm256_set1_pd(d0), lo));
    return _mm_add_pd(_mm256_castpd256_pd128(a), _mm256_extractf128_pd(b, 1));
  }

  static constexpr double kU0 = -4.605170185988091;  // ln kTableLoG
  static constexpr double kU1 = 3.091042453358316;   // ln kBlendHi
  static constexpr double kHu = (kU1 - kU0) / (kNu - 1);
  static constexpr double kHw = kTableW / (kNw - 1);
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
  const bool in_table =
      (g >= kTableLoG).all() && (g <= kBlendHi).all() && (w2 < kTableW * kTableW).all();
  if (!avx2 || !in_table)
    return Rgb(tabulated_series_sum(g[0], log_g[0], t[0]),
               tabulated_series_sum(g[1], log_g[1], t[1]),
               tabulated_series_sum(g[2], log_g[2], t[2]));
  const std::array<double, 3> f = series_table().log_sums(log_g, w2.sqrt());
  return Rgb(std::exp(f[0]), std::exp(f[1]), std::exp(f[2]));
}

double tabulated_series_sum(double g, double log_g, double t) {
  if (!(g > 0)) return 0.0;
  t = std::max(t, 0.0);
  if (g < kTableLoG) return small_g_series_sum(g, t);
  const double w2 = t / (g + 1);
  if (!(w2 < kTableW * kTableW)) return 0.0;
  return std::exp(series_table().log_sum(log_g, std::sqrt(w2)));
}

}  // namespace brdfnav::he_detail
