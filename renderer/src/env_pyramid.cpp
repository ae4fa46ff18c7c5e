#include "env_pyramid.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace brdfnav {

namespace {

// Texels brighter than kHotFactor times the map's mean luminance are hot, at most kMaxHot of
// them (the brightest). On interior.exr that is about 100 texels holding 40% of the power.
constexpr double kHotFactor = 100;
constexpr std::size_t kMaxHot = 512;

// The lat-long rectangle of texel coordinates [x0, x1] x [y0, y1] of a map `width` x `height`.
struct LatLongRect {
  double solid_angle;
  Vec3 centroid;  // unit
};

// What the rectangle's solid angle and centroid take from its rows [y0, y1] ...
struct LatLongRows {
  double sin_tm, sin_hd;
  double s2;       // integral of sin^2(theta) over [theta0, theta1]
  double y_share;  // the centroid's y moment over 2 * half_dphi
};
// The differences are written in forms without cancellation: the rows by the poles are thin.
LatLongRows lat_long_rows(double y0, double y1, int height) {
  const double theta_m = kPi * (y0 + y1) / (2 * height), dtheta = kPi * (y1 - y0) / height;
  const double sin_tm = std::sin(theta_m);
  return {sin_tm, std::sin(dtheta / 2),
          0.5 * ((dtheta - std::sin(dtheta)) + 2 * std::sin(dtheta) * sin_tm * sin_tm),
          0.5 * std::sin(2 * theta_m) * std::sin(dtheta)};
}
// ... and from its columns [x0, x1].
struct LatLongColumns {
  double half_dphi, sin_phi_m, cos_phi_m, sin_hp;
};
LatLongColumns lat_long_columns(double x0, double x1, int width) {
  const double phi_m = kPi * ((x0 + x1) / width - 1), half_dphi = kPi * (x1 - x0) / width;
  return {half_dphi, std::sin(phi_m), std::cos(phi_m), std::sin(half_dphi)};
}
LatLongRect lat_long_rect(const LatLongRows& r, const LatLongColumns& c) {
  const Vec3 moment(-r.s2 * 2 * c.sin_phi_m * c.sin_hp, r.y_share * 2 * c.half_dphi,
                    r.s2 * 2 * c.cos_phi_m * c.sin_hp);
  return {2 * c.half_dphi * 2 * r.sin_tm * r.sin_hd, moment.normalized()};
}
LatLongRect lat_long_rect(double x0, double x1, double y0, double y1, int width, int height) {
  return lat_long_rect(lat_long_rows(y0, y1, height), lat_long_columns(x0, x1, width));
}

}  // namespace

Eigen::Matrix3d EnvPyramid::texel_spread(int x, int y, int width, int height) {
  return texel_spread(texel_frame(x, y, width, height));
}
Eigen::Matrix3d EnvPyramid::texel_spread(const TexelFrame& t) {
  return (t.d_theta * t.d_theta / 12) * t.e_theta * t.e_theta.transpose() +
         (t.d_phi * t.d_phi / 12) * t.e_phi * t.e_phi.transpose();
}
Eigen::Matrix3d EnvPyramid::rounded_texel_spread(int x, int y) const {
  return unpack_spread(pack_spread(texel_spread(frame_of_texel(x, y))).data());
}

EnvPyramid::EnvPyramid(const EnvMap& env) {
  build_texels(env);
  while (levels_.back().width > 2 || levels_.back().height > 1)
    levels_.push_back(half_of(level_count() - 1));
  for (Level& l : levels_) {
    l.luminance = {};
    weigh(l);
  }
  hot_groups_.resize(levels_.size());
  for (int level = 1; level < level_count(); ++level) hot_groups_[level] = group_hot_texels(level);
}

std::vector<EnvPyramid::HotGroup> EnvPyramid::group_hot_texels(int level) const {
  // Node (x >> level, y >> level) of `level` holds level-0 texel (x, y). Groups in node order,
  // members summed in hot_'s order: deterministic.
  std::map<std::pair<int, int>, std::vector<const HotTexel*>> members;
  for (const HotTexel& t : hot_) members[{t.y >> level, t.x >> level}].push_back(&t);
  std::vector<HotGroup> groups;
  for (const auto& [node, texels] : members) {
    HotGroup g{Vec3::Zero(), Rgb::Zero(), 0.0};
    for (const HotTexel* t : texels) {
      const Rgb power = t->radiance * t->solid_angle;
      g.power += power;
      g.centroid += luminance(power) * t->centroid;
    }
    g.centroid.normalize();
    for (const HotTexel* t : texels)
      g.radius = std::max(g.radius, std::acos(std::clamp(g.centroid.dot(t->centroid), -1.0, 1.0)));
    g.radius += node_angle(0);  // a texel's own extent around its centroid
    groups.push_back(g);
  }
  return groups;
}

double luminance_power(const EnvMap& env) {
  double total = 0;
  for (int y = 0; y < env.height(); ++y) {
    const double texel_solid_angle =
        lat_long_rect(0, 1, y, y + 1, env.width(), env.height()).solid_angle;
    for (int x = 0; x < env.width(); ++x) total += luminance(env.texel(x, y)) * texel_solid_angle;
  }
  return total;
}

