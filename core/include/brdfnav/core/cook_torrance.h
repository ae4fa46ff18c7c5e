// Cook-Torrance lobe (Cook & Torrance, SIGGRAPH 1981): Schlick Fresnel, normalised Beckmann D,
// V-groove G (docs/CLOSURES.md, The formulas).
#pragma once

#include <brdfnav/core/microfacet.h>
#include <brdfnav/core/params.h>

#include <array>
#include <span>

namespace brdfnav {

struct CookTorrance {
  static constexpr std::string_view kName = "cook_torrance";
  static constexpr std::string_view kTitle = "Cook-Torrance";
  static constexpr bool kGrey = true;  // eval() is the same in every channel
  static constexpr std::array<ParamSpec, 2> kParams{{
      {.name = "f0",
       .unit = "1",
       .description = "Fresnel reflectance at normal incidence (Schlick)",
       .valid_min = 0.0,
       .valid_max = 1.0,
       .default_value = 0.04,
       .grid_min = 0.01,
       .grid_max = 1.0,
       .grid_count = 11,
       .scale = Scale::log,
       .more = "more reflective face-on",
       .less = "reflective at grazing only"},
      {.name = "m",
       .unit = "1",
       .description = "Beckmann RMS slope",
       .valid_min = 1e-4,
       .valid_max = 1.5,
       .default_value = 0.1,
       .grid_min = 0.005,
       .grid_max = 0.7,
       .grid_count = 13,
       .scale = Scale::log,
       .more = "rougher",
       .less = "sharper"},
  }};

  double f0, m;

  explicit CookTorrance(std::span<const double> p) : f0(p[0]), m(p[1]) {}
  bool operator==(const CookTorrance&) const = default;

  Rgb eval(const Vec3& wi, const Vec3& wo) const {
    const std::optional<Terms> t = terms(wi, wo);
    return t ? Rgb::Constant(t->value(f0)) : Rgb::Zero();
  }
  // eval() at one wo for many wi (the renderer's quadrature), and that of the lobes that differ
  // from this one in f0 alone with the rest computed once: out[k] equals
  // CookTorrance{f0s[k], m}.eval(wi, wo) to the bit.
  struct Bound {
    const CookTorrance& lobe;
    Vec3 wo;
    Rgb eval(const Vec3& wi) const { return lobe.eval(wi, wo); }
    void eval_fresnel(const Vec3& wi, std::span<const double> f0s, Rgb* out) const {
      const std::optional<Terms> t = lobe.terms(wi, wo);
      for (std::size_t k = 0; k < f0s.size(); ++k)
        out[k] = t ? Rgb::Constant(t->value(f0s[k])) : Rgb::Zero();
    }
  };
  Bound bind(const Vec3& wo) const { return {*this, wo}; }
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

 private:
  // Every factor of eval() at (wi, wo) but the Fresnel one, which alone depends on f0.
  struct Terms {
    double wo_h, d, g, cos4;  // cos4 = 4 cos_i cos_o
    double value(double f) const { return fresnel_schlick(wo_h, f) * d * g / cos4; }
  };
  std::optional<Terms> terms(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return std::nullopt;
    // Written with the unnormalised H = wi + wo to keep divisions off the critical path (eval()
    // is about a third faster, docs/CLOSURES.md, Cost): for unit wi, wo, wo.H = |H|^2 / 2, so
    // wi.h = wo.h = |H| / 2, 1 / cos_h^2 = |H|^2 / H.z^2, and the V-groove terms
    // 2 cos_h cos / (wo.h) are 4 H.z cos / |H|^2.
    const Vec3 hv = wi + wo;
    const double len2 = hv.squaredNorm(), hz = hv.z();
    // Below cos_h = 1e-8 the Beckmann exponential is exactly 0 for every valid m (as in
    // beckmann_d), while H.z^2 could underflow and make 0 * inf.
    if (len2 < 1e-24 || hz * hz <= 1e-16 * len2) return std::nullopt;
    const double wo_h = 0.5 * std::sqrt(len2);
    const double inv_cos2 = len2 / (hz * hz);  // 1 + tan^2(theta_h)
    const double d = beckmann_d_from_inv_cos2(inv_cos2, m);
    const double g = std::min(1.0, 4 * hz * std::min(wi.z(), wo.z()) / len2);
    return Terms{wo_h, d, g, 4 * wi.z() * wo.z()};
  }
};

}  // namespace brdfnav
