#include "env_tree.h"

#include "geometry.h"

namespace brdfnav {

LatLongRect lat_long_rect(double x0, double x1, double y0, double y1, int width, int height) {
  // Angles of the edges; the differences below are written in forms without cancellation, as
  // pieces of texels can be tiny.
  const double phi_m = kPi * ((x0 + x1) / width - 1), half_dphi = kPi * (x1 - x0) / width;
  const double theta_m = kPi * (y0 + y1) / (2 * height), dtheta = kPi * (y1 - y0) / height;
  const double sin_tm = std::sin(theta_m), sin_hd = std::sin(dtheta / 2);
  // integral of sin^2(theta) over [theta0, theta1]
  const double s2 = 0.5 * ((dtheta - std::sin(dtheta)) + 2 * std::sin(dtheta) * sin_tm * sin_tm);
  const double sin_hp = std::sin(half_dphi);
  LatLongRect r;
  r.moment = Vec3(-s2 * 2 * std::sin(phi_m) * sin_hp,
                  0.5 * std::sin(2 * theta_m) * std::sin(dtheta) * 2 * half_dphi,
                  s2 * 2 * std::cos(phi_m) * sin_hp);
  r.solid_angle = 2 * half_dphi * 2 * sin_tm * sin_hd;
  r.centre = EnvMap::direction((x0 + x1) / (2.0 * width), (y0 + y1) / (2.0 * height));
  const double theta0 = kPi * y0 / height, theta1 = kPi * y1 / height;
  const double max_sin =
      (theta0 <= kPi / 2 && kPi / 2 <= theta1) ? 1.0 : std::max(std::sin(theta0), std::sin(theta1));
  r.half_extent = std::hypot(dtheta / 2, half_dphi * max_sin);
  return r;
}

namespace {

// Covariance of the directions of a small lat-long rectangle about its centre, in the tangent
// plane: (d theta)^2 / 12 along e_theta, (d phi sin theta)^2 / 12 along e_phi.
Eigen::Matrix3d rect_spread(double x0, double x1, double y0, double y1, int width, int height) {
  const double phi = kPi * ((x0 + x1) / width - 1), theta = kPi * (y0 + y1) / (2 * height);
  const double dphi = 2 * kPi * (x1 - x0) / width, dtheta = kPi * (y1 - y0) / height;
  const double st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
  const Vec3 e_theta(-ct * sp, -st, ct * cp), e_phi(-cp, 0, -sp);
  return dtheta * dtheta / 12 * e_theta * e_theta.transpose() +
         (dphi * st) * (dphi * st) / 12 * e_phi * e_phi.transpose();
}

// Largest angle between `centroid` and the rectangle [x0, x1] x [y0, y1] (texel units). Small
// rectangles are nearly flat: the centre's offset plus the half diagonal. On larger ones the
// farthest point is on the boundary: corners and edge midpoints, with a margin for the bulge of
// the edges between them.
double node_radius(const Vec3& centroid, const LatLongRect& rect, double x0, double x1, double y0,
                   double y1, int width, int height) {
  if (x1 - x0 <= 2) return std::min(kPi, angle_between(centroid, rect.centre) + rect.half_extent);
  double radius = 0;
  for (double u : {x0, 0.5 * (x0 + x1), x1})
    for (double v : {y0, 0.5 * (y0 + y1), y1})
      radius = std::max(radius, angle_between(centroid, EnvMap::direction(u / width, v / height)));
  return std::min(kPi, radius * 1.05);
}

void store(float* d, const EnvNode& n) {
  for (int c = 0; c < 3; ++c) d[c] = static_cast<float>(n.centroid[c]);
  for (int c = 0; c < 3; ++c) d[3 + c] = static_cast<float>(n.power[c]);
  d[6] = static_cast<float>(n.radius);
  const Eigen::Matrix3d& s = n.spread;
  const double packed[6] = {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(0, 2), s(1, 2)};
  for (int c = 0; c < 6; ++c) d[7 + c] = static_cast<float>(packed[c]);
}

EnvNode load(const float* d) {
  EnvNode n;
  n.centroid = Vec3(d[0], d[1], d[2]);
  n.power = Rgb(d[3], d[4], d[5]);
  n.radius = d[6];
  n.spread << d[7], d[10], d[11], d[10], d[8], d[12], d[11], d[12], d[9];
  return n;
}

}  // namespace

EnvTree::Moments& EnvTree::Moments::operator+=(const Moments& o) {
  weight += o.weight;
  first += o.first;
  second += o.second;
  return *this;
}

EnvTree::EnvTree(const EnvMap& env) : radiance_(env.pixels()) {
  std::vector<NodeMoments> moments = build_first_level(env);
  while (levels_.back().height > 1 || levels_.back().width > 2) moments = build_parent(moments);
}

// The node whose directions have these moments: centroid = direction of the mean, spread = their
// covariance about the centroid, projected onto its tangent plane.
EnvNode EnvTree::node_from(const Moments& m, const Rgb& power, int level, int x, int y) const {
  const Vec3 mean = m.first / m.weight;
  const Vec3 c = mean.normalized();
  const Eigen::Matrix3d about_c =
      m.second / m.weight - mean * c.transpose() - c * mean.transpose() + c * c.transpose();
  const Eigen::Matrix3d tangent = Eigen::Matrix3d::Identity() - c * c.transpose();
  const double size = std::ldexp(1.0, level), w = texel_width(), h = texel_height();
  const double x0 = x * size, x1 = std::min(w, (x + 1) * size);
  const double y0 = y * size, y1 = std::min(h, (y + 1) * size);
  const LatLongRect rect = lat_long_rect(x0, x1, y0, y1, texel_width(), texel_height());
  return {c, power, node_radius(c, rect, x0, x1, y0, y1, texel_width(), texel_height()),
          tangent * about_c * tangent};
}

// Level 0 (the texels) is stored directly; its moments are only summed into level 1.
std::vector<EnvTree::NodeMoments> EnvTree::build_first_level(const EnvMap& env) {
  const int w = env.width(), h = env.height();
  Level texels;
  texels.width = w;
  texels.height = h;
  texels.data.resize(kStride * static_cast<std::size_t>(w) * h);
  const int pw = (w + 1) / 2, ph = (h + 1) / 2;
  std::vector<NodeMoments> parents(static_cast<std::size_t>(pw) * ph);
  std::vector<Rgb> parent_power(parents.size(), Rgb::Zero());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const LatLongRect rect = lat_long_rect(x, x + 1, y, y + 1, w, h);
      const Eigen::Matrix3d spread = rect_spread(x, x + 1, y, y + 1, w, h);
      const Vec3 c = rect.moment.normalized();
      const Rgb power = env.texel(x, y) * rect.solid_angle;
      store(&texels.data[kStride * (static_cast<std::size_t>(y) * w + x)],
            {c, power, node_radius(c, rect, x, x + 1, y, y + 1, w, h), spread});
      const Eigen::Matrix3d second = c * c.transpose() + spread;
      const double lum = luminance(env.texel(x, y));
      NodeMoments& parent = parents[static_cast<std::size_t>(y / 2) * pw + x / 2];
      parent.lit += {lum * rect.solid_angle, lum * rect.moment, lum * rect.solid_angle * second};
      parent.geometric += {rect.solid_angle, rect.moment, rect.solid_angle * second};
      parent_power[static_cast<std::size_t>(y / 2) * pw + x / 2] += power;
    }
  }
  levels_.push_back(std::move(texels));
  store_level(pw, ph, parents, parent_power);
  return parents;
}

