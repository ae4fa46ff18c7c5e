// The integrands of the renderer ("kernels": f * cos as a function of the incident world
// direction at one pixel) and the rough shape of each, which guides the quadrature's refinement.
#pragma once

#include "vector_exp.h"

#include <brdfnav/core/closure.h>
#include <brdfnav/renderer/render.h>

#include <array>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace brdfnav {

// Where a kernel is large: around `peak` (unit), roughly a Gaussian with angular standard
// deviation `major_width` along the tangent `major` and `minor_width` across it, in its narrowest
// channel; channel c is `channel_scale[c]` (>= 1) times wider. `node_width` (<= minor_width)
// is the narrowest feature the nodes must resolve: less than minor_width where the lobe is
// squeezed into a line at grazing angles. Only steers the quadrature: a wrong shape costs time
// or accuracy, never what is summed.
struct KernelShape {
  Vec3 peak;
  Vec3 major;
  double major_width;
  double minor_width;
  double node_width;
  Rgb channel_scale = Rgb::Ones();
  // For a lobe over half vectors given as slope deviations (sx, sy) along the frame's x and y:
  // the quadrature's window is then the ellipse of `reach` deviations in slope space, which
  // follows the lobe where it bends away from the ellipse around its peak (far along the long
  // axis of an anisotropic lobe), instead of that ellipse.
  struct Slopes {
    Frame frame;  // local to world
    Vec3 wo;      // local
    double sx, sy;
  };
  std::optional<Slopes> slopes = std::nullopt;
  // For a lobe over slopes whose kernel is smooth at the scale of the distance from its peak (a
  // heavy tail, GGX's), 0 otherwise: a node rho deviations of `slopes` from the peak may be
  // max(1, node_growth * rho) times as wide as node_width, the finest nodes only around the peak.
  double node_growth = 0;

  static KernelShape isotropic(const Vec3& peak, double width);
  KernelShape to_world(const Frame& frame) const {
    KernelShape s{frame.from_local(peak),
                  frame.from_local(major),
                  major_width,
                  minor_width,
                  node_width,
                  channel_scale,
                  slopes,
                  node_growth};
    if (s.slopes) s.slopes->frame = frame;
    return s;
  }
};

// A kernel's value is a double (grey kernels) or an Rgb.
template <typename V>
V zero() {
  if constexpr (std::is_same_v<V, double>)
    return 0.0;
  else
    return V::Zero();
}
// ... or a batch of Rgbs, one per lobe of a batch rendered together (FresnelBatchKernel).
template <int N>
using Values = Eigen::Array<double, N, 1>;
inline bool positive(double k) {
  return k > 0;
}
template <int N>
bool positive(const Values<N>& k) {
  return (k > 0).any();
}
inline double max0(double k) {
  return std::max(k, 0.0);
}
template <int N>
Values<N> max0(const Values<N>& k) {
  return k.cwiseMax(0);
}
// power * K, what the quadrature sums: an Rgb, or one Rgb per lobe of a batch.
inline Rgb weighted(const Rgb& power, double k) {
  return power * k;
}
inline Rgb weighted(const Rgb& power, const Rgb& k) {
  return power * k;
}
template <int N>
Values<N> weighted(const Rgb& power, const Values<N>& k) {
  return power.replicate<N / 3, 1>() * k;
}

// A lobe seen from one wo: L::Bound where the lobe computes its wo terms once (Ward, He), else
// the lobe and wo.
template <typename L>
struct AtWo {
  const L& lobe;
  Vec3 wo;
  Rgb eval(const Vec3& wi) const { return lobe.eval(wi, wo); }
};
template <typename L>
auto bind_wo(const L& lobe, const Vec3& wo) {
  if constexpr (requires { lobe.bind(wo); })
    return lobe.bind(wo);
  else
    return AtWo<L>{lobe, wo};
}

// rho_s = 1 lobe of a closure times the cosine, in the frame of one pixel: a double for grey
// lobes, an Rgb otherwise.
template <typename L>
struct LobeKernel {
  using Value = std::conditional_t<GreyLobe<L>, double, Rgb>;
  using Bound = decltype(bind_wo(std::declval<const L&>(), Vec3()));
  LobeKernel(const L& lobe, const Frame& frame, const Vec3& wo)
      : lobe(bind_wo(lobe, wo)), frame(frame) {}

