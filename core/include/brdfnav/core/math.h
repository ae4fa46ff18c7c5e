// Small vector helpers shared by every closure. Directions are in the local shading frame of
// docs/MODELS.md and docs/CLOSURES.md: normal +z, tangent +x, bitangent +y, all pointing away
// from the surface.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace brdfnav {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Rgb = Eigen::Array3d;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInvPi = 1.0 / std::numbers::pi;

inline double safe_sqrt(double x) {
  return std::sqrt(std::max(x, 0.0));
}

// Mirror of `w` about the unit vector `n` (both pointing away from the surface).
inline Vec3 reflect(const Vec3& w, const Vec3& n) {
  return 2.0 * w.dot(n) * n - w;
}

// Unit vector with polar angle given by (cos_theta, sin_theta) and azimuth phi around +z.
inline Vec3 spherical_direction(double sin_theta, double cos_theta, double phi) {
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}

// `v` scaled to unit length, or nothing for the zero vector; `v` must be finite. stableNorm(), so
// that components as large as 1e300 or as small as 1e-300 neither overflow nor vanish.
inline std::optional<Vec3> unit_direction(const Vec3& v) {
  const double length = v.stableNorm();
  if (!(length > 0)) return std::nullopt;
  return Vec3(v / length);
}

// Rec. 709 / sRGB-primaries luminance; used only to weigh sampling strategies.
inline double luminance(const Rgb& c) {
  return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

// Orthonormal frame (x, y, z) with z the shading normal; converts between world and local.
struct Frame {
  Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};

  // Frame around `n` with a tangent chosen without branches that flip near the poles
  // (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
  static Frame from_normal(const Vec3& n) {
    const double sign = std::copysign(1.0, n.z());
    const double a = -1.0 / (sign + n.z());
    const double b = n.x() * n.y() * a;
    Frame f;
    f.x = Vec3(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
    f.y = Vec3(b, sign + n.y() * n.y() * a, -n.y());
    f.z = n;
    return f;
  }
  // Frame around `n` whose x axis is the tangent `t` projected onto the plane of `n` (for the
  // anisotropic Ward lobe). Falls back to from_normal() when `t` is parallel to `n`.
  static Frame from_normal_tangent(const Vec3& n, const Vec3& t) {
    Vec3 x = t - t.dot(n) * n;
    if (x.squaredNorm() < 1e-20) return from_normal(n);
    Frame f;
    f.z = n;
    f.x = x.normalized();
    f.y = f.z.cross(f.x);
    return f;
  }

  Vec3 to_local(const Vec3& w) const { return {w.dot(x), w.dot(y), w.dot(z)}; }
  Vec3 from_local(const Vec3& w) const { return w.x() * x + w.y() * y + w.z() * z; }
};

// Cosine-weighted hemisphere sampling (Malley's method over a concentric disk map).
Vec3 sample_cosine_hemisphere(const Vec2& u);
inline double cosine_hemisphere_pdf(double cos_theta) {
  return cos_theta > 0 ? cos_theta * kInvPi : 0.0;
}

// Samples a cos^n lobe around +z: cos(theta) = u0^(1/(n+1)); pdf = (n+1)/(2 pi) cos^n.
Vec3 sample_cos_power(const Vec2& u, double n);
inline double cos_power_pdf(double cos_theta, double n) {
  return cos_theta > 0 ? (n + 1) / (2 * kPi) * std::pow(cos_theta, n) : 0.0;
}

}  // namespace brdfnav
