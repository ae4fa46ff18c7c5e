// Cook-Torrance lobe: Schlick Fresnel, normalised Beckmann D, V-groove G
// (shared/reference/brdf-models.md).
#pragma once

#include <brdfnav/core/microfacet.h>
#include <brdfnav/core/params.h>

#include <array>
#include <span>

namespace brdfnav {

struct CookTorrance {
  static constexpr std::string_view kName = "cook_torrance";
  static constexpr std::string_view kTitle = "Cook-Torrance";
  static constexpr std::array<ParamSpec, 2> kParams{{
      {"f0", "1", "Fresnel reflectance at normal incidence (Schlick)", 0.0, 1.0, 0.04, 0.01, 1.0,
       11, Scale::log},
      {"m", "1", "Beckmann RMS slope", 1e-4, 1.5, 0.1, 0.005, 0.7, 13, Scale::log},
  }};

  double f0, m;

  explicit CookTorrance(std::span<const double> p) : f0(p[0]), m(p[1]) {}

  Rgb eval(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return Rgb::Zero();
    const auto h = half_vector(wi, wo);
    if (!h) return Rgb::Zero();
    const double cos_h = h->z(), wo_h = wo.dot(*h);
    const double g = std::min({1.0, 2 * cos_h * wo.z() / wo_h, 2 * cos_h * wi.z() / wo_h});
    const double value =
        fresnel_schlick(wi.dot(*h), f0) * beckmann_d(cos_h, m) * g / (4 * wi.z() * wo.z());
    return Rgb::Constant(value);
  }
  std::optional<Vec3> sample(const Vec3& wo, const Vec2& u) const {
    return reflect_about_half(wo, sample_beckmann(u, m));
  }
  double pdf(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return 0.0;
    const auto h = half_vector(wi, wo);
    if (!h) return 0.0;
    return half_to_incident_pdf(beckmann_d(h->z(), m) * h->z(), wo, *h);
  }
  // Fresnel at the viewing angle: the energy the lobe can reflect, shadowing aside.
  double albedo_hint(const Vec3& wo) const { return fresnel_schlick(wo.z(), f0); }
};

}  // namespace brdfnav
