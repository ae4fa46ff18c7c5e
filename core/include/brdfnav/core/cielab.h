// CIE 1976 L*a*b* of linear Rec. 709 RGB under D65 (CIE 15:2004, section 8.2.1), for every
// CIELAB computation of brdfnav (the validation report's image metric; the navigator's colour
// tabs can share it).
#pragma once

#include <brdfnav/core/math.h>

#include <cmath>

namespace brdfnav {

// Linear Rec. 709 (sRGB primaries) to CIE XYZ, D65 white: the IEC 61966-2-1 matrix to 7 digits
// (B. Lindbloom, "RGB/XYZ Matrices").
inline Vec3 xyz_from_rec709(const Rgb& c) {
  return {0.4124564 * c[0] + 0.3575761 * c[1] + 0.1804375 * c[2],
          0.2126729 * c[0] + 0.7151522 * c[1] + 0.0721750 * c[2],
          0.0193339 * c[0] + 0.1191920 * c[1] + 0.9503041 * c[2]};
}

// L*a*b* whose white is RGB (1, 1, 1), i.e. D65 at Y = 1 through the same matrix, so that greys
// have a* = b* = 0 exactly rather than to the matrix's rounding. For another white, divide the
// colour by its luminance first. Values above the white extend the cube-root law (L* > 100).
inline Vec3 lab_from_rec709(const Rgb& c) {
  constexpr double kDelta = 6.0 / 29.0;
  const auto f = [](double t) {
    return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3 * kDelta * kDelta) + 4.0 / 29.0;
  };
  const Vec3 xyz = xyz_from_rec709(c), white = xyz_from_rec709(Rgb::Ones());
  const double fx = f(xyz[0] / white[0]), fy = f(xyz[1] / white[1]), fz = f(xyz[2] / white[2]);
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

}  // namespace brdfnav
