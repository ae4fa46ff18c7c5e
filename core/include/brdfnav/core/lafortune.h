// Isotropic single-lobe Lafortune (Lafortune et al. 1997):
// N max(0, cxy (wi.x wo.x + wi.y wo.y) + cz wi.z wo.z)^n with cxy = -sqrt((1 - cz^2) / 2) and
// N = (n + 2) / (2 pi max(|cxy|, |cz|)^n) (docs/CLOSURES.md, The formulas).
#pragma once

#include <brdfnav/core/math.h>
#include <brdfnav/core/params.h>

#include <array>
#include <optional>
#include <span>

namespace brdfnav {

struct Lafortune {
  // Dense around cz = 1/sqrt(3), where a cos^n lobe around the mirror direction sits and where
  // the paper (Figure 9) finds almost all of the visual change at large n.
  static constexpr std::array<double, 14> kCzNodes{0.0,     0.3,   0.45, 0.51, 0.54, 0.56, 0.57,
                                                   0.57735, 0.585, 0.6,  0.63, 0.7,  0.82, 1.0};
  static constexpr std::string_view kName = "lafortune";
  static constexpr std::string_view kTitle = "Lafortune";
  static constexpr bool kGrey = true;  // eval() is the same in every channel
  static constexpr std::array<ParamSpec, 2> kParams{{
      {.name = "cz",
       .unit = "1",
       .description = "z weight of the lobe axis; 1/sqrt(3) is a Phong lobe around the mirror",
       .valid_min = 0.0,
       .valid_max = 1.0,
       .default_value = 0.57735026918962573,
       .grid_min = 0.0,
       .grid_max = 1.0,
       .grid_count = 14,
       .scale = Scale::linear,
       .nodes = kCzNodes,
       .more = "highlight towards the normal",
       .less = "highlight towards grazing",
       .kink = 0.57735026918962573},
      {.name = "n",
       .unit = "1",
       .description = "lobe exponent; larger is sharper",
       .valid_min = 0.0,
       .valid_max = 1e6,
       .default_value = 100.0,
       .grid_min = 2.0,
       .grid_max = 16384.0,
       .grid_count = 13,
       .scale = Scale::log,
       .more = "sharper",
       .less = "rougher"},
  }};

  double cz, n, cxy, inv_max_c;

  explicit Lafortune(std::span<const double> p)
      : cz(p[0]),
        n(p[1]),
        cxy(-std::sqrt(std::max(0.0, (1 - p[0] * p[0]) / 2))),
        inv_max_c(1.0 / std::max(std::abs(cxy), std::abs(cz))) {}

  Rgb eval(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return Rgb::Zero();
    // N * dot^n written as (n+2)/(2 pi) * (dot / max|c|)^n: max|c|^n underflows for large n.
    const double dot = wi.dot(weighted(wo)) * inv_max_c;
    if (dot <= 0) return Rgb::Zero();
    return Rgb::Constant((n + 2) / (2 * kPi) * std::pow(dot, n));
  }
  std::optional<Vec3> sample(const Vec3& wo, const Vec2& u) const {
    const Vec3 v = weighted(wo);
    const double len = v.norm();
    if (len <= 0) return std::nullopt;
    const Frame axis = Frame::from_normal(v / len);
    const Vec3 wi = axis.from_local(sample_cos_power(u, n));
    if (wi.z() <= 0) return std::nullopt;
    return wi;
  }
  double pdf(const Vec3& wi, const Vec3& wo) const {
    if (wi.z() <= 0 || wo.z() <= 0) return 0.0;
    const Vec3 v = weighted(wo);
    const double len = v.norm();
    if (len <= 0) return 0.0;
    return cos_power_pdf(wi.dot(v) / len, n);
  }
  // The lobe is (n+2)/(2 pi) (|v|/max|c|)^n cos^n around v = c * wo: its mass is about
  // (|v|/max|c|)^n, times the cosine of the axis. The cosine is floored by what the half of the
  // lobe above the horizon reflects when the axis lies on it (cz = 0): about 0.4/sqrt(n) for
  // large n, 1/pi at n = 1. Without the floor such a lobe is never sampled though f > 0.
  double albedo_hint(const Vec3& wo) const {
    const Vec3 v = weighted(wo);
    const double len = v.norm();
    if (len <= 0) return 0.0;
    return std::pow(len * inv_max_c, n) * std::max(v.z() / len, 0.5 / std::sqrt(n + 2));
  }

 private:
  Vec3 weighted(const Vec3& wo) const { return {cxy * wo.x(), cxy * wo.y(), cz * wo.z()}; }
};

}  // namespace brdfnav
