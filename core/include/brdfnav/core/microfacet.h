// Microfacet math shared by the half-vector lobes (Blinn-Phong, Ward, Cook-Torrance, He, GGX).
#pragma once

#include <brdfnav/core/math.h>

#include <optional>

namespace brdfnav {

// Normalised half vector of two directions in the upper hemisphere; nullopt when degenerate.
inline std::optional<Vec3> half_vector(const Vec3& wi, const Vec3& wo) {
  const Vec3 h = wi + wo;
  const double len2 = h.squaredNorm();
  if (len2 < 1e-24) return std::nullopt;
  return h / std::sqrt(len2);
}

// Reflects wo about a sampled half vector h; nullopt when wo is on the back of h or the result
// points below the horizon (the sample is then lost, which pdf() accounts for by only giving
// density to reachable directions).
inline std::optional<Vec3> reflect_about_half(const Vec3& wo, const Vec3& h) {
  if (wo.dot(h) <= 0) return std::nullopt;
  const Vec3 wi = reflect(wo, h);
  if (wi.z() <= 0) return std::nullopt;
  return wi;
}

// Jacobian from a half-vector density to a density over wi: dw_h / dw_i = 1 / (4 |wo.h|).
inline double half_to_incident_pdf(double pdf_h, const Vec3& wo, const Vec3& h) {
  const double wo_h = wo.dot(h);
  return wo_h > 0 ? pdf_h / (4.0 * wo_h) : 0.0;
}

// Beckmann distribution normalised so that integral D cos_h dw_h = 1 (slope RMS m), from
// 1 / cos_h^2 = 1 + tan^2(theta_h): callers holding the unnormalised H = wi + wo get it as
// |H|^2 / H.z^2 without a square root.
inline double beckmann_d_from_inv_cos2(double inv_cos2, double m) {
  return std::exp((1.0 - inv_cos2) / (m * m)) * inv_cos2 * inv_cos2 / (kPi * m * m);
}

inline double beckmann_d(double cos_h, double m) {
  // Below 1e-8 the exponential is exactly 0 in double for every valid m (<= 1.5), while
  // cos_h^4 could underflow to 0 and turn the quotient into 0/0.
  if (cos_h <= 1e-8) return 0.0;
  return beckmann_d_from_inv_cos2(1.0 / (cos_h * cos_h), m);
}

// Samples h with density D(h) cos_h for the Beckmann distribution.
inline Vec3 sample_beckmann(const Vec2& u, double m) {
  const double tan2 = -m * m * std::log1p(-u[0]);
  const double cos_h = 1.0 / std::sqrt(1.0 + tan2);
  const double sin_h = safe_sqrt(1.0 - cos_h * cos_h);
  return spherical_direction(sin_h, cos_h, 2 * kPi * u[1]);
}

// Anisotropic Trowbridge-Reitz (GGX) distribution, normalised so that integral D cos_h dw_h = 1,
// with roughness alpha_x along x and alpha_y along y:
//   D(h) = 1 / (pi ax ay ((h.x / ax)^2 + (h.y / ay)^2 + h.z^2)^2)  for unit h.
// Scale-free form: `h` need not be unit (the caller's H = wi + wo), its squared length is len2.
inline double ggx_d(const Vec3& h, double len2, double alpha_x, double alpha_y) {
  const double x = h.x() / alpha_x, y = h.y() / alpha_y;
  const double q = (x * x + y * y + h.z() * h.z()) / len2;
  return 1.0 / (kPi * alpha_x * alpha_y * q * q);
}

// Smith's masking function of the GGX distribution for a unit direction w above the horizon,
// G1 = 1 / (1 + Lambda) = 2 w.z / (w.z + sqrt(w.z^2 + ax^2 w.x^2 + ay^2 w.y^2)); 0 at and below
// the horizon.
inline double ggx_g1(const Vec3& w, double alpha_x, double alpha_y) {
  if (w.z() <= 0) return 0.0;
  const double x = alpha_x * w.x(), y = alpha_y * w.y(), z = w.z();
  return 2 * z / (z + std::sqrt(z * z + x * x + y * y));
}

// Samples a GGX normal h from the distribution of normals visible from wo (wo.z > 0), whose
// density is G1(wo) max(0, wo.h) D(h) / wo.z (Heitz, "Sampling the GGX Distribution of Visible
// Normals", JCGT 2018): wo is stretched to the hemisphere configuration, a point of the projected
// hemisphere is drawn uniformly, lifted onto it and unstretched.
inline Vec3 sample_ggx_visible_normal(const Vec3& wo, double alpha_x, double alpha_y,
                                      const Vec2& u) {
  const Vec3 v = Vec3(alpha_x * wo.x(), alpha_y * wo.y(), wo.z()).normalized();
  const double len2 = v.x() * v.x() + v.y() * v.y();
  const Vec3 t1 = len2 > 0 ? Vec3(-v.y(), v.x(), 0) / std::sqrt(len2) : Vec3(1, 0, 0);
  const Vec3 t2 = v.cross(t1);
  const double r = std::sqrt(u[0]), phi = 2 * kPi * u[1];
  const double p1 = r * std::cos(phi);
  const double s = 0.5 * (1 + v.z());
  const double p2 = (1 - s) * safe_sqrt(1 - p1 * p1) + s * r * std::sin(phi);
  const Vec3 n = p1 * t1 + p2 * t2 + safe_sqrt(1 - p1 * p1 - p2 * p2) * v;
  return Vec3(alpha_x * n.x(), alpha_y * n.y(), std::max(0.0, n.z())).normalized();
}

// Schlick's approximation of Fresnel reflectance.
inline double fresnel_schlick(double cos_theta, double f0) {
  const double k = 1.0 - std::clamp(cos_theta, 0.0, 1.0);
  const double k2 = k * k;
  return f0 + (1.0 - f0) * k2 * k2 * k;
}

// Exact unpolarised Fresnel reflectance of a dielectric with real relative index eta > 1.
inline double fresnel_dielectric(double cos_theta, double eta) {
  const double c = std::clamp(cos_theta, 0.0, 1.0);
  const double g = safe_sqrt(eta * eta + c * c - 1.0);
  const double gmc = g - c, gpc = g + c;
  if (gpc <= 0) return 1.0;
  const double a = (c * gpc - 1.0) / (c * gmc + 1.0);
  return 0.5 * (gmc * gmc) / (gpc * gpc) * (1.0 + a * a);
}

}  // namespace brdfnav