void EnvPyramid::build_texels(const EnvMap& env) {
  const int w = env.width(), h = env.height();
  const double threshold = kHotFactor * luminance_power(env) / (4 * kPi);
  for (int y = 0; y < h; ++y) {
    const double texel_solid_angle = lat_long_rect(0, 1, y, y + 1, w, h).solid_angle;
    for (int x = 0; x < w; ++x)
      if (threshold > 0 && luminance(env.texel(x, y)) > threshold)
        hot_.push_back({x, y, env.texel(x, y), lat_long_rect(x, x + 1, y, y + 1, w, h).centroid,
                        texel_solid_angle});
  }
  // The brightest first, ties in map order: deterministic.
  std::stable_sort(hot_.begin(), hot_.end(), [](const HotTexel& a, const HotTexel& b) {
    return luminance(a.radiance) > luminance(b.radiance);
  });
  if (hot_.size() > kMaxHot) hot_.resize(kMaxHot);

  const std::size_t count = static_cast<std::size_t>(w) * h;
  Level texels{w,
               h,
               std::vector<float>(3 * count),
               std::vector<float>(3 * count),
               std::vector<float>(3 * count),
               {},
               std::vector<double>(count)};
  // Every angle a texel's terms need is its row's or its column's: computed once each.
  std::vector<LatLongColumns> columns;
  for (int x = 0; x < w; ++x) {
    columns.push_back(lat_long_columns(x, x + 1, w));
    texel_phis_.push_back(texel_phi(x, w));
  }
  for (int y = 0; y < h; ++y) texel_thetas_.push_back(texel_theta(y, h));
  for (int y = 0; y < h; ++y) {
    const LatLongRows rows = lat_long_rows(y, y + 1, h);
    for (int x = 0; x < w; ++x) {
      const LatLongRect rect = lat_long_rect(rows, columns[x]);
      const std::size_t i = texels.index(x, y);
      const Rgb power = env.texel(x, y) * rect.solid_angle;
      for (int c = 0; c < 3; ++c) texels.centroid[i + c] = static_cast<float>(rect.centroid[c]);
      for (int c = 0; c < 3; ++c) texels.power[i + c] = static_cast<float>(power[c]);
      texels.luminance[i / 3] = luminance(power);
    }
  }
  for (const HotTexel& t : hot_) {
    const std::size_t i = texels.index(t.x, t.y);
    for (int c = 0; c < 3; ++c) texels.power[i + c] = 0.f;
    texels.luminance[i / 3] = 0;
  }
  levels_.push_back(std::move(texels));
}

// A parent's power is its children's sum; its centroid their luminance-weighted mean direction
// (the solid-angle weighted one where they are black, so that it stays inside the node).
EnvPyramid::Level EnvPyramid::half_of(int fine_level) const {
  const Level& fine = levels_[fine_level];
  Level coarse{(fine.width + 1) / 2, (fine.height + 1) / 2, {}, {}, {}, {}, {}};
  const std::size_t count = static_cast<std::size_t>(coarse.width) * coarse.height;
  coarse.centroid.assign(3 * count, 0.f);
  coarse.power.assign(3 * count, 0.f);
  coarse.weight.assign(3 * count, 0.f);
  coarse.spread.assign(6 * count, 0.f);
  coarse.luminance.assign(count, 0.0);
  for (int y = 0; y < coarse.height; ++y) {
    for (int x = 0; x < coarse.width; ++x) {
      Vec3 lit = Vec3::Zero(), plain = Vec3::Zero();
      Rgb power = Rgb::Zero();
      double lum = 0;
      for (int fy = 2 * y; fy < std::min(2 * y + 2, fine.height); ++fy) {
        for (int fx = 2 * x; fx < std::min(2 * x + 2, fine.width); ++fx) {
          const std::size_t j = fine.index(fx, fy);
          const Vec3 c = fine.centroid_at(j);
          lit += fine.luminance[j / 3] * c;
          plain += c;
          power += rgb(fine.power, j);
          lum += fine.luminance[j / 3];
        }
      }
      const std::size_t i = coarse.index(x, y);
      const bool lit_up = lum > 0 && lit.squaredNorm() > 0;
      const Vec3 centroid = (lit_up ? lit : plain).normalized();
      // The children's spreads and their offsets from the centroid, weighed as the centroid is.
      Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
      double total = 0;
      for (int fy = 2 * y; fy < std::min(2 * y + 2, fine.height); ++fy) {
        for (int fx = 2 * x; fx < std::min(2 * x + 2, fine.width); ++fx) {
          const std::size_t j = fine.index(fx, fy);
          const double weight = lit_up ? fine.luminance[j / 3] : 1.0;
          const Vec3 offset = fine.centroid_at(j) - centroid;
          spread += weight * (this->spread(fine_level, fx, fy) + offset * offset.transpose());
          total += weight;
        }
      }
      const std::array<float, 6> packed = pack_spread(spread / total);
      std::copy(packed.begin(), packed.end(), &coarse.spread[2 * i]);
      for (int c = 0; c < 3; ++c) coarse.centroid[i + c] = static_cast<float>(centroid[c]);
      for (int c = 0; c < 3; ++c) coarse.power[i + c] = static_cast<float>(power[c]);
      coarse.luminance[i / 3] = lum;
    }
  }
  return coarse;
}

// Neighbours along a row wrap around; the first and last rows have none beyond the pole.
void EnvPyramid::weigh(Level& level) {
  const int w = level.width, h = level.height;
  auto power = [&](int x, int y) { return rgb(level.power, level.index(x, y)); };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Rgb own = power(x, y);
      Rgb differences = power(x > 0 ? x - 1 : w - 1, y) + power(x + 1 < w ? x + 1 : 0, y) - 2 * own;
      if (y > 0) differences += power(x, y - 1) - own;
      if (y + 1 < h) differences += power(x, y + 1) - own;
      const Rgb weight = own + differences * kSecondDifferenceFactor;
      const std::size_t i = level.index(x, y);
      for (int c = 0; c < 3; ++c) level.weight[i + c] = static_cast<float>(weight[c]);
    }
  }
}

}  // namespace brdfnav