// The parent of the current top level: powers and moments add up, so the centroid and spread of
// any node are those of its texels, however coarse the node.
std::vector<EnvTree::NodeMoments> EnvTree::build_parent(const std::vector<NodeMoments>& child) {
  const Level& below = levels_.back();
  const int pw = (below.width + 1) / 2, ph = (below.height + 1) / 2;
  std::vector<NodeMoments> parents(static_cast<std::size_t>(pw) * ph);
  std::vector<Rgb> power(parents.size(), Rgb::Zero());
  for (int y = 0; y < below.height; ++y) {
    for (int x = 0; x < below.width; ++x) {
      const std::size_t j = static_cast<std::size_t>(y) * below.width + x;
      const std::size_t i = static_cast<std::size_t>(y / 2) * pw + x / 2;
      parents[i].lit += child[j].lit;
      parents[i].geometric += child[j].geometric;
      power[i] += load(&below.data[kStride * j]).power;
    }
  }
  store_level(pw, ph, parents, power);
  return parents;
}

void EnvTree::store_level(int width, int height, const std::vector<NodeMoments>& moments,
                          const std::vector<Rgb>& power) {
  Level level;
  level.width = width;
  level.height = height;
  level.data.resize(kStride * moments.size());
  const int this_level = static_cast<int>(levels_.size());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      const NodeMoments& m = moments[i];
      const bool lit = m.lit.weight > 0 && m.lit.first.squaredNorm() > 0;
      store(&level.data[kStride * i],
            node_from(lit ? m.lit : m.geometric, power[i], this_level, x, y));
    }
  }
  levels_.push_back(std::move(level));
}

EnvNode EnvTree::node(int level, int x, int y) const {
  if (level < 0) return piece(level, x, y);
  const Level& l = levels_[level];
  return load(&l.data[kStride * (static_cast<std::size_t>(y) * l.width + x)]);
}

EnvNode EnvTree::piece(int level, int x, int y) const {
  const double size = std::ldexp(1.0, level);
  const double x0 = x * size, y0 = y * size;
  const int w = texel_width(), h = texel_height();
  const LatLongRect rect = lat_long_rect(x0, x0 + size, y0, y0 + size, w, h);
  const int tx = x >> -level, ty = y >> -level;
  const float* l = &radiance_[3 * (static_cast<std::size_t>(ty) * w + tx)];
  const Vec3 c = rect.moment.normalized();
  return {c, Rgb(l[0], l[1], l[2]) * rect.solid_angle,
          node_radius(c, rect, x0, x0 + size, y0, y0 + size, w, h),
          rect_spread(x0, x0 + size, y0, y0 + size, w, h)};
}

}  // namespace brdfnav
