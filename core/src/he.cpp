// He, Torrance, Sillion, Greenberg 1991, unpolarised, exactly as the He section of
// docs/CLOSURES.md (The formulas) writes it: directional-diffuse lobe F S G D / (pi cos_i cos_o)
// plus a mirror term F exp(-g_s) S.
#include <brdfnav/core/he.h>

#include "he_tables.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace brdfnav {

namespace {
// Per-channel 1 / lambda^2 (micrometres^-2) and its logarithm.
const Rgb& inv_lambda_squared() {
  static const Rgb k = [] {
    const Rgb lambda(He::kLambda[0], He::kLambda[1], He::kLambda[2]);
    return Rgb((lambda * lambda).inverse());
  }();
  return k;
}
const Rgb& log_inv_lambda_squared() {
  static const Rgb log_k = inv_lambda_squared().log();
  return log_k;
}
}  // namespace

namespace he_detail {

namespace {
// Terms below exp(-kLogTolerance) of the largest are left out. The terms are log-concave in m, so
// those beyond the cut on either side add less than it times the terms' spread in m over
// sqrt(2 kLogTolerance) (or times 1 / (1 - their ratio) for small g): below 1e-13 of the sum.
constexpr double kLogTolerance = 30.0;

// The terms a_m = P_m exp(-t/m) / m, P_m = exp(-g) g^m / m! the Poisson weights, are log-concave
// in m (each factor is): the largest is found by bisection on the sign of ln a_{m+1} - ln a_m
// (near the Poisson mode m ~ g for t = 0, further up in the lobe's tail), and the terms are summed
// outward from it in log space until they fall below exp(-kLogTolerance) of it.
double channel_series_sum(double g, double t) {
  if (!(g > 0)) return 0.0;
  t = std::max(t, 0.0);
  if (!(t < 1e300)) return 0.0;  // every exp(-t/m) underflows (and +inf would not bisect)
  const double log_g = std::log(g);
  auto log_term = [&](double m) { return log_poisson(m, g, log_g) - std::log(m) - t / m; };
  // ln a_{m+1} - ln a_m decreases in m and is negative beyond 3 g + sqrt(t) + 10, where
  // ln g + ln m - 2 ln(m + 1) < -ln 3 and t / (m (m + 1)) < 1.
  double lo = 1, hi = std::ceil(3 * g + std::sqrt(t) + 10);
  while (lo < hi) {
    const double mid = std::floor(0.5 * (lo + hi));
    if (log_term(mid + 1) > log_term(mid)) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  const double log_cut = log_term(lo) - kLogTolerance;
  double sum = 0.0;
  for (double m = lo; m >= 1; --m) {
    const double l = log_term(m);
    if (l < log_cut) break;
    sum += std::exp(l);
  }
  for (double m = lo + 1;; ++m) {
    const double l = log_term(m);
    if (l < log_cut) break;
    sum += std::exp(l);
  }
  return sum;
}
}  // namespace

Rgb series_sum(const Rgb& g, const Rgb& t) {
  return Rgb(channel_series_sum(g[0], t[0]), channel_series_sum(g[1], t[1]),
             channel_series_sum(g[2], t[2]));
}

Rgb tabulated_series_sum(const Rgb& g, const Rgb& t) {
  return tabulated_series_sums(g, g.log(), t);
}

namespace {
// tabulated_series_sum() of g = g_scale / lambda^2 and t = t_scale / lambda^2 per channel, with
// one log() for the three ln(g). Every channel is summed for its own g: no rough-surface limit.
Rgb series_sum_per_wavelength(double g_scale, double t_scale) {
  const Rgb& k = inv_lambda_squared();
  return tabulated_series_sums(g_scale * k, std::log(g_scale) + log_inv_lambda_squared(),
                               t_scale * k);
}
}  // namespace

}  // namespace he_detail

namespace {

// Cosines are floored here: S1 ~ cos near grazing cancels the 1/cos of the lobe, and the floor
// keeps that cancellation free of 0/0 and overflow for directions on (or rounding onto) the
// horizon.
constexpr double kMinCos = 1e-10;

// Sampling: a Beckmann half-vector lobe (see sampling_slopes) mixed with a kWideFactor times wider
// one, which covers the lobe's heavier tails (its Poisson components with m above g) and the
// shapes that are not Beckmann-like (grazing views, where vz varies across the lobe).
constexpr double kWideFraction = 0.2;
constexpr double kWideFactor = 2.5;
constexpr double kMinSlope = 1e-5;
constexpr double kMaxSlope = 1.0;
constexpr double kMaxWideSlope = 2.5;

// Shadowing S1(theta) and K(theta) = tan(theta) erfc(a) of one direction, a = tau cot / (2 sigma).
struct AngleTerms {
  double shadowing;  // S1
  double k;          // K
};

// With exact_shadowing (the mirror term, sampling) or tabulated_shadowing (eval), which are 1 and
// 0 from a_end on. That also covers normal incidence, where cot(theta) is infinite.
template <typename Shadow>
AngleTerms angle_terms(double cos_theta, double sin_theta, const He& he, double a_end,
                       Shadow&& shadow) {
  const double denom = 2.0 * he.sigma * sin_theta;
  if (he.tau * cos_theta >= a_end * denom) return {1.0, 0.0};
  const he_detail::Shadowing s = shadow(he.tau * cos_theta / denom);
  return {s.s1, sin_theta / cos_theta * s.erfc};
}

// sigma0 = sigma / sqrt(1 + x^2) with x = z0 / sigma from K_i + K_o; `ratio` is the exact or the
// tabulated 1 / sqrt(1 + x^2) as a function of y = (K_i + K_o) / sqrt(8 pi).
template <typename Ratio>
double effective_sigma(double sigma, double k_sum, Ratio&& ratio) {
  return k_sum > 0 ? sigma * ratio(k_sum / std::sqrt(8.0 * kPi)) : sigma;
}

double floored_cos(const Vec3& w) {
  return std::max(w.z(), kMinCos);
}
double sin_theta(const Vec3& w) {
  return std::sqrt(w.x() * w.x() + w.y() * w.y());
}

// Quantities of the mirror configuration wi = (-wo.x, -wo.y, wo.z), where theta_i = theta_o.
struct MirrorTerms {
  double cos;
  double fresnel;
  double s1;  // S1(theta_o); the mirror's S is its square
  double sigma0;
};

MirrorTerms mirror_terms(const He& he, const Vec3& wo) {
  const double cos_o = floored_cos(wo);
  const AngleTerms t =
      angle_terms(cos_o, sin_theta(wo), he, he_detail::kUnshadowedA, he_detail::exact_shadowing);
  return {cos_o, fresnel_dielectric(cos_o, he.eta), t.shadowing,
          effective_sigma(he.sigma, 2.0 * t.k, he_detail::sigma0_ratio)};
}

// g at the mirror direction per channel: (4 pi sigma0 cos / lambda)^2.
Rgb mirror_g(const MirrorTerms& m) {
  const double s = 4.0 * kPi * m.sigma0 * m.cos;
  return inv_lambda_squared() * (s * s);
}

// Beckmann slopes of the two sampling lobes at wo. The lobe is a Poisson mixture of Gaussians in
// the half-vector slope, the m-th of width sqrt(m) lambda / (pi tau vz): near the mirror
// (vz = 2 cos_o) the first has width lambda / (2 pi tau cos_o) (the smooth-surface lobe) and the
// mixture tends to width 2 sigma0 / tau (the rough limit) for large g. Their quadrature sum
// covers both regimes; the longest wavelength gives the widest, safest lobe.
std::array<double, 2> sampling_slopes(const He& he, const Vec3& wo) {
  const MirrorTerms mirror = mirror_terms(he, wo);
  const double rough = 2.0 * mirror.sigma0 / he.tau;
  const double smooth = He::kLambda[0] / (2.0 * kPi * he.tau * mirror.cos);
  const double m = std::clamp(std::hypot(rough, smooth), kMinSlope, kMaxSlope);
  return {m, std::min(kWideFactor * m, kMaxWideSlope)};
}

}  // namespace

He::DirectionTerms He::direction_terms(const Vec3& w) const {
  const double cos = floored_cos(w);
  const AngleTerms t = angle_terms(cos, sin_theta(w), *this, he_detail::kShadowTableEnd,
                                   he_detail::tabulated_shadowing);
  return {w, cos, t.shadowing, t.k};
}

Rgb He::eval(const Vec3& wi, const Vec3& wo) const {
  if (wi.z() <= 0 || wo.z() <= 0) return Rgb::Zero();
  return lobe(direction_terms(wi), direction_terms(wo));
}

Rgb He::Bound::eval(const Vec3& wi) const {
  if (wi.z() <= 0 || wo.w.z() <= 0) return Rgb::Zero();
  return he.lobe(he.direction_terms(wi), wo);
}

void He::Bound::eval_fresnel(const Vec3& wi, std::span<const double> etas, Rgb* out) const {
  if (wi.z() <= 0 || wo.w.z() <= 0) {
    std::fill(out, out + etas.size(), Rgb::Zero());
    return;
  }
  const LobeTerms t = he.lobe_terms(he.direction_terms(wi), wo);
  for (std::size_t k = 0; k < etas.size(); ++k) out[k] = lobe_with_eta(t, etas[k]);
}

Rgb He::lobe(const DirectionTerms& i, const DirectionTerms& o) const {
  return lobe_with_eta(lobe_terms(i, o), eta);
}

He::LobeTerms He::lobe_terms(const DirectionTerms& i, const DirectionTerms& o) const {
  // Every quantity below is computed symmetrically in (i, o): reciprocity holds to the bit.
  const double vx = i.w.x() + o.w.x(), vy = i.w.y() + o.w.y();
  const double vxy2 = vx * vx + vy * vy;
  const double vz = i.cos + o.cos;
  const double v2 = vxy2 + vz * vz;
  const double sigma0 = effective_sigma(sigma, i.k + o.k, he_detail::tabulated_sigma0_ratio);
  LobeTerms t;
  // For unit wi, wo: wi.h = (1 + wi.wo) / |wi + wo| = |wi + wo| / 2 (no degenerate h needed).
  t.fresnel_cos = std::min(0.5 * std::sqrt(v2), 1.0);
  t.geometry = (v2 / vz) * (v2 / vz);
  // Products of an i and an o factor are formed first: commutative, hence bitwise symmetric.
  t.shadowing = i.shadowing * o.shadowing;
  t.denominator = kPi * (i.cos * o.cos);

  // Per channel: g = (2 pi sigma0 vz / lambda)^2, t = pi^2 tau^2 vxy^2 / lambda^2 and D's prefactor
  // pi^2 tau^2 / (4 lambda^2).
  const double g_scale = (2.0 * kPi * sigma0 * vz) * (2.0 * kPi * sigma0 * vz);
  const double tau_scale = kPi * kPi * tau * tau;
  t.prefactor = 0.25 * tau_scale;
  t.sum = he_detail::series_sum_per_wavelength(g_scale, tau_scale * vxy2);
  return t;
}

Rgb He::lobe_with_eta(const LobeTerms& t, double eta) {
  const double fresnel = fresnel_dielectric(t.fresnel_cos, eta);
  const double common = fresnel * t.shadowing * t.geometry / t.denominator;
  return common * t.prefactor * inv_lambda_squared() * t.sum;
}

Rgb He::mirror_weight(const Vec3& wo) const {
  if (wo.z() <= 0) return Rgb::Zero();
  const MirrorTerms m = mirror_terms(*this, wo);
  return m.fresnel * m.s1 * m.s1 * (-mirror_g(m)).exp();
}

// The lobe carries roughly the part of F that the mirror term does not, (1 - exp(-g_s)) F, shadowed
// by S1(theta_o) on the way out; S1(theta_i) is left out, since most of the lobe is reflected
// away from grazing even when wo is grazing. The green channel stands for all three (a hint).
double He::albedo_hint(const Vec3& wo) const {
  if (wo.z() <= 0) return 0.0;
  const MirrorTerms m = mirror_terms(*this, wo);
  return m.fresnel * m.s1 * -std::expm1(-mirror_g(m)[1]);
}

std::optional<Vec3> He::sample(const Vec3& wo, const Vec2& u) const {
  if (wo.z() <= 0) return std::nullopt;
  const auto slopes = sampling_slopes(*this, wo);
  // u[0] picks the lobe and is rescaled to [0, 1) for the lobe's own use.
  const double main_fraction = 1.0 - kWideFraction;
  const bool wide = u[0] >= main_fraction;
  const Vec2 v(wide ? (u[0] - main_fraction) / kWideFraction : u[0] / main_fraction, u[1]);
  return reflect_about_half(wo, sample_beckmann(v, slopes[wide ? 1 : 0]));
}

double He::pdf(const Vec3& wi, const Vec3& wo) const {
  if (wi.z() <= 0 || wo.z() <= 0) return 0.0;
  const auto h = half_vector(wi, wo);
  // Sampled half vectors have cos_h > 0.06 (tan^2 <= 37 m^2, m <= 2.5); the guard also keeps
  // beckmann_d away from cos_h^2 underflowing to 0 (0/0).
  if (!h || h->z() < kMinCos) return 0.0;
  const auto slopes = sampling_slopes(*this, wo);
  const double pdf_h = ((1.0 - kWideFraction) * beckmann_d(h->z(), slopes[0]) +
                        kWideFraction * beckmann_d(h->z(), slopes[1])) *
                       h->z();
  // dw_h / dw_i = 1 / (4 wo.h), with wo.h floored like the cosines: finite for grazing wo.
  const double wo_h = wo.dot(*h);
  return wo_h > 0 ? pdf_h / (4.0 * std::max(wo_h, kMinCos)) : 0.0;
}

}  // namespace brdfnav
