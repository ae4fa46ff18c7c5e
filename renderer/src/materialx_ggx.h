// GGX with MaterialX's terms instead of Cycles' (docs/HOSTS.md, MaterialX): what MaterialX 1.38's
// GLSL implementation of `generalized_schlick_bsdf` computes with color0 = color90 = rho_s and
// roughness (alpha_x, alpha_y), for the export's statement of how far a MaterialX renderer's
// image is from the `ggx` closure's. Not a model: Renderer::materialx_ggx() renders it in the
// windows of the Ggx lobe it is built from.
//
//   f cos_i = D(h) G2(wi, wo) (rho_s + rho_s^2 (1 - E(cos_o)) / E(cos_o)) / (4 cos_o)
//
// D is the anisotropic Trowbridge-Reitz distribution (Cycles' too); G2 Smith's height-correlated
// masking-shadowing with the isotropic alpha a = sqrt(ax ay), 2 / (l(wi) + l(wo)) with
// l(w) = sqrt(a^2 + (1 - a^2) cos^2) / cos; the last factor is its Fresnel term (rho_s at every
// angle) times its energy compensation 1 + F (1 - E) / E, E the directional albedo of the lobe
// with F = 1 from MaterialX's rational fit. The image is no longer linear in rho_s: it is
// rho_s times the `plain` lobe D G2 / (4 cos_i cos_o) plus rho_s^2 times the `compensation`
// lobe, the plain one times (1 - E) / E.
#pragma once

#include <brdfnav/core/ggx.h>

#include <algorithm>
#include <cmath>

namespace brdfnav {

// MaterialX's fit of the GGX directional albedo E(cos_o, alpha) with F0 = F90 = 1 (its
// mx_ggx_dir_albedo_analytic), a rational function of cos_o and the isotropic alpha.
inline double materialx_ggx_albedo(double cos_o, double alpha) {
  const double x = cos_o, y = alpha, x2 = x * x, y2 = y * y;
  // Numerators and denominators of the scale and bias terms A and B, E = A + B.
  auto rational = [&](const double(&c)[9]) {
    return c[0] + c[1] * x + c[2] * y + c[3] * x * y + c[4] * x2 + c[5] * y2 + c[6] * x2 * y +
           c[7] * x * y2 + c[8] * x2 * y2;
  };
  static constexpr double kAn[9] = {0.1003, -0.6303, 9.748, -2.038, 29.34,
                                    -8.245, -26.44,  19.99, -5.448};
  static constexpr double kBn[9] = {0.9345,  -2.323, 2.229,  -3.748, 1.424,
                                    -0.7684, 1.436,  0.2913, 0.6286};
  static constexpr double kAd[9] = {1.0, -1.765, 8.263, 11.53, 28.96, -7.507, -36.11, 15.86, 33.37};
  static constexpr double kBd[9] = {1.0, 0.2281, 15.94, -55.83, 13.08, 41.26, 54.9, 300.2, -285.1};
  const double a = std::clamp(rational(kAn) / rational(kAd), 0.0, 1.0);
  const double b = std::clamp(rational(kBn) / rational(kBd), 0.0, 1.0);
  return a + b;
}

struct MaterialxGgx {
  static constexpr bool kGrey = true;
  double alpha_x, alpha_y;
  bool compensation;  // the rho_s^2 lobe, else the rho_s one

  struct Bound {
    Vec3 wo;
    double alpha_x, alpha_y, a2;
    double l_o;    // l(wo)
    double scale;  // 1 / (4 cos_o), times (1 - E) / E for the compensation; 0 below the horizon
    double eval_cos(const Vec3& wi) const {
      if (wi.z() <= 0 || scale == 0) return 0.0;
      const Vec3 h = wi + wo;
      const double len2 = h.squaredNorm();
      if (len2 < 1e-24) return 0.0;
      const double z = wi.z(), l_i = std::sqrt(a2 + (1 - a2) * z * z) / z;
      return ggx_d(h, len2, alpha_x, alpha_y) * 2 / (l_i + l_o) * scale;
    }
    Rgb eval(const Vec3& wi) const {
      return Rgb::Constant(wi.z() > 0 ? eval_cos(wi) / wi.z() : 0.0);
    }
  };
  Bound bind(const Vec3& wo) const {
    const double a2 = alpha_x * alpha_y;
    if (wo.z() <= 0) return {wo, alpha_x, alpha_y, a2, 1, 0};
    const double z = wo.z();
    double scale = 1 / (4 * z);
    if (compensation) {
      const double e = materialx_ggx_albedo(z, std::sqrt(a2));
      scale *= (1 - e) / e;
    }
    return {wo, alpha_x, alpha_y, a2, std::sqrt(a2 + (1 - a2) * z * z) / z, scale};
  }
};

}  // namespace brdfnav