  Value value(const Vec3& wi_world) const { return value_local(frame.to_local(wi_world)); }
  // ... at wi in the pixel's frame (the frame of the lobe's KernelShape::Slopes).
  Value value_local(const Vec3& wi) const {
    if (wi.z() <= 0) return zero<Value>();
    if constexpr (requires { lobe.eval_cos(wi); })
      return lobe.eval_cos(wi);
    else if constexpr (GreyLobe<L>)
      return lobe.eval(wi)[0] * wi.z();
    else
      return lobe.eval(wi) * wi.z();
  }
  // value_local() at n local directions at once, stored as x[0..n), y = x + n, z = x + 2n, for
  // lobes that take arrays (Ward's): K is then 0 or NaN below the horizon (Quadrature checks).
  void values_local(const double* x, Eigen::Index n, double* out) const requires
      requires(const Bound& b, const Eigen::Map<const Eigen::ArrayXd>& a,
               Eigen::Ref<Eigen::ArrayXd> o) {
    b.eval_cos(a, a, a, o, exp_in_place);
  }
  {
    using Column = Eigen::Map<const Eigen::ArrayXd>;
    const Column cx(x, n), cy(x + n, n), cz(x + 2 * n, n);
    lobe.eval_cos(cx, cy, cz, Eigen::Map<Eigen::ArrayXd>(out, n), exp_in_place);
  }

 private:
  Bound lobe;
  Frame frame;
};

// The parameter of the lobes that a batch rendered together varies: the one the Fresnel factor
// alone depends on (He's eta, Cook-Torrance's f0), or none. A lobe that names one needs
// bind(wo).eval_fresnel() and an operator== (shares_quadrature() compares the rest with it).
template <typename L>
inline constexpr double L::*kFresnelParameter = nullptr;
template <>
inline constexpr double He::*kFresnelParameter<He> = &He::eta;
template <>
inline constexpr double CookTorrance::*kFresnelParameter<CookTorrance> = &CookTorrance::f0;

// Lobes that differ in kFresnelParameter alone, at most kFresnelBatch of them, times the cosine:
// lobe k in channels 3k..3k+2, the rest zero. Everything but the Fresnel factor is computed once
// per direction; each lobe's channels equal LobeKernel's for it to the bit.
using BatchValue = Values<3 * kFresnelBatch>;
template <typename L>
struct FresnelBatchKernel {
  using Value = BatchValue;
  FresnelBatchKernel(const L& lobe, std::span<const double> params, const Frame& frame,
                     const Vec3& wo)
      : lobe(lobe.bind(wo)), params(params), frame(frame) {}

  Value value(const Vec3& wi_world) const {
    const Vec3 wi = frame.to_local(wi_world);
    Value v = Value::Zero();
    if (wi.z() <= 0) return v;
    std::array<Rgb, kFresnelBatch> each;
    lobe.eval_fresnel(wi, params, each.data());
    for (std::size_t k = 0; k < params.size(); ++k) v.segment<3>(3 * k) = each[k] * wi.z();
    return v;
  }

 private:
  typename L::Bound lobe;
  std::span<const double> params;
  Frame frame;
};

// Lambert with rho_d = 1: cos / pi.
struct LambertKernel {
  using Value = double;
  Vec3 normal;
  double value(const Vec3& wi) const { return std::max(0.0, normal.dot(wi)) * kInvPi; }
};

// He's mirror term without its weight: a normalised von Mises-Fisher filter of angular width
// `width` around the mirror direction, i.e. an environment lookup filtered over the pixel's
// footprint.
struct MirrorKernel {
  using Value = double;
  Vec3 axis;
  double kappa, norm;

  MirrorKernel(const Vec3& mirror, double width) : axis(mirror), kappa(1 / (width * width)) {
    norm = kappa / (2 * kPi * -std::expm1(-2 * kappa));
  }
  double value(const Vec3& wi) const {
    return norm * std::exp(-0.5 * kappa * (wi - axis).squaredNorm());
  }
};

// Shape of the rho_s = 1 lobe of each model seen from `wo`, in the local frame.
KernelShape lobe_shape(const Lobe& lobe, const Vec3& wo);

}  // namespace brdfnav
