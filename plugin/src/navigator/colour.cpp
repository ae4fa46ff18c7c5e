#include "navigator/colour.h"

#include <Eigen/LU>

#include <cmath>
#include <numbers>

namespace brdfnav::nav {

namespace {

// Linear Rec.709 (= sRGB primaries) to CIE XYZ, D65 white: B. Lindbloom, "RGB/XYZ Matrices"
// (brucelindbloom.com, sRGB row), the IEC 61966-2-1 matrix to 7 digits. The inverse is computed
// from it so that the round trip is exact to rounding.
const Eigen::Matrix3d& rgb_to_xyz() {
  static const Eigen::Matrix3d m =
      (Eigen::Matrix3d() << 0.4124564, 0.3575761, 0.1804375, 0.2126729, 0.7151522, 0.0721750,  //
       0.0193339, 0.1191920, 0.9503041)
          .finished();
  return m;
}
const Eigen::Matrix3d& xyz_to_rgb() {
  static const Eigen::Matrix3d m = rgb_to_xyz().inverse();
  return m;
}
// The reference white is RGB (1, 1, 1) through the same matrix (D65, Y = 1), so that greys have
// a = b = 0 exactly rather than to the matrix's rounding.
const Vec3& white() {
  static const Vec3 w = rgb_to_xyz() * Vec3::Ones();
  return w;
}

// CIE 1976 L*a*b* (CIE 15:2004, section 8.2.1): f(t) = cbrt(t) above (6/29)^3, linear below.
constexpr double kDelta = 6.0 / 29.0;
double lab_f(double t) {
  return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3 * kDelta * kDelta) + 4.0 / 29.0;
}
double lab_f_inverse(double f) {
  return f > kDelta ? f * f * f : 3 * kDelta * kDelta * (f - 4.0 / 29.0);
}

// Slices of a colour ray for the walk: the distance along a ray is smooth, so a few suffice to
// find its first crossing of the sphere.
constexpr int kColourSlices = 16;
// Samples of a ray when looking for where it leaves the valid range, then halvings.
constexpr int kGamutScan = 256;
constexpr int kBisections = 64;

// Exact: a tolerance would let a colour on the edge of the range (black, a saturated primary)
// step outside by it and report that step as a neighbour. The ray's origin is never tested.
bool in_range(const Rgb& c, double max) {
  return (c >= 0).all() && (c <= max).all();
}

// How far the ray lab + s * direction (s >= 0) stays inside the valid range.
double gamut_limit(const Vec3& lab, const Vec3& direction, double max) {
  // Over RGB in [0, max] the CIELAB f spans [4/29, cbrt(max)], so L, a and b span at most 116,
  // 1000 and 400 times that: no two valid colours are farther apart than `reach`.
  const double reach = 1100 * (std::cbrt(max) - 4.0 / 29.0);
  double lo = 0;
  for (int i = 1; i <= kGamutScan; ++i) {
    double hi = reach * i / kGamutScan;
    if (in_range(lab_to_rgb(lab + hi * direction), max)) {
      lo = hi;
      continue;
    }
    for (int k = 0; k < kBisections; ++k) {
      const double mid = 0.5 * (lo + hi);
      (in_range(lab_to_rgb(lab + mid * direction), max) ? lo : hi) = mid;
    }
    return lo;
  }
  return reach;
}

Path colour_path(const Material& m, ColourTerm term, const Vec3& direction, std::string label) {
  const bool diffuse = term == ColourTerm::diffuse;
  const double max = diffuse ? kRhoDMax : kRhoSMax;
  const Vec3 lab = rgb_to_lab(diffuse ? m.rho_d : m.rho_s);
  const double end = gamut_limit(lab, direction, max);
  std::vector<double> breaks{0.0};
  if (end > 0)
    for (int i = 1; i <= kColourSlices; ++i) breaks.push_back(end * i / kColourSlices);
  auto material = [m, diffuse, max, lab, direction](double s) {
    Material out = m;
    if (s <= 0) return out;  // exactly the current colour
    const Rgb c = lab_to_rgb(lab + s * direction).max(0.0).min(max);
    (diffuse ? out.rho_d : out.rho_s) = c;
    return out;
  };
  return {std::move(label), std::move(material), std::move(breaks)};
}

}  // namespace

Vec3 rgb_to_lab(const Rgb& rgb) {
  const Vec3 xyz = rgb_to_xyz() * rgb.matrix();
  const double fx = lab_f(xyz.x() / white().x()), fy = lab_f(xyz.y() / white().y()),
               fz = lab_f(xyz.z() / white().z());
  return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

Rgb lab_to_rgb(const Vec3& lab) {
  const double fy = (lab.x() + 16) / 116, fx = fy + lab.y() / 500, fz = fy - lab.z() / 200;
  const Vec3 xyz(white().x() * lab_f_inverse(fx), white().y() * lab_f_inverse(fy),
                 white().z() * lab_f_inverse(fz));
  return (xyz_to_rgb() * xyz).array();
}

std::vector<Path> colour_paths(const Material& m, ColourTerm term) {
  std::vector<Path> paths;
  paths.push_back(colour_path(m, term, Vec3(1, 0, 0), "L+"));
  paths.push_back(colour_path(m, term, Vec3(-1, 0, 0), "L-"));
  for (int degrees = 0; degrees < 360; degrees += 45) {
    const double angle = degrees * std::numbers::pi / 180;
    paths.push_back(colour_path(m, term, Vec3(0, std::cos(angle), std::sin(angle)),
                                "ab+" + std::to_string(degrees)));
  }
  return paths;
}

}  // namespace brdfnav::nav
