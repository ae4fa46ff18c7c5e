// He et al. 1991 lobe (core/src/he.cpp) against the He section of docs/CLOSURES.md (The
// formulas).
#include <brdfnav/core/cpu.h>
#include <brdfnav/core/he.h>
#include <brdfnav/core/material.h>

#include <gtest/gtest.h>
#include "he_tables.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace brdfnav {
namespace {

constexpr double kDeg = kPi / 180.0;

He make_he(double sigma, double tau, double eta) {
  const std::array<double, 3> p{sigma, tau, eta};
  return He(p);
}

Vec3 direction(double theta_deg, double phi_deg) {
  return spherical_direction(std::sin(theta_deg * kDeg), std::cos(theta_deg * kDeg),
                             phi_deg * kDeg);
}

double relative_error(double value, double expected) {
  return std::abs(value - expected) / std::abs(expected);
}

// --- Independent, deliberately plain versions of the formulas in docs/CLOSURES.md (no code
// shared with he.cpp), used by the rough-limit test and the plain lobe below.

double plain_fresnel(double c, double eta) {
  const double g = std::sqrt(eta * eta + c * c - 1.0);
  const double a = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return 0.5 * (g - c) * (g - c) / ((g + c) * (g + c)) * (1.0 + a * a);
}

double plain_s1(const Vec3& w, double sigma, double tau) {
  const double theta = std::acos(w.z());
  if (theta == 0.0) return 1.0;
  const double a = tau / std::tan(theta) / (2.0 * sigma);
  const double l = 0.5 * (std::exp(-a * a) / (std::sqrt(kPi) * a) - std::erfc(a));
  return (1.0 - 0.5 * std::erfc(a)) / (1.0 + l);
}

double plain_k(const Vec3& w, double sigma, double tau) {
  const double tan_theta = std::tan(std::acos(w.z()));
  if (tan_theta == 0.0) return 0.0;
  return tan_theta * std::erfc(tau / (2.0 * sigma * tan_theta));
}

// sigma0 with x exp(x^2/2) = (K_i + K_o) / sqrt(8 pi) solved by bisection.
double plain_sigma0(const Vec3& wi, const Vec3& wo, double sigma, double tau) {
  const double y = (plain_k(wi, sigma, tau) + plain_k(wo, sigma, tau)) / std::sqrt(8.0 * kPi);
  double lo = 0.0, hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid * std::exp(0.5 * mid * mid) < y ? lo : hi) = mid;
  }
  return sigma / std::sqrt(1.0 + lo * lo);
}

// The rough-surface limit written as a microfacet lobe: F S D_Beckmann / (4 cos_i cos_o) with
// the Beckmann slope m = 2 sigma0 / tau.
double beckmann_form(const He& he, const Vec3& wi, const Vec3& wo) {
  const Vec3 h = (wi + wo).normalized();
  const double m = 2.0 * plain_sigma0(wi, wo, he.sigma, he.tau) / he.tau;
  const double tan2 = (1.0 - h.z() * h.z()) / (h.z() * h.z());
  const double d = std::exp(-tan2 / (m * m)) / (kPi * m * m * std::pow(h.z(), 4));
  const double s = plain_s1(wi, he.sigma, he.tau) * plain_s1(wo, he.sigma, he.tau);
  return plain_fresnel(wi.dot(h), he.eta) * s * d / (4.0 * wi.z() * wo.z());
}

// --- The series, independently: long double, compensated.

// sum_{m>=1} exp(-g) g^m / (m! m) exp(-t/m) in long double: every m within 20 sqrt(g) + 100 of
// the Poisson mode (and sqrt(t) beyond it, where the lobe's tail moves the largest term), the
// terms left out being below exp(-180) of the sum. ln(exp(-g) g^m / m!) from lgammal at the first
// m, then by the recurrence + ln g - ln m; Neumaier's compensated sum. No code shared with
// he.cpp, and several times its terms.
long double reference_series(long double g, long double t) {
  const long double spread = 20 * std::sqrt(g) + 100;
  const long double first = std::max(1.0L, std::floor(g - spread));
  const long double last = std::ceil(g + spread + std::sqrt(t));
  const long double log_g = std::log(g);
  long double log_poisson = -g + first * log_g - std::lgamma(first + 1);
  long double sum = 0, compensation = 0, log_m = std::log(first);
  for (long double m = first; m <= last; m += 1) {
    const long double term = std::exp(log_poisson - log_m - t / m);
    const long double next = sum + term;
    compensation += std::abs(sum) >= std::abs(term) ? (sum - next) + term : (term - next) + sum;
    sum = next;
    log_m = std::log(m + 1);
    log_poisson += log_g - log_m;
  }
  return sum + compensation;
}

