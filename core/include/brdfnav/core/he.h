// He, Torrance, Sillion, Greenberg 1991 (unpolarised): directional-diffuse lobe plus a mirror
// (delta) term, as fixed in shared/reference/brdf-models.md.
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
      {"sigma", "um", "RMS surface height", 1e-3, 10.0, 0.16, 0.02, 2.56, 8, Scale::log},
      {"tau", "um", "surface autocorrelation length", 0.1, 500.0, 8.0, 2.0, 128.0, 9, Scale::log},
      {"eta", "1", "real refractive index", 1.01, 20.0, 1.5, 1.2, 9.0, 5, Scale::log, kEtaNodes},
  }};
  // Wavelengths (micrometres) of the R, G, B channels.
  static constexpr std::array<double, 3> kLambda{0.645, 0.526, 0.444};

  double sigma, tau, eta;

  explicit He(std::span<const double> p) : sigma(p[0]), tau(p[1]), eta(p[2]) {}

  // Directional-diffuse term only (the mirror term is a delta: see mirror_weight()).
  Rgb eval(const Vec3& wi, const Vec3& wo) const;
  // Reflects wo about a Beckmann half vector (a mixture of two slopes chosen from sigma0 at wo,
  // tau and lambda); pdf() is the exact density of the directions it returns.
  std::optional<Vec3> sample(const Vec3& wo, const Vec2& u) const;
  double pdf(const Vec3& wi, const Vec3& wo) const;
  // Rough estimate of the lobe's albedo at wo, (1 - exp(-g_s)) F S1(theta_o) with the green g_s,
  // for choosing between sampling strategies.
  double albedo_hint(const Vec3& wo) const;
  // Reflectance of the mirror term at wo, per channel: F(cos_o) exp(-g_s) S.
  Rgb mirror_weight(const Vec3& wo) const;
};

// The sum over m in He's distribution D (without the pi^2 tau^2 / (4 lambda^2) prefactor), per
// channel, with t = pi^2 tau^2 vxy^2 / lambda^2. Exposed so that tests can compare the series
// with its rough-surface limit inside the blend range.
namespace he_detail {
// Blend range of g: the series below kBlendLo, the rough limit above kBlendHi.
inline constexpr double kBlendLo = 14.0;
inline constexpr double kBlendHi = 22.0;
// sum_{m>=1} exp(-g) g^m / (m! m) exp(-t / m) over m <= 64, to a relative 1e-10; a sum below
// 1e-14 of its value at t = 0 (the peak over directions) may come back as 0. Channels with
// g <= 0 give 0.
Rgb series_sum(const Rgb& g, const Rgb& t);
// The large-g limit exp(-t / g) / g.
Rgb rough_limit_sum(const Rgb& g, const Rgb& t);
// series_sum below kBlendLo, rough_limit_sum above kBlendHi, a smoothstep blend in between.
Rgb distribution_sum(const Rgb& g, const Rgb& t);
}  // namespace he_detail

}  // namespace brdfnav
