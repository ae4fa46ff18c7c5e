// A material's closure: f = rho_d / pi + rho_s * lobe(wi, wo), evaluated and importance-sampled
// in the local shading frame. Each lobe is a small value type with the same methods
// (eval, sample, pdf, albedo_hint); He et al. also has a mirror (delta) term.
#pragma once

#include <brdfnav/core/blinn_phong.h>
#include <brdfnav/core/cook_torrance.h>
#include <brdfnav/core/ggx.h>
#include <brdfnav/core/he.h>
#include <brdfnav/core/lafortune.h>
#include <brdfnav/core/ward.h>

#include <concepts>
#include <optional>
#include <variant>

namespace brdfnav {

// Alternatives are in ModelId order (models.h).
using Lobe = std::variant<BlinnPhong, Ward, CookTorrance, Lafortune, He, Ggx>;

// A lobe with a mirror (delta) term (He's), whose reflectance at wo is mirror_weight(wo).
// Detected from the type, not registered: the closure samples it, the registry reports it and the
// renderer adds it as a mirror lookup.
template <typename L>
concept MirrorLobe = requires(const L& lobe, const Vec3& wo) {
  { lobe.mirror_weight(wo) } -> std::convertible_to<Rgb>;
};

// A lobe that declares eval() the same in every channel (L::kGrey; all but He's). The renderer
// then sums doubles instead of Rgb; a lobe that does not say so is rendered in colour, slower but
// never wrong.
template <typename L>
concept GreyLobe = requires {
  requires L::kGrey;
};

struct BsdfSample {
  Vec3 wi;     // sampled incident direction, local frame
  Rgb f;       // BRDF value without the cosine; for a delta lobe: reflectance / cos_i
  double pdf;  // solid-angle density; for a delta lobe: the discrete selection probability
  bool delta;  // true for He's mirror term
};

class Closure {
 public:
  Closure(Lobe lobe, const Rgb& rho_d, const Rgb& rho_s)
      : lobe_(std::move(lobe)), rho_d_(rho_d), rho_s_(rho_s) {}

  // f(wi, wo) without the cosine and without delta terms; zero below the horizon.
  Rgb eval(const Vec3& wi, const Vec3& wo) const;
  // Chooses diffuse, glossy lobe or mirror in proportion to their albedo estimates at wo, then
  // samples that component. nullopt when the chosen strategy produced no valid direction.
  // `uc` picks the component, `u` the direction; all in [0, 1).
  std::optional<BsdfSample> sample(const Vec3& wo, double uc, const Vec2& u) const;
  // Solid-angle density of sample() over the non-delta components (integrates to at most 1).
  double pdf(const Vec3& wi, const Vec3& wo) const;

  // The delta lobe's reflectance at wo (rho_s times He's mirror weight; zero for other models).
  Rgb mirror_reflectance(const Vec3& wo) const;

  const Lobe& lobe() const { return lobe_; }
  const Rgb& rho_d() const { return rho_d_; }
  const Rgb& rho_s() const { return rho_s_; }

 private:
  struct Weights {
    double diffuse, lobe, mirror;  // selection probabilities, summing to 1 (or all 0)
  };
  Weights weights(const Vec3& wo) const;
  // pdf() with the strategy weights at wo already known (sample() has them).
  double pdf(const Weights& w, const Vec3& wi, const Vec3& wo) const;

  Lobe lobe_;
  Rgb rho_d_, rho_s_;
};

// The one wrapper that converts frames: world-space directions in, local closure calls inside.
class ShadingClosure {
 public:
  ShadingClosure(const Closure& closure, const Frame& frame) : closure_(closure), frame_(frame) {}

  Rgb eval(const Vec3& wi, const Vec3& wo) const {
    return closure_.eval(frame_.to_local(wi), frame_.to_local(wo));
  }
  std::optional<BsdfSample> sample(const Vec3& wo, double uc, const Vec2& u) const {
    auto s = closure_.sample(frame_.to_local(wo), uc, u);
    if (s) s->wi = frame_.from_local(s->wi);
    return s;
  }
  double pdf(const Vec3& wi, const Vec3& wo) const {
    return closure_.pdf(frame_.to_local(wi), frame_.to_local(wo));
  }

 private:
  const Closure& closure_;
  Frame frame_;
};

}  // namespace brdfnav