// The whole lobe F S G D / (pi cos_i cos_o) from those formulas with the plain forms above
// and reference_series(), per channel (wi, wo of unit length).
std::array<double, 3> plain_lobe(const He& he, const Vec3& wi, const Vec3& wo) {
  const Vec3 v = wi + wo;
  const double vz = wi.z() + wo.z(), vxy2 = v.x() * v.x() + v.y() * v.y();
  const double fresnel = plain_fresnel(0.5 * v.norm(), he.eta);
  const double shadowing = plain_s1(wi, he.sigma, he.tau) * plain_s1(wo, he.sigma, he.tau);
  const double geometry = std::pow(v.squaredNorm() / vz, 2);
  const double sigma0 = plain_sigma0(wi, wo, he.sigma, he.tau);
  std::array<double, 3> lobe;
  for (int c = 0; c < 3; ++c) {
    const double lambda = He::kLambda[c];
    const double g = std::pow(2 * kPi * sigma0 * vz / lambda, 2);
    const double t = kPi * kPi * he.tau * he.tau * vxy2 / (lambda * lambda);
    const double d = kPi * kPi * he.tau * he.tau / (4 * lambda * lambda) *
                     static_cast<double>(reference_series(g, t));
    lobe[c] = fresnel * shadowing * geometry * d / (kPi * wi.z() * wo.z());
  }
  return lobe;
}

// The reference series against mpmath at 40 digits (summed around its largest term): 7e-15 at
// g = 1e4, where the recurrence for the Poisson weights runs over 4000 terms.
TEST(He, ReferenceSeriesMatchesMpmath) {
  struct Case {
    double g, t, sum;
  };
  for (const Case& c : std::array<Case, 4>{{{0.19887282, 0.63682036, 0.09242186451139024},
                                            {23.13372, 2.6695094, 0.039889281735088369},
                                            {291.41567, 151.66863, 0.0020398240657147182},
                                            {1e4, 5e4, 6.7403048397546186e-7}}}) {
    EXPECT_NEAR(static_cast<double>(reference_series(c.g, c.t)), c.sum, 1e-13 * c.sum)
        << "g " << c.g << " t " << c.t;
  }
}

// --- Spot values.

struct Spot {
  double sigma, tau, eta;
  Vec3 wi, wo;
  std::array<double, 3> lobe;    // eval(wi, wo), R G B
  std::array<double, 3> mirror;  // mirror_weight(wo), R G B
};

// Reference values computed with mpmath at 40 digits straight from the formulas of
// docs/CLOSURES.md (the "sheet" of the test's name): F at c = wi.h, S1 with the errata exp(-a^2),
// sigma0 from findroot, D from the series summed in log space over every term above 1e-60 of its
// largest. Intermediates, so that a failure can be traced:
//  A: c 0.486233090722, F 0.093819244365, S1i 0.994353635075, S1o 0.999999617232,
//     x 0.00551505705415, sigma0 0.049999239621, G 1.06681645432,
//     g (0.19887282, 0.29903593, 0.41969029), t (0.63682036, 0.95755754, 1.3439107).
//  B: c 0.92732657785, F 0.111602993217, S = 1, sigma0 = sigma, G 3.44499329645,
//     g (4.6931586, 7.0568871, 9.9041844), t (7.9664976, 11.978857, 16.81206).
//  C: c 0.641569678485, F 0.624367253277, S1i 0.936439465146, S1o 0.997417258326,
//     x 0.0363120610542, sigma0 0.999341368376, G 1.86038969321,
//     g (138.08911, 207.63825, 291.41567), t (71.869112, 108.06628, 151.66863). The series
//     (not its rough-surface limit exp(-t/g)/g, 0.39888350178087791 in every channel, which C
//     held until the limit was dropped): 0.06%, 0.04% and 0.03% above the limit.
const std::array<Spot, 3> kSpots{{
    {0.05,
     0.5,
     1.5,
     direction(70, 0),
     direction(55, 160),
     {0.022129139956102045, 0.034647163957506642, 0.044776529493624933},
     {0.051028020591369223, 0.043603512699423584, 0.036079799007367833}},
    {0.12,
     8.0,
     2.0,
     direction(20, 30),
     direction(24, 205),
     {1.7817989811388747, 1.8680811974699034, 1.9275977036482427},
     {0.0011679499566459986, 0.00011739044402168936, 7.3741889248820282e-6}},
    {1.0,
     4.0,
     9.0,
     direction(60, 0),
     direction(45, 150),
     {0.39913715703049563, 0.39905659459979461, 0.39900859686765628},
     {2.363033118551729e-83, 7.2500449698505058e-125, 7.1532767830595425e-175}},
}};

TEST(He, SpotValuesMatchTheSheetPerChannel) {
  for (const Spot& s : kSpots) {
    SCOPED_TRACE(::testing::Message() << "sigma " << s.sigma << " tau " << s.tau);
    const He he = make_he(s.sigma, s.tau, s.eta);
    const Rgb lobe = he.eval(s.wi, s.wo);
    const Rgb mirror = he.mirror_weight(s.wo);
    for (int c = 0; c < 3; ++c) {
      // eval() interpolates the series, S1 and sigma0 from tables good to a relative ~6e-6 of
      // the lobe (see the table tests below).
      EXPECT_LT(relative_error(lobe[c], s.lobe[c]), 2e-5) << "channel " << c;
      // exp(-g_s) with g_s up to ~400 turns a 1e-16 error of g_s into ~1e-13 of the weight.
      EXPECT_LT(relative_error(mirror[c], s.mirror[c]), 1e-10) << "channel " << c;
    }
  }
}

