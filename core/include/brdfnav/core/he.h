// He, Torrance, Sillion, Greenberg 1991 (unpolarised): directional-diffuse lobe plus a mirror
// (delta) term, as fixed in docs/CLOSURES.md (The formulas).
#pragma once

#include <brdfnav/core/microfacet.h>
#include <brdfnav/core/params.h>

#include <array>
#include <span>

namespace brdfnav {

struct He {
  static constexpr std::array<double, 5> kEtaNodes{1.2, 1.5, 2.0, 4.0, 9.0};
  static constexpr std::string_view kName = "he";
  static constexpr std::string_view kTitle = "He et al.";
  static constexpr std::array<ParamSpec, 3> kParams{{
      {.name = "sigma",
       .unit = "um",
       .description = "RMS surface height",
       .valid_min = 1e-3,
       .valid_max = 10.0,
       .default_value = 0.16,
       .grid_min = 0.02,
       .grid_max = 2.56,
       .grid_count = 8,
       .scale = Scale::log,
       .more = "rougher",
       .less = "glossier"},
      {.name = "tau",
       .unit = "um",
       .description = "surface autocorrelation length",
       .valid_min = 0.1,
       .valid_max = 500.0,
       .default_value = 8.0,
       .grid_min = 2.0,
       .grid_max = 128.0,
       .grid_count = 9,
       .scale = Scale::log,
       .more = "sharper",
       .less = "blurrier"},
      {.name = "eta",
       .unit = "1",
       .description = "real refractive index",
       .valid_min = 1.01,
       .valid_max = 20.0,
       .default_value = 1.5,
       .grid_min = 1.2,
       .grid_max = 9.0,
       .grid_count = 5,
       .scale = Scale::log,
       .nodes = kEtaNodes,
       .more = "more reflective",
       .less = "less reflective"},
  }};
  // Wavelengths (micrometres) of the R, G, B channels.
  static constexpr std::array<double, 3> kLambda{0.645, 0.526, 0.444};

  double sigma, tau, eta;

  explicit He(std::span<const double> p) : sigma(p[0]), tau(p[1]), eta(p[2]) {}
  bool operator==(const He&) const = default;

  // The factors of eval() that depend on one direction alone.
  struct DirectionTerms {
    Vec3 w;
    double cos;        // floored, see he.cpp
    double shadowing;  // S1(theta)
    double k;          // K(theta) = tan(theta) erfc(a)
  };
  // eval() at one wo with wo's terms computed once, for many wi (the renderer's quadrature):
  // bind(wo).eval(wi) equals eval(wi, wo) to the bit.
  struct Bound {
    const He& he;
    DirectionTerms wo;
    Rgb eval(const Vec3& wi) const;
    // eval(wi) of the lobes that differ from `he` in eta alone, etas[k] for out[k]: all but the
    // Fresnel factor computed once. out[k] equals He{sigma, tau, etas[k]}.bind(wo).eval(wi) to
    // the bit.
    void eval_fresnel(const Vec3& wi, std::span<const double> etas, Rgb* out) const;
  };

  // Directional-diffuse term only (the mirror term is a delta: see mirror_weight()).
  Rgb eval(const Vec3& wi, const Vec3& wo) const;
  Bound bind(const Vec3& wo) const { return {*this, direction_terms(wo)}; }
  // Reflects wo about a Beckmann half vector (a mixture of two slopes chosen from sigma0 at wo,
  // tau and lambda); pdf() is the exact density of the directions it returns.
  std::optional<Vec3> sample(const Vec3& wo, const Vec2& u) const;
  double pdf(const Vec3& wi, const Vec3& wo) const;
  // Rough estimate of the lobe's albedo at wo, (1 - exp(-g_s)) F S1(theta_o) with the green g_s,
  // for choosing between sampling strategies.
  double albedo_hint(const Vec3& wo) const;
  // Reflectance of the mirror term at wo, per channel: F(cos_o) exp(-g_s) S.
  Rgb mirror_weight(const Vec3& wo) const;

 private:
  // The factors of the lobe at one (wi, wo) but the Fresnel one, which alone depends on eta.
  struct LobeTerms {
    double fresnel_cos;  // wi.h
    double shadowing, geometry, denominator;
    double prefactor;  // of D, without 1 / lambda^2
    Rgb sum;           // D's sum, per channel
  };
  DirectionTerms direction_terms(const Vec3& w) const;
  // The lobe from both directions' terms, formed symmetrically: lobe(i, o) == lobe(o, i).
  Rgb lobe(const DirectionTerms& i, const DirectionTerms& o) const;
  LobeTerms lobe_terms(const DirectionTerms& i, const DirectionTerms& o) const;
  static Rgb lobe_with_eta(const LobeTerms& t, double eta);
};

// The sum over m in He's distribution D (without the pi^2 tau^2 / (4 lambda^2) prefactor), per
// channel, with t = pi^2 tau^2 vxy^2 / lambda^2, and the factors that eval() tabulates. Exposed
// so that tests can compare the tables with the exact forms.
namespace he_detail {
// sum_{m>=1} exp(-g) g^m / (m! m) exp(-t / m), summed term by term in log space outward from its
// largest term (near the Poisson mode m ~ g, further up in the lobe's tail) until the terms fall
// below exp(-30) of it: to a relative 1e-11 for g up to 1e6 (0 only where it underflows).
// Channels with g <= 0 give 0. About 16 sqrt(g) + 10 terms, a few logs and an exp each (not meant
// for g beyond ~1e8): the exact reference for the table that eval() uses (tests compare them).
Rgb series_sum(const Rgb& g, const Rgb& t);
// The series table's rows are uniform in ln g from g = 0.01 to here (0.01 e^7.5) and beyond it in
// (kTableRoughFrom / g)^(1/4), down to 0 (g = infinity) at the last row (core/src/he_tables.cpp).
inline constexpr double kTableRoughFrom = 18.08042414456063;
// The same sum interpolated from that table for every g > 0, to a relative 1e-5 where the sum is
// above 1e-8 of its value at t = 0, to 1e-13 of that value elsewhere; what eval() uses.
Rgb tabulated_series_sum(const Rgb& g, const Rgb& t);

// Exact and tabulated forms of the other costly factors: the mirror term and sampling use the
// exact ones, eval() the tables (tests compare them).
// Shadowing of one direction as a function of a = tau cot(theta) / (2 sigma): S1 and erfc(a).
struct Shadowing {
  double s1;
  double erfc;
};
// From He et al.'s formulas, for 0 < a < kUnshadowedA: beyond it erfc(a) < 1e-295 and exp(-a^2)
// underflows, S1 = 1 and K = 0 exactly in double precision.
inline constexpr double kUnshadowedA = 26.0;
Shadowing exact_shadowing(double a);
// Interpolated, for 0 <= a < kShadowTableEnd. Beyond it S1 = 1 and erfc(a) = 0 as far as eval()
// is concerned: 1 - S1 < 1e-17, and K = tan erfc(a) < 1e-12 moves sigma0 by < 1e-24.
inline constexpr double kShadowTableEnd = 6.0;
Shadowing tabulated_shadowing(double a);

// sigma0 / sigma = 1 / sqrt(1 + x^2) with x exp(x^2 / 2) = y, y >= 0: exact (Newton) and
// interpolated (Newton beyond the table).
double sigma0_ratio(double y);
double tabulated_sigma0_ratio(double y);
}  // namespace he_detail

}  // namespace brdfnav
