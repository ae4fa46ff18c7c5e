#include "color.h"

#include <brdfnav/core/cielab.h>

#include <cmath>
#include <numbers>

namespace brdfnav::nav {

namespace {

// Slices of a colour ray for the walk: the distance along a ray is smooth, so a few suffice to
// find its first crossing of the sphere.
constexpr int kColorSlices = 16;
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
    if (in_range(rec709_from_lab(lab + hi * direction), max)) {
      lo = hi;
      continue;
    }
    for (int k = 0; k < kBisections; ++k) {
      const double mid = 0.5 * (lo + hi);
      (in_range(rec709_from_lab(lab + mid * direction), max) ? lo : hi) = mid;
    }
    return lo;
  }
  return reach;
}

Path color_path(const Material& m, ColorTerm term, const Vec3& direction, std::string label) {
  const bool diffuse = term == ColorTerm::diffuse;
  const double max = diffuse ? kRhoDMax : kRhoSMax;
  const Vec3 lab = lab_from_rec709(diffuse ? m.rho_d : m.rho_s);
  const double end = gamut_limit(lab, direction, max);
  std::vector<double> breaks{0.0};
  if (end > 0)
    for (int i = 1; i <= kColorSlices; ++i) breaks.push_back(end * i / kColorSlices);
  auto material = [m, diffuse, max, lab, direction](double s) {
    Material out = m;
    if (s <= 0) return out;  // exactly the current colour
    const Rgb c = rec709_from_lab(lab + s * direction).max(0.0).min(max);
    (diffuse ? out.rho_d : out.rho_s) = c;
    return out;
  };
  return {std::move(label), std::move(material), std::move(breaks)};
}

}  // namespace

std::vector<Path> color_paths(const Material& m, ColorTerm term) {
  std::vector<Path> paths;
  paths.push_back(color_path(m, term, Vec3(1, 0, 0), "L+"));
  paths.push_back(color_path(m, term, Vec3(-1, 0, 0), "L-"));
  for (int degrees = 0; degrees < 360; degrees += 45) {
    const double angle = degrees * std::numbers::pi / 180;
    paths.push_back(color_path(m, term, Vec3(0, std::cos(angle), std::sin(angle)),
                               "ab+" + std::to_string(degrees)));
  }
  return paths;
}

}  // namespace brdfnav::nav