// The example that showed the rough-surface limit to be wrong (hence the test's name): sigma
// 0.7227, tau 12.09, eta 2, g = 23, 35 and 49 in R, G, B, near the lobe's peak. `brdfnav eval`
// gave the rough-surface limit there, 3.4% below the series (red).
// Through the whole closure (rho_d = 0, rho_s = 1, directions normalised as `brdfnav eval` does)
// against the plain lobe; mpmath at 40 digits gives 10.435841278528747, 10.310511681553708 and
// 10.24128658890603.
TEST(He, IssueExampleFollowsTheSeriesThroughTheClosure) {
  Material m = default_material(ModelId::he);
  m.params = {0.7227, 12.09, 2.0};
  m.rho_d = Rgb::Zero();
  m.rho_s = Rgb::Ones();
  const Closure closure = make_closure(m);
  const Vec3 wi = Vec3(-0.42, 0.84, 0.343).normalized(),
             wo = Vec3(0.445, -0.828, 0.34).normalized();
  const Rgb f = closure.eval(wi, wo);
  const std::array<double, 3> expected = plain_lobe(make_he(0.7227, 12.09, 2.0), wi, wo);
  const std::array<double, 3> mpmath{10.435841278528747, 10.310511681553708, 10.24128658890603};
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(relative_error(expected[c], mpmath[c]), 1e-12) << "channel " << c;
    EXPECT_LT(relative_error(f[c], expected[c]), 1e-4) << "channel " << c;
  }
  // The channels differ (their g do), as the rough limit's did not: red over blue is 1.019.
  EXPECT_GT(f[0] / f[2], 1.015);
  // The limit exp(-t/g) / g in place of red's series: 3.4% low.
  const Vec3 v = wi + wo;
  const double g = std::pow(2 * kPi * plain_sigma0(wi, wo, 0.7227, 12.09) * v.z() / 0.645, 2);
  const double t = std::pow(kPi * 12.09 / 0.645, 2) * (v.x() * v.x() + v.y() * v.y());
  EXPECT_NEAR(std::exp(-t / g) / g / static_cast<double>(reference_series(g, t)), 0.966, 1e-3);
}

