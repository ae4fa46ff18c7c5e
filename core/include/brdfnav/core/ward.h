// Anisotropic Ward lobe, 1992 form with the unnormalised H = wi + wo, sampled as in Walter 2005
// "Notes on the Ward BRDF" (shared/reference/brdf-models.md).
#pragma once

#include <brdfnav/core/microfacet.h>
#include <brdfnav/core/params.h>

#include <array>
#include <span>

namespace brdfnav {

struct Ward {
  static constexpr std::string_view kName = "ward";
  static constexpr std::string_view kTitle = "Ward (anisotropic)";
  static constexpr std::array<ParamSpec, 2> kParams{{
      {"alpha_x", "1", "RMS slope along the tangent x", 1e-4, 1.0, 0.1, 0.005, 0.5, 15,
       Scale::log},
      {"alpha_y", "1", "RMS slope along the bitangent y", 1e-4, 1.0, 0.1, 0.005, 0.5, 15,
       Scale::log},
  }};

  double alpha_x, alpha_y;

  explicit Ward(std::span<const double> p) : alpha_x(p[0]), alpha_y(p[1]) {}

  Rgb eval(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return Rgb::Zero();
    const Vec3 h = wi + wo;
    const double value = gaussian(h) / (4 * kPi * alpha_x * alpha_y * std::sqrt(wi.z() * wo.z()));
    return Rgb::Constant(value);
  }
  std::optional<Vec3> sample(const Vec3& wo, const Vec2& u) const {
    const double phi0 = 2 * kPi * u[0];
    const double phi = std::atan2(alpha_y * std::sin(phi0), alpha_x * std::cos(phi0));
    const double c = std::cos(phi) / alpha_x, s = std::sin(phi) / alpha_y;
    const double tan2 = -std::log1p(-u[1]) / (c * c + s * s);
    const double cos_h = 1.0 / std::sqrt(1.0 + tan2);
    return reflect_about_half(wo, spherical_direction(safe_sqrt(1 - cos_h * cos_h), cos_h, phi));
  }
  double pdf(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return 0.0;
    const auto h = half_vector(wi, wo);
    if (!h) return 0.0;
    const double cos_h = h->z(), wo_h = wo.dot(*h);
    if (cos_h <= 0 || wo_h <= 0) return 0.0;
    return gaussian(*h) / (4 * kPi * alpha_x * alpha_y * wo_h * cos_h * cos_h * cos_h);
  }
  double albedo_hint(const Vec3& /*wo*/) const { return 1.0; }

 private:
  // exp(-((h.x/ax)^2 + (h.y/ay)^2) / h.z^2): scale-free in h.
  double gaussian(const Vec3& h) const {
    if (h.z() <= 0) return 0.0;
    const double x = h.x() / alpha_x, y = h.y() / alpha_y;
    return std::exp(-(x * x + y * y) / (h.z() * h.z()));
  }
};

}  // namespace brdfnav
