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
  std::optional<Vec3> sample(const Vec3& wo, const Vec2& u) const;
  double pdf(const Vec3& wi, const Vec3& wo) const;
  double albedo_hint(const Vec3& wo) const;
  // Reflectance of the mirror term at wo, per channel: F(cos_o) exp(-g_s) S.
  Rgb mirror_weight(const Vec3& wo) const;
};

}  // namespace brdfnav
