// Blinn-Phong lobe (Blinn 1977): (n + 2) / (8 pi) cos_h^n (docs/CLOSURES.md, The formulas).
#pragma once

#include <brdfnav/core/microfacet.h>
#include <brdfnav/core/params.h>

#include <array>
#include <span>

namespace brdfnav {

struct BlinnPhong {
  static constexpr std::string_view kName = "blinn_phong";
  static constexpr std::string_view kTitle = "Blinn-Phong";
  static constexpr bool kGrey = true;  // eval() is the same in every channel
  static constexpr std::array<ParamSpec, 1> kParams{{
      {.name = "n",
       .unit = "1",
       .description = "exponent of cos(theta_h); larger is sharper",
       .valid_min = 0.0,
       .valid_max = 1e6,
       .default_value = 100.0,
       .grid_min = 2.0,
       .grid_max = 80000.0,
       .grid_count = 15,
       .scale = Scale::log,
       .more = "sharper",
       .less = "rougher"},
  }};

  double n;

  explicit BlinnPhong(std::span<const double> p) : n(p[0]) {}

  Rgb eval(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return Rgb::Zero();
    // cos_h^n as (cos_h^2)^(n/2) from the unnormalised H = wi + wo: skipping the square root
    // and the normalisation saves a fifth of the call (docs/CLOSURES.md, Cost).
    const Vec3 h = wi + wo;
    const double len2 = h.squaredNorm();
    if (len2 < 1e-24) return Rgb::Zero();
    return Rgb::Constant((n + 2) / (8 * kPi) * std::pow(h.z() * h.z() / len2, 0.5 * n));
  }
  std::optional<Vec3> sample(const Vec3& wo, const Vec2& u) const {
    return reflect_about_half(wo, sample_cos_power(u, n));
  }
  double pdf(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return 0.0;
    const auto h = half_vector(wi, wo);
    if (!h) return 0.0;
    return half_to_incident_pdf(cos_power_pdf(h->z(), n), wo, *h);
  }
  // With the (n+2)/(8 pi) factor the albedo is close to 1 at normal incidence for large n.
  double albedo_hint(const Vec3& /*wo*/) const { return 1.0; }
};

}  // namespace brdfnav