// eval() against the plain lobe over the parameter ranges, per channel, wherever D's series is
// at least 1e-3 of its peak over directions (its value at vxy = 0 for the same g): smooth to very
// rough lobes (g up to ~8e4), wi drawn from the lobe's own sampler around random wo. Measured:
// at most 4.8e-6 over about 800 comparisons.
TEST(He, EvalFollowsThePlainLobeAcrossTheParameterRanges) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, uniform(rng)); };
  int compared = 0;
  double worst = 0;
  for (int p = 0; p < 60; ++p) {
    const He he = make_he(log_uniform(0.005, 10), log_uniform(0.5, 200), log_uniform(1.1, 15));
    SCOPED_TRACE(::testing::Message()
                 << "sigma " << he.sigma << " tau " << he.tau << " eta " << he.eta);
    for (int k = 0; k < 6; ++k) {
      const Vec3 wo = direction(85 * std::sqrt(uniform(rng)), 360 * uniform(rng));
      const auto wi = he.sample(wo, {uniform(rng), uniform(rng)});
      if (!wi || wi->z() < 0.02) continue;
      const Rgb f = he.eval(*wi, wo);
      const std::array<double, 3> expected = plain_lobe(he, *wi, wo);
      const Vec3 v = *wi + wo;
      const double sigma0 = plain_sigma0(*wi, wo, he.sigma, he.tau);
      for (int c = 0; c < 3; ++c) {
        const double lambda = He::kLambda[c];
        const double g = std::pow(2 * kPi * sigma0 * v.z() / lambda, 2);
        const double t = std::pow(kPi * he.tau / lambda, 2) * (v.x() * v.x() + v.y() * v.y());
        if (reference_series(g, t) < 1e-3 * reference_series(g, 0)) continue;
        const double error = relative_error(f[c], expected[c]);
        worst = std::max(worst, error);
        EXPECT_LT(error, 1e-4) << "g " << g << " t " << t << " channel " << c;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 300);
  RecordProperty("worst", std::to_string(worst));
}

// --- Series.

// The exact series keeps only the terms near its largest one, found by bisection: it must equal
// the reference sum of many more terms, from smooth (g << 1) to very rough (g = 1e6) surfaces.
TEST(He, SeriesMatchesTheReferenceSum) {
  for (double g : {1e-6, 1e-3, 0.1, 0.7, 2.0, 5.0, 10.0, 18.0, 22.0, 60.0, 300.0, 3e3, 1e4, 1e6}) {
    // t from 0 (the peak) to far beyond the lobe; scaled with g once the lobe widens with g.
    for (double ratio : {0.0, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0}) {
      const double t = ratio * std::max(g, 1.0);
      const double expected = static_cast<double>(reference_series(g, t));
      const double value = he_detail::series_sum(Rgb::Constant(g), Rgb::Constant(t))[0];
      EXPECT_LE(std::abs(value - expected), 1e-11 * expected)
          << "g " << g << " t " << t << " value " << value << " expected " << expected;
    }
  }
}

// eval() uses the table: it must follow the exact series over the whole (g, t) range it serves,
// both sides of the small-g switch (0.01), through the seam of its rows (kTableRoughFrom), up to
// g = 1e7 and through the series' tail. The lobe is the sum times smooth factors, so the sum's
// relative error is the lobe's; 1e-5 (the table measures 5.0e-6) keeps the lobe well inside the
// 1e-4 that the renderer's accuracy ratios tolerate. Values below 1e-8 of the peak (t = 0) need
// only be small next to the peak.
TEST(He, TabulatedSeriesMatchesTheExactSeries) {
  for (double g = 1e-4; g <= 1e7; g *= g < 2e3 ? 1.07 : 2.7) {
    const double at_zero = he_detail::series_sum(Rgb::Constant(g), Rgb::Zero())[0];
    for (double t = 0; t < 200 * (g + 1); t = (g < 2e3 ? 1.05 : 1.3) * t + 0.01) {
      const Rgb gg = Rgb::Constant(g), tt = Rgb::Constant(t);
      const double expected = he_detail::series_sum(gg, tt)[0];
      const double value = he_detail::tabulated_series_sum(gg, tt)[0];
      const double tolerance = expected > 1e-8 * at_zero ? 1e-5 * expected : 1e-13 * at_zero;
      ASSERT_LE(std::abs(value - expected), tolerance) << "g " << g << " t " << t;
    }
  }
}

// The requirement per channel: the three channels' sums as eval() forms them (g and t scaled by
// 1 / lambda^2 of each), against the reference sum, for red g from 0.001 to 1e4 (blue 2.1 times
// more) and t over the lobe down to 1e-3 of its peak: within 1e-4 (the table's worst over dense
// sweeps is 5.0e-6, at g ~ 4).
TEST(He, EverySeriesChannelFollowsTheReferenceSum) {
  const Rgb inv_lambda2(1 / std::pow(He::kLambda[0], 2), 1 / std::pow(He::kLambda[1], 2),
                        1 / std::pow(He::kLambda[2], 2));
  int compared = 0;
  for (double g_red = 1e-3; g_red <= 1e4; g_red *= 1.25) {
    const Rgb g = g_red / inv_lambda2[0] * inv_lambda2;
    std::array<double, 3> peak;
    for (int c = 0; c < 3; ++c) peak[c] = static_cast<double>(reference_series(g[c], 0));
    // w = sqrt(t / (g + 1)) of red in steps of 0.1: the lobe falls to 1e-3 by w ~ 2.7.
    for (double w = 0; w < 4; w += 0.1) {
      const Rgb t = w * w * (g_red + 1) / inv_lambda2[0] * inv_lambda2;
      const Rgb value = he_detail::tabulated_series_sum(g, t);
      bool any = false;
      for (int c = 0; c < 3; ++c) {
        const double expected = static_cast<double>(reference_series(g[c], t[c]));
        if (expected < 1e-3 * peak[c]) continue;
        any = true;
        EXPECT_LT(relative_error(value[c], expected), 1e-4)
            << "g " << g[c] << " t " << t[c] << " channel " << c;
        ++compared;
      }
      if (!any) break;
    }
  }
  EXPECT_GT(compared, 1500);
}

// eval() takes the three channels' series four lanes wide where the CPU can: the same
// interpolation as one channel at a time, to rounding, for channels that differ, on both sides
// of the table's seam and far into the rough rows.
TEST(He, SeriesOfTheThreeChannelsAtOnceAreThoseOfEachAlone) {
  if (!cpu_has_avx2_fma()) GTEST_SKIP() << "no AVX2 and FMA: the channels go one at a time";
  int compared = 0;
  for (double g = 0.011; g <= 1e8; g *= 1.13) {
    for (double t = 0; t < 90 * (g + 1); t = 1.2 * t + 0.03) {
      const Rgb gg(g, 1.5 * g, 1.2 * g), tt(t, 0.7 * t, 1.1 * t);
      const Rgb together = he_detail::tabulated_series_sums(gg, gg.log(), tt);
      for (int c = 0; c < 3; ++c) {
        const double alone = he_detail::tabulated_series_sum(gg[c], std::log(gg[c]), tt[c]);
        ASSERT_NEAR(together[c], alone, 1e-12 * alone) << "g " << gg[c] << " t " << tt[c];
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

// S1 multiplies the lobe (relative error passes through); erfc enters through K = tan erfc and
// y = (K_i + K_o) / sqrt(8 pi), whose absolute error moves sigma0 by less, and g ~ sigma0^2
// by twice as much relatively, amplified by d ln S / d ln g (up to ~30 in the tails).
TEST(He, TabulatedShadowingAndRoughnessMatchTheExactForms) {
  for (double a = 1e-6; a < he_detail::kShadowTableEnd; a += 1e-3) {
    const he_detail::Shadowing exact = he_detail::exact_shadowing(a);
    const he_detail::Shadowing table = he_detail::tabulated_shadowing(a);
    ASSERT_LT(relative_error(table.s1, exact.s1), 1e-8) << "a " << a;
    ASSERT_LT(std::abs(table.erfc - exact.erfc), 1e-9) << "a " << a;
  }
  // 1 - S1 and erfc at the table's end: what eval() neglects beyond it.
  const he_detail::Shadowing end = he_detail::exact_shadowing(he_detail::kShadowTableEnd);
  EXPECT_LT(1 - end.s1, 1e-16);
  EXPECT_LT(end.erfc, 3e-17);
  for (double y = 0; y < 1e4; y = 1.01 * y + 1e-4) {
    ASSERT_LT(relative_error(he_detail::tabulated_sigma0_ratio(y), he_detail::sigma0_ratio(y)),
              1e-8)
        << "y " << y;
  }
}

// Why eval() sums the series at every g: its rough-surface limit exp(-t/g) / g is only first
// order. With c = t / g the series is the limit times 1 + (c^2 - 4 c + 2) / (2 g) + O(1/g^2)
// (the second Laguerre polynomial of c, over g; the 1/g^2 term is c^4/8 - 11 c^3/6 + 15 c^2/2
// - 9 c + 2, within 3 + c^4 / 4): the limit is about 1/g low at the lobe's centre (6% at g = 16),
// high around c = 2, further off in the tail, and it makes the three channels equal.
TEST(He, RoughLimitIsOnlyFirstOrderInOneOverG) {
  for (double g : {16.0, 50.0, 300.0, 3e3, 1e4}) {
    for (double c : {0.0, 0.1, 0.5, 1.0, 2.0, 3.4, 5.0, 7.0}) {
      const double series = static_cast<double>(reference_series(g, c * g));
      const double limit = std::exp(-c) / g;
      EXPECT_NEAR(series / limit - 1, (c * c - 4 * c + 2) / (2 * g),
                  (3 + std::pow(c, 4) / 4) / (g * g))
          << "g " << g << " c " << c;
    }
  }
}

// The table's rows change coordinate at kTableRoughFrom (ln g below, (kTableRoughFrom / g)^(1/4)
// above, the two with the same slope there): the sum is as smooth across it as elsewhere.
TEST(He, TabulatedSeriesIsContinuousAcrossTheRowSeam) {
  for (double t_over_g : {0.0, 1.0, 3.0}) {
    const double step = 1e-3, from = he_detail::kTableRoughFrom - 1;
    auto sum = [&](double g) {
      return he_detail::tabulated_series_sum(Rgb::Constant(g), Rgb::Constant(t_over_g * g))[0];
    };
    for (double g = from; g < he_detail::kTableRoughFrom + 1; g += step) {
      // Second differences along t = r g: at most 8e-9 measured (step^2 times the second
      // derivative), while a jump of the size of the table's errors (1e-6) would show whole.
      const double curvature = (sum(g + step) - 2 * sum(g) + sum(g - step)) / sum(g);
      EXPECT_LT(std::abs(curvature), 1e-7) << "g " << g << " t/g " << t_over_g;
    }
  }
}

// As g grows (sigma >> lambda) the lobe becomes the Beckmann microfacet lobe with m = 2 sigma0 /
// tau; here m = 0.2 throughout (tau = 10 sigma) while g at the mirror grows from ~0.3 to several
// thousand.
TEST(He, RoughLimitIsABeckmannLobe) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> worst;
  for (double sigma : {0.06, 0.12, 0.18, 0.36, 1.0, 4.0}) {
    const He he = make_he(sigma, 10 * sigma, 1.5);
    double deviation = 0;
    for (int n = 0; n < 400; ++n) {
      // Drawn one by one: a function's arguments are evaluated in an order each compiler picks.
      const double theta_o = 60 * uniform(rng), phi_o = 360 * uniform(rng);
      const Vec3 wo = direction(theta_o, phi_o);
      // wi within about 1.4 Beckmann widths of the mirror half vector (the bulk of the lobe).
      const double tan_h = 0.2 * std::sqrt(2.0 * uniform(rng));
      const Vec3 h = spherical_direction(tan_h / std::hypot(1.0, tan_h),
                                         1.0 / std::hypot(1.0, tan_h), 2 * kPi * uniform(rng));
      const Vec3 wi = reflect(wo, h);
      if (wi.z() < 0.1) continue;
      const double expected = beckmann_form(he, wi, wo);
      const Rgb value = he.eval(wi, wo);
      for (int c = 0; c < 3; ++c) {
        deviation = std::max(deviation, relative_error(value[c], expected));
      }
    }
    worst.push_back(deviation);
  }
  // The deviation shrinks as g grows. At the mirror g_red = (4 pi sigma0 cos / 0.645)^2, where
  // sigma0 <= sigma is the roughness the shadowing leaves, smallest for grazing wi: sigma
  // 0.06..0.18 covers g ~ 0.3..12 where the series is far from its limit; from sigma 0.36 on
  // only the series' O(1/g) terms remain, (c^2 - 4 c + 2) / (2 g) with c = t / g <= 2 here (see
  // RoughLimitIsOnlyFirstOrderInOneOverG). Measured over these 400 directions: 0.17 at sigma
  // 0.36, 0.022 at sigma 1 and 0.0022 at sigma 4 (its worst at wi 84 degrees from the normal,
  // where sigma0 is smallest), 16 times g: falling like 1/g, less the shadowing's share.
  for (std::size_t k = 1; k < worst.size(); ++k) EXPECT_LT(worst[k], worst[k - 1]) << k;
  EXPECT_LT(worst[3], 0.2);
  EXPECT_LT(worst[4], 0.03);
  EXPECT_LT(worst[5], 0.003);
  EXPECT_GT(worst[4] / worst[5], 8);
}

// The table's rows change coordinate at kTableRoughFrom (about 18): the lobe has no step there.
TEST(He, LobeIsContinuousWhenSigmaSweepsThroughTheTableSeam) {
  // g at the mirror for wo at 30 degrees: (4 pi sigma cos / lambda)^2; sigma 0.08..0.3 takes it
  // from 1.8 to 26 (red) and from 3.8 to 54 (blue): every channel crosses the seam.
  const Vec3 wo = direction(30, 0);
  const Vec3 wi = reflect(wo, direction(3, 90));
  const double ratio = 1.0005;
  Rgb previous = make_he(0.08, 4, 1.5).eval(wi, wo);
  for (double sigma = 0.08 * ratio; sigma < 0.3; sigma *= ratio) {
    const Rgb value = make_he(sigma, 4, 1.5).eval(wi, wo);
    for (int c = 0; c < 3; ++c) {
      // d ln f / d ln sigma is O(1) here, so a 0.05% step moves f by ~0.1%; a switch to another
      // form of the sum would jump by up to several percent.
      EXPECT_LT(relative_error(value[c], previous[c]), 5e-3) << "sigma " << sigma << " c " << c;
    }
    previous = value;
  }
}

// --- Robustness.

// Directions that stress the edge cases: normal incidence (cot = inf), grazing and on the
// horizon, tiny and denormal z, wi = -wo in the plane (h degenerate).
std::vector<Vec3> edge_directions() {
  const double tiny = 1e-300, denormal = 4.9e-324;
  return {Vec3(0, 0, 1),
          Vec3(1, 0, 0),
          Vec3(-1, 0, 0),
          Vec3(0, 1, 0),
          Vec3(1, 0, tiny),
          Vec3(-1, 0, tiny),
          Vec3(1, 0, denormal),
          Vec3(std::sqrt(1 - 1e-24), 0, 1e-12),
          Vec3(-std::sqrt(1 - 1e-24), 0, 1e-12),
          direction(89.999, 45),
          direction(1e-9, 10),
          Vec3(0, 0, -1)};
}

TEST(He, FiniteNonNegativeAndReciprocalEverywhere) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, uniform(rng)); };
  const std::vector<Vec3> edges = edge_directions();
  for (int p = 0; p < 300; ++p) {
    const He he = make_he(log_uniform(1e-3, 10), log_uniform(0.1, 500), log_uniform(1.01, 20));
    SCOPED_TRACE(::testing::Message()
                 << "sigma " << he.sigma << " tau " << he.tau << " eta " << he.eta);
    std::vector<Vec3> dirs = edges;
    for (int k = 0; k < 20; ++k)
      dirs.push_back(sample_cosine_hemisphere({uniform(rng), uniform(rng)}));
    for (const Vec3& wo : dirs) {
      const Rgb mirror = he.mirror_weight(wo);
      EXPECT_TRUE(mirror.isFinite().all() && (mirror >= 0).all() && (mirror <= 1).all());
      const double hint = he.albedo_hint(wo);
      EXPECT_TRUE(std::isfinite(hint) && hint >= 0);
      const auto sampled = he.sample(wo, {uniform(rng), uniform(rng)});
      if (sampled) {
        EXPECT_GT(sampled->z(), 0);
        EXPECT_NEAR(sampled->norm(), 1.0, 1e-9);
      }
      for (const Vec3& wi : dirs) {
        const Rgb f = he.eval(wi, wo);
        ASSERT_TRUE(f.isFinite().all() && (f >= 0).all())
            << wi.transpose() << " | " << wo.transpose();
        const double pdf = he.pdf(wi, wo);
        ASSERT_TRUE(std::isfinite(pdf) && pdf >= 0);
        if (wi.z() <= 0 || wo.z() <= 0) {
          EXPECT_TRUE((f == 0).all() && pdf == 0);
        }
        // Every quantity is formed symmetrically in (wi, wo), so this holds to the bit; bind()
        // computes the same terms once.
        const Rgb g = he.eval(wo, wi), bound = he.bind(wo).eval(wi);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(f[c], g[c]);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(f[c], bound[c]);
      }
    }
  }
}

// --- Integrals over the hemisphere.

// Integral of fn(wi) over the upper hemisphere, by the midpoint rule in half-vector
// coordinates around the normal: h has slope p = width tan(v), v in [0, pi/2), azimuth phi, and
// wi = reflect(wo, h) with dwi = 4 (wo.h) dw_h. Lobes of any narrowness around the mirror
// direction are resolved when `width` is about their slope width.
template <typename T, typename Fn>
T hemisphere_integral(const Vec3& wo, double width, T zero, Fn&& fn, int nv = 192, int nphi = 96) {
  T total = zero;
  for (int i = 0; i < nv; ++i) {
    const double v = (i + 0.5) / nv * (kPi / 2);
    const double p = width * std::tan(v);
    // dw_h = p / (1 + p^2)^(3/2) dp dphi, dp = width / cos^2(v) dv.
    const double jacobian = p / std::pow(1 + p * p, 1.5) * width / (std::cos(v) * std::cos(v));
    for (int j = 0; j < nphi; ++j) {
      const double phi = (j + 0.5) / nphi * 2 * kPi;
      const Vec3 h = Vec3(p * std::cos(phi), p * std::sin(phi), 1.0).normalized();
      const double wo_h = wo.dot(h);
      if (wo_h <= 0) continue;
      const Vec3 wi = reflect(wo, h);
      if (wi.z() <= 0) continue;
      total += fn(wi) * (4 * wo_h * jacobian);
    }
  }
  return total * ((kPi / 2 / nv) * (2 * kPi / nphi));
}

// Slope width of the lobe near the mirror: the rough width 2 sigma / tau or the smooth-surface
// width lambda_red / (2 pi tau cos_o), whichever is larger.
double lobe_width(const He& he, const Vec3& wo) {
  return std::min(std::hypot(2 * he.sigma / he.tau, 0.645 / (2 * kPi * he.tau * wo.z())), 1.0);
}

TEST(He, DirectionalAlbedoWithMirrorIsAtMostOne) {
  for (double sigma : {1e-3, 0.02, 0.16, 1.28, 10.0}) {
    for (double tau : {0.1, 2.0, 32.0, 500.0}) {
      for (double eta : {1.5, 20.0}) {
        const He he = make_he(sigma, tau, eta);
        for (double theta_o : {0.0, 60.0, 85.0}) {
          const Vec3 wo = direction(theta_o, 0);
          const Rgb albedo = he.mirror_weight(wo) +
                             hemisphere_integral(
                                 wo, lobe_width(he, wo), Rgb::Zero().eval(),
                                 [&](const Vec3& wi) { return (he.eval(wi, wo) * wi.z()).eval(); });
          // The He lobe stays close to F(cos_o) (<= 0.82 here), so 1e-3 of quadrature error at the
          // horizon cut is plenty of margin.
          EXPECT_LE(albedo.maxCoeff(), 1.0 + 1e-3)
              << "sigma " << sigma << " tau " << tau << " eta " << eta << " theta_o " << theta_o;
        }
      }
    }
  }
}

// --- Mirror term.

TEST(He, MirrorWeightTendsToFresnelWhenSmoothAndToZeroWhenRough) {
  for (double theta : {0.0, 30.0, 60.0, 80.0}) {
    const Vec3 wo = direction(theta, 40);
    const double fresnel = plain_fresnel(wo.z(), 1.5);
    // sigma = 1e-3: g_s = (4 pi sigma cos / lambda)^2 <= 8e-4 and S = 1 (a = tau cot / 2 sigma
    // is huge), so the weight is F exp(-g_s) = F within 1e-3.
    const Rgb smooth = make_he(1e-3, 10, 1.5).mirror_weight(wo);
    for (int c = 0; c < 3; ++c) EXPECT_LT(relative_error(smooth[c], fresnel), 1e-3);
    // Blue loses most (largest g_s).
    EXPECT_GT(smooth[0], smooth[2]);
    double previous = fresnel;
    for (double sigma : {0.01, 0.05, 0.2, 1.0}) {
      const double weight = make_he(sigma, 10, 1.5).mirror_weight(wo)[1];
      EXPECT_LT(weight, previous) << "sigma " << sigma;
      previous = weight;
    }
    // sigma = 2: g_s = (4 pi sigma0 cos / lambda)^2 >= 27 (red at 80 degrees, where shadowing
    // lowers sigma0 to 0.77 sigma).
    EXPECT_LT(make_he(2.0, 10, 1.5).mirror_weight(wo).maxCoeff(), 1e-11);
  }
}

// --- Sampling.

struct SamplingCase {
  double sigma, tau, eta, theta_o;
};
// Moderately wide lobes (so that a theta/phi histogram resolves them), covering the smooth
// regime (small g: width ~ lambda / (2 pi tau cos_o)), the rough regime, a clamped very rough
// lobe and grazing view.
const std::array<SamplingCase, 5> kSamplingCases{{
    {0.05, 2.0, 1.5, 60.0},
    {0.4, 4.0, 1.5, 30.0},
    {0.3, 2.0, 4.0, 80.0},
    {2.0, 2.0, 1.5, 45.0},
    {0.1, 1.0, 1.5, 0.0},
}};

TEST(He, PdfIntegratesToTheFractionOfValidSamples) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const SamplingCase& s : kSamplingCases) {
    const He he = make_he(s.sigma, s.tau, s.eta);
    const Vec3 wo = direction(s.theta_o, 20);
    const double integral = hemisphere_integral(
        wo, lobe_width(he, wo), 0.0, [&](const Vec3& wi) { return he.pdf(wi, wo); }, 384, 192);
    const int n = 40000;
    int valid = 0;
    for (int k = 0; k < n; ++k) valid += he.sample(wo, {uniform(rng), uniform(rng)}).has_value();
    const double fraction = static_cast<double>(valid) / n;
    EXPECT_LE(integral, 1.0 + 1e-3);
    // 4 binomial standard deviations plus 2e-3 of quadrature error.
    const double tolerance = 4 * std::sqrt(fraction * (1 - fraction) / n) + 2e-3;
    EXPECT_NEAR(integral, fraction, tolerance) << "sigma " << s.sigma << " theta_o " << s.theta_o;
  }
}

