#include "kernels.h"

#include <Eigen/Eigenvalues>

namespace brdfnav {

KernelShape KernelShape::isotropic(const Vec3& peak, double width) {
  const Vec3 other = std::abs(peak.x()) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 major = (other - other.dot(peak) * peak).normalized();
  return {peak, major, width, width, width};
}

namespace {

constexpr double kMaxWidth = 1.0;  // radians; broader lobes are all "broad"
// Reflection squeezes a lobe across the plane of incidence by 2 (wo . h): 2 cos(theta_o) at its
// peak. Below this cosine the window does not follow the squeeze (it would cut rough lobes, for
// which the first-order picture fails).
constexpr double kMinCos = 0.25;

// A lobe over half vectors whose slopes (h.x/h.z, h.y/h.z) have covariance diag(sx^2, sy^2) in
// the local frame, seen from wo. To first order around the mirror direction, reflection maps a
// half-vector offset (du in the plane of incidence, dv across it) to an incident offset
// (2 du, 2 cos_o dv), along e_in = (cos_o cos_phi, cos_o sin_phi, sin_o) and
// e_across = (-sin_phi, cos_phi, 0).
KernelShape half_vector_shape(const Vec3& wo, double sx, double sy) {
  const double sin_o = std::hypot(wo.x(), wo.y());
  const double cp = sin_o > 1e-9 ? wo.x() / sin_o : 1.0, sp = sin_o > 1e-9 ? wo.y() / sin_o : 0.0;
  Eigen::Matrix2d rot;  // local (x, y) -> (in plane, across)
  rot << cp, sp, -sp, cp;
  const Eigen::Matrix2d slopes =
      rot * Eigen::Vector2d(sx * sx, sy * sy).asDiagonal() * rot.transpose();
  auto incident = [&](double cos_o) {  // covariance of the incident offsets (in plane, across)
    const Eigen::Matrix2d jacobian = Eigen::Vector2d(2, 2 * cos_o).asDiagonal();
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(jacobian * slopes * jacobian);
  };
  const double cos_window = std::max(wo.z(), kMinCos);
  // The nodes follow the squeeze further, to 2 (cos(theta_o) + s), where the half vector leans
  // one slope deviation s toward wo (leaning away sends wi below the horizon): seen at grazing
  // angles a lobe is a wedge, as thin as a line at the horizon, across which nodes spaced for the
  // unsqueezed lobe alias. At 320 x 320 the outermost pixels of Cook-Torrance m = 0.015 were 40%
  // too dark, and of m = 0.12 up to 60% too bright.
  const double cos_nodes = std::min(cos_window, std::max(wo.z(), 0.0) + std::max(sx, sy));
  const auto eig = incident(cos_window);  // ascending eigenvalues
  const Eigen::Vector2d axis = eig.eigenvectors().col(1);
  const Vec3 e_in(wo.z() * cp, wo.z() * sp, sin_o), e_across(-sp, cp, 0);
  const Vec3 mirror(-wo.x(), -wo.y(), wo.z());
  auto width = [](double variance) {
    return std::min(kMaxWidth, std::sqrt(std::max(variance, 0.0)));
  };
  const double minor = width(eig.eigenvalues()[0]);
  const double node =  // the same squeeze away from the silhouette: no second solve
      cos_nodes < cos_window ? std::min(minor, width(incident(cos_nodes).eigenvalues()[0])) : minor;
  return {mirror, (axis[0] * e_in + axis[1] * e_across).normalized(), width(eig.eigenvalues()[1]),
          minor, node};
}

KernelShape shape(const BlinnPhong& l, const Vec3& wo) {
  // cos^n(theta_h) ~ exp(-n tan^2(theta_h) / 2)
  const double s = 1 / std::sqrt(l.n + 1);
  return half_vector_shape(wo, s, s);
}

KernelShape shape(const Ward& l, const Vec3& wo) {
  // exp(-(tan(theta_h) cos(phi) / alpha_x)^2 - ...): slope deviations alpha / sqrt(2). The
  // window follows the slopes: an anisotropic Ward lobe bends far from its peak's ellipse.
  const double sx = l.alpha_x / std::sqrt(2.0), sy = l.alpha_y / std::sqrt(2.0);
  KernelShape s = half_vector_shape(wo, sx, sy);
  s.slopes = KernelShape::Slopes{Frame{}, wo, sx, sy};
  return s;
}

KernelShape shape(const CookTorrance& l, const Vec3& wo) {
  return half_vector_shape(wo, l.m / std::sqrt(2.0), l.m / std::sqrt(2.0));
}

KernelShape shape(const Lafortune& l, const Vec3& wo) {
  // A cos^n lobe around c * wo (componentwise).
  const Vec3 axis(l.cxy * wo.x(), l.cxy * wo.y(), l.cz * wo.z());
  const double s = std::min(kMaxWidth, 1 / std::sqrt(l.n + 1));
  return KernelShape::isotropic(axis.squaredNorm() > 1e-24 ? axis.normalized() : Vec3(0, 0, 1), s);
}

KernelShape shape(const He& l, const Vec3& wo) {
  // The directional-diffuse lobe is a Poisson mixture of Gaussians in the projected half vector;
  // its rough limit is Beckmann with slope 2 sigma / tau (the same in every channel), its smooth
  // limit the m = 1 term of width lambda / (sqrt(2) pi tau) in the projected half vector
  // (~ 2 cos_o slope), wider in red than in blue.
  const double cos_o = std::max(wo.z(), kMinCos), rough = std::sqrt(2.0) * l.sigma / l.tau;
  Rgb slope;
  for (int c = 0; c < 3; ++c)
    slope[c] = std::max(rough, He::kLambda[c] / (std::sqrt(8.0) * kPi * l.tau * cos_o));
  KernelShape s = half_vector_shape(wo, slope.minCoeff(), slope.minCoeff());
  s.channel_scale = slope / slope.minCoeff();
  return s;
}

// GGX's D cos_h mass beyond slope t is alpha^2 / (alpha^2 + t^2) (isotropic): a window of
// `reach` (3.5) deviations of its peak leaves a third of the lobe outside. Its window reaches
// slope kGgxReach alpha at the default reach instead, leaving out 1 / (1 + kGgxReach^2) of the
// lobe (0.01%), with nodes for the peak (alpha / sqrt(2)) around it that grow with their distance
// from it (KernelShape::node_growth): beyond the peak D falls like slope^-4, smooth at the scale
// of that distance, so a node there may be kGgxGrowth times its distance in slopes from the peak
// (before texels_per_width). The peak's nodes all the way out exceeded the node budget of smooth
// lobes, and a window to 6 alpha had accuracy ratios of 0.3-0.6. The smooth setting's ratio
// (alpha_x) at 128 x 128 under forest.exr: with a window to 40 alpha, 0.098-0.100 at growth
// 0.2-0.3, 0.107 at 0.4, 0.130 at 0.5; to 100 alpha, 0.055 at 0.3 and 0.072 at 0.4, which takes
// a third fewer of the smooth lobe's nodes (docs/RENDERER.md, point 10).
constexpr double kGgxReach = 100, kGgxGrowth = 0.4, kDefaultReach = 3.5;

KernelShape shape(const Ggx& l, const Vec3& wo) {
  const double ax = l.alpha_x, ay = l.alpha_y, window = kGgxReach / kDefaultReach;
  const double node = 1 / std::sqrt(2.0);
  KernelShape s = half_vector_shape(wo, window * ax, window * ay);
  s.node_width = half_vector_shape(wo, node * ax, node * ay).node_width;
  s.slopes = KernelShape::Slopes{Frame{}, wo, window * ax, window * ay};
  s.node_growth = kGgxGrowth * window / node;  // per deviation of the window
  return s;
}

}  // namespace

KernelShape lobe_shape(const Lobe& lobe, const Vec3& wo) {
  return std::visit([&](const auto& l) { return shape(l, wo); }, lobe);
}

}  // namespace brdfnav
