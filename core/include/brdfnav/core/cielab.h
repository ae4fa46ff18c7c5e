// CIE 1976 L*a*b* of linear Rec. 709 RGB under D65 (CIE 15:2004, section 8.2.1), for every
// CIELAB computation of brdfnav: the validation report's image metric and the navigator's
// colour tabs.
#pragma once

#include <brdfnav/core/math.h>

#include <Eigen/LU>

#include <cmath>

namespace brdfnav {

// Linear Rec. 709 (sRGB primaries) to CIE XYZ, D65 white: the IEC 61966-2-1 matrix to 7 digits
// (B. Lindbloom, "RGB/XYZ Matrices"), and its inverse computed from it, so that the round trip
// is exact to rounding.
inline const Eigen::Matrix3d& xyz_from_rec709_matrix() {
  static const Eigen::Matrix3d m = (Eigen::Matrix3d() << 0.4124564, 0.3575761, 0.1804375,  //
                                    0.2126729, 0.7151522, 0.0721750,                       //
                                    0.0193339, 0.1191920, 0.9503041)
                                       .finished();
  return m;
}
inline const Eigen::Matrix3d& rec709_from_xyz_matrix() {
  static const Eigen::Matrix3d m = xyz_from_rec709_matrix().inverse();
  return m;
}

namespace cielab_detail {

constexpr double kDelta = 6.0 / 29.0;
// f(t) = cbrt(t) above (6/29)^3, linear below, and its inverse.
inline double f(double t) {
  return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3 * kDelta * kDelta) + 4.0 / 29.0;
}
inline double f_inverse(double f) {
  return f > kDelta ? f * f * f : 3 * kDelta * kDelta * (f - 4.0 / 29.0);
}
// The reference white: RGB (1, 1, 1) through the same matrix (D65 at Y = 1), so that greys
// have a* = b* = 0 exactly rather than to the matrix's rounding.
inline const Vec3& white() {
  static const Vec3 w = xyz_from_rec709_matrix() * Vec3::Ones();
  return w;
}

}  // namespace cielab_detail

// L*a*b* whose white is RGB (1, 1, 1). For another white, divide the colour by its luminance
// first. Values above the white extend the cube-root law (L* > 100).
inline Vec3 lab_from_rec709(const Rgb& c) {
  using namespace cielab_detail;
  const Vec3 xyz = xyz_from_rec709_matrix() * c.matrix();
  const double fx = f(xyz.x() / white().x()), fy = f(xyz.y() / white().y()),
               fz = f(xyz.z() / white().z());
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

// The inverse of lab_from_rec709().
inline Rgb rec709_from_lab(const Vec3& lab) {
  using namespace cielab_detail;
  const double fy = (lab.x() + 16) / 116, fx = fy + lab.y() / 500, fz = fy - lab.z() / 200;
  const Vec3 xyz(white().x() * f_inverse(fx), white().y() * f_inverse(fy),
                 white().z() * f_inverse(fz));
  return (rec709_from_xyz_matrix() * xyz).array();
}

}  // namespace brdfnav