// Chi-square of sample() against pdf() on a theta/phi histogram of wi.
TEST(He, SamplesFollowThePdf) {
  constexpr int kTheta = 16, kPhi = 32, kSub = 12, kSamples = 200000;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const SamplingCase& s : kSamplingCases) {
    SCOPED_TRACE(::testing::Message() << "sigma " << s.sigma << " theta_o " << s.theta_o);
    const He he = make_he(s.sigma, s.tau, s.eta);
    const Vec3 wo = direction(s.theta_o, 20);
    auto bin_of = [&](const Vec3& w) {
      const int i = std::min(static_cast<int>(std::acos(w.z()) / (kPi / 2) * kTheta), kTheta - 1);
      double phi = std::atan2(w.y(), w.x());
      if (phi < 0) phi += 2 * kPi;
      return i * kPhi + std::min(static_cast<int>(phi / (2 * kPi) * kPhi), kPhi - 1);
    };
    std::vector<double> observed(kTheta * kPhi, 0.0), expected(kTheta * kPhi, 0.0);
    for (int k = 0; k < kSamples; ++k) {
      if (const auto wi = he.sample(wo, {uniform(rng), uniform(rng)})) observed[bin_of(*wi)] += 1;
    }
    // Expected counts: the pdf integrated over each bin (midpoint rule, kSub^2 points per bin).
    const double d_theta = kPi / 2 / (kTheta * kSub), d_phi = 2 * kPi / (kPhi * kSub);
    for (int i = 0; i < kTheta * kSub; ++i) {
      const double theta = (i + 0.5) * d_theta;
      for (int j = 0; j < kPhi * kSub; ++j) {
        const Vec3 wi = spherical_direction(std::sin(theta), std::cos(theta), (j + 0.5) * d_phi);
        expected[(i / kSub) * kPhi + j / kSub] +=
            he.pdf(wi, wo) * std::sin(theta) * d_theta * d_phi * kSamples;
      }
    }
    // Bins expecting fewer than 5 samples are pooled into one.
    double chi2 = 0, pooled_observed = 0, pooled_expected = 0;
    int dof = 0;
    for (std::size_t b = 0; b < observed.size(); ++b) {
      if (expected[b] < 5) {
        pooled_observed += observed[b];
        pooled_expected += expected[b];
        continue;
      }
      chi2 += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
      ++dof;
    }
    if (pooled_expected >= 5) {
      chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
              pooled_expected;
      ++dof;
    }
    ASSERT_GT(dof, 20);
    --dof;
    // Wilson-Hilferty quantile of chi-square(dof) at z = 4 (p ~ 3e-5 per case).
    const double k = 2.0 / (9.0 * dof);
    const double critical = dof * std::pow(1 - k + 4.0 * std::sqrt(k), 3);
    EXPECT_LT(chi2, critical) << "dof " << dof;
  }
}

}  // namespace
}  // namespace brdfnav
