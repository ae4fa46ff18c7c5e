#include <brdfnav/core/closure.h>

namespace brdfnav {

namespace {
template <typename L>
Rgb lobe_mirror(const L& lobe, const Vec3& wo) {
  if constexpr (MirrorLobe<L>) {
    return lobe.mirror_weight(wo);
  } else {
    return Rgb::Zero();
  }
}
}  // namespace

Rgb Closure::eval(const Vec3& wi, const Vec3& wo) const {
  if (wi.z() <= 0 || wo.z() <= 0) return Rgb::Zero();
  const Rgb lobe = std::visit([&](const auto& l) { return l.eval(wi, wo); }, lobe_);
  return rho_d_ * kInvPi + rho_s_ * lobe;
}

Rgb Closure::mirror_reflectance(const Vec3& wo) const {
  if (wo.z() <= 0) return Rgb::Zero();
  return rho_s_ * std::visit([&](const auto& l) { return lobe_mirror(l, wo); }, lobe_);
}

Closure::Weights Closure::weights(const Vec3& wo) const {
  const double d = luminance(rho_d_);
  const double s =
      luminance(rho_s_) * std::visit([&](const auto& l) { return l.albedo_hint(wo); }, lobe_);
  const double m = luminance(mirror_reflectance(wo));
  const double total = d + s + m;
  if (!(total > 0)) return {0, 0, 0};
  return {d / total, s / total, m / total};
}

std::optional<BsdfSample> Closure::sample(const Vec3& wo, double uc, const Vec2& u) const {
  if (wo.z() <= 0) return std::nullopt;
  const Weights w = weights(wo);
  if (uc < w.mirror) {
    const Vec3 wi(-wo.x(), -wo.y(), wo.z());
    return BsdfSample{wi, mirror_reflectance(wo) / wi.z(), w.mirror, true};
  }
  std::optional<Vec3> wi;
  if (uc < w.mirror + w.diffuse) {
    wi = sample_cosine_hemisphere(u);
  } else if (w.lobe > 0) {
    wi = std::visit([&](const auto& l) { return l.sample(wo, u); }, lobe_);
  }
  if (!wi || wi->z() <= 0) return std::nullopt;
  const double p = pdf(w, *wi, wo);
  if (!(p > 0)) return std::nullopt;
  return BsdfSample{*wi, eval(*wi, wo), p, false};
}

double Closure::pdf(const Vec3& wi, const Vec3& wo) const {
  if (wi.z() <= 0 || wo.z() <= 0) return 0.0;
  return pdf(weights(wo), wi, wo);
}

double Closure::pdf(const Weights& w, const Vec3& wi, const Vec3& wo) const {
  double p = w.diffuse * cosine_hemisphere_pdf(wi.z());
  if (w.lobe > 0) p += w.lobe * std::visit([&](const auto& l) { return l.pdf(wi, wo); }, lobe_);
  return p;
}

}  // namespace brdfnav
