#include <brdfnav/core/math.h>

namespace brdfnav {

namespace {
// Shirley-Chiu concentric map of [0,1)^2 onto the unit disk (area-preserving, low distortion).
Vec2 concentric_disk(const Vec2& u) {
  const Vec2 o = 2.0 * u - Vec2(1, 1);
  if (o.x() == 0 && o.y() == 0) return Vec2(0, 0);
  double r, theta;
  if (std::abs(o.x()) > std::abs(o.y())) {
    r = o.x();
    theta = kPi / 4 * (o.y() / o.x());
  } else {
    r = o.y();
    theta = kPi / 2 - kPi / 4 * (o.x() / o.y());
  }
  return r * Vec2(std::cos(theta), std::sin(theta));
}
}  // namespace

Vec3 sample_cosine_hemisphere(const Vec2& u) {
  const Vec2 d = concentric_disk(u);
  return Vec3(d.x(), d.y(), safe_sqrt(1.0 - d.squaredNorm()));
}

Vec3 sample_cos_power(const Vec2& u, double n) {
  const double cos_theta = std::pow(u[0], 1.0 / (n + 1.0));
  return spherical_direction(safe_sqrt(1.0 - cos_theta * cos_theta), cos_theta, 2 * kPi * u[1]);
}

}  // namespace brdfnav
