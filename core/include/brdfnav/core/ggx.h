// Anisotropic Trowbridge-Reitz (GGX) microfacet lobe without Fresnel, term for term what Cycles
// (Blender 3.4) evaluates for its Glossy and Anisotropic BSDFs with the GGX distribution:
//   f = D(h) G1(wi) G1(wo) / (4 cos_i cos_o),
// D the anisotropic Trowbridge-Reitz distribution and G1 Smith's masking for it, applied
// separately to wi and wo (docs/CLOSURES.md, docs/MODELS.md).
#pragma once

#include <brdfnav/core/microfacet.h>
#include <brdfnav/core/params.h>

#include <array>
#include <span>

namespace brdfnav {

struct Ggx {
  static constexpr std::string_view kName = "ggx";
  static constexpr std::string_view kTitle = "GGX (Trowbridge-Reitz, anisotropic)";
  static constexpr bool kGrey = true;  // eval() is the same in every channel
  // What docs/MODELS.md says of the formula (the paper has no GGX).
  static constexpr std::string_view kFormula =
      "The lobe is what Cycles (Blender 3.4) computes for its Glossy and Anisotropic BSDFs with "
      "the GGX distribution and colour rho_s: `lobe = D(h) G1(wi) G1(wo) / (4 cos_i cos_o)`, "
      "without a Fresnel factor (F = 1). D is the anisotropic Trowbridge-Reitz distribution, "
      "`D(h) = 1 / (pi ax ay ((h.x / ax)^2 + (h.y / ay)^2 + h.z^2)^2)` for the unit half vector "
      "h, normalised so that D cos_h integrates to 1; G is Smith's masking-shadowing in its "
      "separable form, with `G1(w) = 2 / (1 + sqrt(1 + (ax^2 w.x^2 + ay^2 w.y^2) / w.z^2))`. "
      "Cycles' Roughness r and Anisotropy a give `ax = r^2 (1 - a)`, `ay = r^2 / (1 - a)` "
      "(docs/CLOSURES.md).";
  // Below alpha_x alpha_y = 1e-7 Cycles treats the lobe as a mirror, above 1 it clamps alpha:
  // the valid range keeps every material one that Cycles renders as written.
  static constexpr std::array<ParamSpec, 2> kParams{{
      {.name = "alpha_x",
       .unit = "1",
       .description = "roughness along the tangent x (Cycles: Roughness^2)",
       .valid_min = 1e-3,
       .valid_max = 1.0,
       .default_value = 0.1,
       .grid_min = 0.01,
       .grid_max = 1.0,
       .grid_count = 13,
       .scale = Scale::log,
       .more = "stretched along x",
       .less = "sharper along x"},
      {.name = "alpha_y",
       .unit = "1",
       .description = "roughness along the bitangent y (alpha_x for an isotropic lobe)",
       .valid_min = 1e-3,
       .valid_max = 1.0,
       .default_value = 0.1,
       .grid_min = 0.01,
       .grid_max = 1.0,
       .grid_count = 13,
       .scale = Scale::log,
       .more = "stretched along y",
       .less = "sharper along y"},
  }};

  double alpha_x, alpha_y;

  explicit Ggx(std::span<const double> p) : alpha_x(p[0]), alpha_y(p[1]) {}

  // eval() at one wo with wo's terms computed once, for many wi (the renderer's quadrature).
  struct Bound {
    Vec3 wo;
    double alpha_x, alpha_y;
    double scale;  // G1(wo) / (4 cos_o), 0 below the horizon
    Rgb eval(const Vec3& wi) const {
      return Rgb::Constant(wi.z() > 0 ? eval_cos(wi) / wi.z() : 0.0);
    }
    // eval(wi) times cos(theta_i), the renderer's kernel: D G1(wi) G1(wo) / (4 cos_o).
    double eval_cos(const Vec3& wi) const {
      if (wi.z() <= 0 || scale == 0) return 0.0;
      const Vec3 h = wi + wo;
      const double len2 = h.squaredNorm();
      if (len2 < 1e-24) return 0.0;
      return ggx_d(h, len2, alpha_x, alpha_y) * ggx_g1(wi, alpha_x, alpha_y) * scale;
    }
    // eval_cos() at many local directions (x, y, z) at once, into `out` (the quadrature's slope
    // windows); 0 at and below the horizon. The lobe has no exponential: `exp_in_place` is unused.
    template <typename A, typename Exp>
    void eval_cos(const Eigen::ArrayBase<A>& x, const Eigen::ArrayBase<A>& y,
                  const Eigen::ArrayBase<A>& z, Eigen::Ref<Eigen::ArrayXd> out,
                  Exp&& /*exp_in_place*/) const {
      const double ax2 = alpha_x * alpha_x, ay2 = alpha_y * alpha_y;
      const auto hx = x + wo.x(), hy = y + wo.y(), hz = z + wo.z();
      const auto len2 = hx.square() + hy.square() + hz.square();
      const auto q = hx.square() / ax2 + hy.square() / ay2 + hz.square();
      const auto zp = z.cwiseMax(0.0);
      const auto g1 = 2 * zp / (zp + (zp.square() + ax2 * x.square() + ay2 * y.square()).sqrt());
      out = (len2 / q).square() * g1 * (scale / (kPi * alpha_x * alpha_y));
    }
  };
  Bound bind(const Vec3& wo) const {
    const double scale = wo.z() > 0 ? ggx_g1(wo, alpha_x, alpha_y) / (4 * wo.z()) : 0.0;
    return {wo, alpha_x, alpha_y, scale};
  }

  Rgb eval(const Vec3& wi, const Vec3& wo) const { return bind(wo).eval(wi); }
  // Visible normals: the half vector's density is G1(wo) max(0, wo.h) D(h) / cos_o, which makes
  // f cos_i / pdf = G1(wi) <= 1.
  std::optional<Vec3> sample(const Vec3& wo, const Vec2& u) const {
    if (wo.z() <= 0) return std::nullopt;
    return reflect_about_half(wo, sample_ggx_visible_normal(wo, alpha_x, alpha_y, u));
  }
  // The visible-normal density over wi: G1(wo) D(h) / (4 cos_o).
  double pdf(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return 0.0;
    const Vec3 h = wi + wo;
    const double len2 = h.squaredNorm();
    if (len2 < 1e-24) return 0.0;
    return ggx_g1(wo, alpha_x, alpha_y) * ggx_d(h, len2, alpha_x, alpha_y) / (4 * wo.z());
  }
  // The albedo is at most G1(wo) (f cos_i / pdf = G1(wi) <= 1 under a density of mass <= 1).
  double albedo_hint(const Vec3& wo) const { return ggx_g1(wo, alpha_x, alpha_y); }
};

}  // namespace brdfnav
