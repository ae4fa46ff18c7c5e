// Anisotropic Ward lobe, 1992 form with the unnormalised H = wi + wo, sampled as in Walter 2005
// "Notes on the Ward BRDF", Cornell PCG technical report PCG-05-06 (docs/CLOSURES.md).
#pragma once

#include <brdfnav/core/microfacet.h>
#include <brdfnav/core/params.h>

#include <array>
#include <span>

namespace brdfnav {

struct Ward {
  static constexpr std::string_view kName = "ward";
  static constexpr std::string_view kTitle = "Ward (anisotropic)";
  static constexpr bool kGrey = true;  // eval() is the same in every channel
  static constexpr std::array<ParamSpec, 2> kParams{{
      {.name = "alpha_x",
       .unit = "1",
       .description = "RMS slope along the tangent x",
       .valid_min = 1e-4,
       .valid_max = 1.0,
       .default_value = 0.1,
       .grid_min = 0.005,
       .grid_max = 0.5,
       .grid_count = 15,
       .scale = Scale::log,
       .more = "stretched along x",
       .less = "sharper along x"},
      {.name = "alpha_y",
       .unit = "1",
       .description = "RMS slope along the bitangent y",
       .valid_min = 1e-4,
       .valid_max = 1.0,
       .default_value = 0.1,
       .grid_min = 0.005,
       .grid_max = 0.5,
       .grid_count = 15,
       .scale = Scale::log,
       .more = "stretched along y",
       .less = "sharper along y"},
  }};

  double alpha_x, alpha_y;

  explicit Ward(std::span<const double> p) : alpha_x(p[0]), alpha_y(p[1]) {}

  // eval() at one wo with wo's terms computed once, for many wi (the renderer's quadrature):
  // bind(wo).eval(wi) is eval(wi, wo), which it computes.
  struct Bound {
    Vec3 wo;
    double inv_alpha_x, inv_alpha_y;
    double scale;  // 1 / (4 pi alpha_x alpha_y sqrt(cos_o)), 0 below the horizon
    Rgb eval(const Vec3& wi) const {
      const double g = scaled_gaussian(wi);
      return Rgb::Constant(g > 0 ? g / std::sqrt(wi.z()) : 0.0);
    }
    // eval(wi) times cos(theta_i), the renderer's kernel, with a square root for the division.
    double eval_cos(const Vec3& wi) const {
      const double g = scaled_gaussian(wi);
      return g > 0 ? g * std::sqrt(wi.z()) : 0.0;
    }
    // eval_cos() at many local directions (x, y, z) at once, into `out`, with `exp_in_place`
    // exponentiating an array (the renderer's runs a vector of them at a time). Above the horizon
    // (z > 0, wo.z > 0) h.z is positive; z <= 0 gives 0, or NaN where wi is exactly -wo.
    template <typename A, typename Exp>
    void eval_cos(const Eigen::ArrayBase<A>& x, const Eigen::ArrayBase<A>& y,
                  const Eigen::ArrayBase<A>& z, Eigen::Ref<Eigen::ArrayXd> out,
                  Exp&& exp_in_place) const {
      out = (-((x + wo.x()) * inv_alpha_x).square() - ((y + wo.y()) * inv_alpha_y).square())
                .cwiseQuotient((z + wo.z()).square());
      exp_in_place(out);
      out *= scale * z.cwiseMax(0.0).sqrt();
    }
    // f(wi) sqrt(cos_i): 0 below either horizon.
    double scaled_gaussian(const Vec3& wi) const {
      return wi.z() <= 0 || scale == 0 ? 0.0 : gaussian(wi + wo, inv_alpha_x, inv_alpha_y) * scale;
    }
  };
  Bound bind(const Vec3& wo) const {
    const double scale = wo.z() > 0 ? 1 / (4 * kPi * alpha_x * alpha_y * std::sqrt(wo.z())) : 0;
    return {wo, 1 / alpha_x, 1 / alpha_y, scale};
  }

  Rgb eval(const Vec3& wi, const Vec3& wo) const { return bind(wo).eval(wi); }
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
    return gaussian(*h, 1 / alpha_x, 1 / alpha_y) /
           (4 * kPi * alpha_x * alpha_y * wo_h * cos_h * cos_h * cos_h);
  }
  double albedo_hint(const Vec3& /*wo*/) const { return 1.0; }

 private:
  // exp(-((h.x/ax)^2 + (h.y/ay)^2) / h.z^2): scale-free in h.
  static double gaussian(const Vec3& h, double inv_alpha_x, double inv_alpha_y) {
    if (h.z() <= 0) return 0.0;
    const double x = h.x() * inv_alpha_x, y = h.y() * inv_alpha_y;
    return std::exp(-(x * x + y * y) / (h.z() * h.z()));
  }
};

}  // namespace brdfnav
