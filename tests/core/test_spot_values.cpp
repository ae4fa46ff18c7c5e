// Spot values of the lobes, derived by hand from the formulas of docs/CLOSURES.md (The formulas) at
// directions chosen so the half vector is simple. Every literal is printed by a python3 one-liner
// given next to it, run with this preamble P:
//   P='from math import *; d=lambda t,p: (sin(radians(t))*cos(radians(p)),
//      sin(radians(t))*sin(radians(p)), cos(radians(t))); dot=lambda a,b: sum(x*y for x,y in
//      zip(a,b))'
//   python3 -c "$P; <one-liner>"
// d(theta, phi) in degrees is the same direction as dir() below.
#include <brdfnav/core/material.h>
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

namespace brdfnav {
namespace {

// The lobes and the closure are deterministic formulas: only rounding separates them from the
// python values.
constexpr double kRelTol = 1e-9;

Vec3 dir(double theta_deg, double phi_deg) {
  const double t = theta_deg * kPi / 180, p = phi_deg * kPi / 180;
  return spherical_direction(std::sin(t), std::cos(t), p);
}

void expect_rel(double actual, double expected) {
  EXPECT_NEAR(actual, expected, kRelTol * std::abs(expected));
}

// The lobes return a grey Rgb; every channel must carry the value.
void expect_grey(const Rgb& actual, double expected) {
  for (int ch = 0; ch < 3; ++ch) expect_rel(actual[ch], expected);
}

// ---------------------------------------------------------------------------------------------
// Blinn-Phong: lobe = (n+2)/(8 pi) cos_h^n, pdf = (n+1)/(2 pi) cos_h^n / (4 wo.h)

TEST(SpotBlinnPhong, HalfVectorAtThirtyDegrees) {
  // wi = normal, wo at 60 deg: h bisects them at 30 deg, cos_h = cos 30, wo.h = cos 30.
  const BlinnPhong lobe(std::array{10.0});
  const Vec3 wi = dir(0, 0), wo = dir(60, 0);
  // print(repr((10+2)/(8*pi)*cos(radians(30))**10))
  expect_grey(lobe.eval(wi, wo), 0.1133046421035076);
  // print(repr((10+1)/(2*pi)*cos(radians(30))**10/(4*cos(radians(30)))))
  expect_rel(lobe.pdf(wi, wo), 0.1199301869679729);
}

TEST(SpotBlinnPhong, MirrorPairWithNonIntegerExponent) {
  // wi and wo mirror each other about the normal: h = normal, cos_h = 1, wo.h = cos 37.
  const BlinnPhong lobe(std::array{37.5});
  const Vec3 wi = dir(37, 0), wo = dir(37, 180);
  // print(repr((37.5+2)/(8*pi)))
  expect_grey(lobe.eval(wi, wo), 1.5716550630324666);
  // print(repr((37.5+1)/(2*pi)/(4*cos(radians(37)))))
  expect_rel(lobe.pdf(wi, wo), 1.9181044518904249);
}

// ---------------------------------------------------------------------------------------------
// Ward: exp(-((H.x/ax)^2 + (H.y/ay)^2) / H.z^2) / (4 pi ax ay sqrt(cos_i cos_o)), H = wi + wo

TEST(SpotWard, AlphaXStretchesTheLobeAlongX) {
  // wo = normal, wi at 20 deg: H.x/H.z (or H.y/H.z) = sin 20 / (1 + cos 20) = tan 10.
  // With alpha_x = 0.3 > alpha_y = 0.1, tilting h along x costs less than along y.
  const Ward lobe(std::array{0.3, 0.1});
  const Vec3 wo = dir(0, 0);
  // print(repr(exp(-(tan(radians(10))/0.3)**2)/(4*pi*0.3*0.1*sqrt(cos(radians(20))))))
  const double along_wide_axis = 1.9370710320321918;
  // print(repr(exp(-(tan(radians(10))/0.1)**2)/(4*pi*0.3*0.1*sqrt(cos(radians(20))))))
  const double along_narrow_axis = 0.12215243657865237;
  expect_grey(lobe.eval(dir(20, 0), wo), along_wide_axis);
  expect_grey(lobe.eval(dir(20, 90), wo), along_narrow_axis);
  // The opposite order of the alphas swaps the axes.
  const Ward swapped(std::array{0.1, 0.3});
  expect_grey(swapped.eval(dir(20, 90), wo), along_wide_axis);
  expect_grey(swapped.eval(dir(20, 0), wo), along_narrow_axis);
  // pdf = exp(..) / (4 pi ax ay (h.wo) cos_h^3) with h at 10 deg: h.wo = cos_h = cos 10.
  // print(repr(exp(-(tan(radians(10))/0.3)**2)/(4*pi*0.3*0.1*cos(radians(10))*cos(radians(10))**3)))
  expect_rel(lobe.pdf(dir(20, 0), wo), 1.9963313130067433);
}

TEST(SpotWard, GeneralDirections) {
  const Ward lobe(std::array{0.3, 0.1});
  // wi=d(35,30); wo=d(38,215); H=[a+b for a,b in zip(wi,wo)];
  // print(repr(exp(-((H[0]/0.3)**2+(H[1]/0.1)**2)/H[2]**2)/(4*pi*0.3*0.1*sqrt(wi[2]*wo[2]))))
  expect_grey(lobe.eval(dir(35, 30), dir(38, 215)), 2.7836470903359807);
}

TEST(SpotWard, TheRenderersKernelIsTheLobeTimesTheCosine) {
  const Ward lobe(std::array{0.3, 0.1});
  const Vec3 wi = dir(35, 30);
  // The same python value times cos(35 degrees); zero below the horizon.
  expect_rel(lobe.bind(dir(38, 215)).eval_cos(wi), 2.7836470903359807 * wi.z());
  EXPECT_EQ(lobe.bind(dir(38, 215)).eval_cos(dir(95, 30)), 0.0);
  EXPECT_EQ(lobe.bind(dir(95, 215)).eval_cos(wi), 0.0);
}

// A Bound's eval_cos() over arrays of directions (the renderer's slope windows) against its
// eval_cos() at each: directions around the mirror one of wo = dir(38, 215), in a narrow lobe and
// out in its tails, and two below the horizon; the array form takes them as columns of x, y and
// z, with `exp_in_place` for its exponentials.
template <typename Bound, typename Exp>
void expect_array_kernel_is_the_kernel(const Bound& bound, Exp&& exp_in_place, double tolerance) {
  std::vector<Vec3> wi;
  for (double theta : {36.0, 37.9, 38.0, 38.1, 40.0, 60.0, 95.0})
    for (double phi : {30.0, 34.0, 35.0, 36.0, 90.0}) wi.push_back(dir(theta, phi));
  const auto n = static_cast<Eigen::Index>(wi.size());
  Eigen::ArrayXd x(n), y(n), z(n), out(n);
  for (Eigen::Index i = 0; i < n; ++i) x[i] = wi[i].x(), y[i] = wi[i].y(), z[i] = wi[i].z();
  bound.eval_cos(x, y, z, out, exp_in_place);
  int lit = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double expected = bound.eval_cos(wi[i]);
    EXPECT_NEAR(out[i], expected, tolerance * expected) << "direction " << i;
    lit += expected > 1e-3;
  }
  EXPECT_GE(lit, 3);  // the comparison covers the lobe, not only its zero tails
}

TEST(SpotWard, TheKernelOverAnArrayOfDirectionsIsTheKernelAtEach) {
  expect_array_kernel_is_the_kernel(
      Ward(std::array{0.05, 0.005}).bind(dir(38, 215)),
      [](Eigen::Ref<Eigen::ArrayXd> v) {
        for (double& e : v) e = std::exp(e);
      },
      1e-14);
}

// ---------------------------------------------------------------------------------------------
// Cook-Torrance: F(wi.h) D(h) G / (4 cos_i cos_o), Schlick F, Beckmann D,
// G = min(1, 2 cos_h cos_o / (wo.h), 2 cos_h cos_i / (wo.h))

TEST(SpotCookTorrance, SchlickFresnelAtSeventyDegreesWithUnitG) {
  // Mirror pair at 70 deg: h = normal, D = 1 / (pi m^2), wi.h = cos 70 so Schlick's
  // (1 - cos)^5 term is far from zero; G = min(1, 2, 2) = 1.
  const CookTorrance lobe(std::array{0.5, 0.3});
  // F=0.5+0.5*(1-cos(radians(70)))**5; D=1/(pi*0.3**2); print(repr(F*D*1/(4*cos(radians(70))**2)))
  expect_grey(lobe.eval(dir(70, 0), dir(70, 180)), 4.2454232000568455);
}

TEST(SpotCookTorrance, VGrooveMaskingBranch) {
  // wi = normal, wo at 80 deg: h at 40 deg, cos_h = wo.h = cos 40, so the wo term of G is
  // 2 cos 80 = 0.347 (the wi term is 2): masking picks the wo branch.
  const CookTorrance lobe(std::array{0.5, 0.5});
  // ch=cos(radians(40)); F=0.5+0.5*(1-ch)**5; D=exp(-tan(radians(40))**2/0.5**2)/(pi*0.5**2*ch**4);
  // G=min(1, 2*ch*cos(radians(80))/ch, 2*ch*1/ch); print(G, repr(F*D*G/(4*1*cos(radians(80)))))
  expect_grey(lobe.eval(dir(0, 0), dir(80, 0)), 0.055336551938445375);
}

TEST(SpotCookTorrance, VGrooveShadowingBranch) {
  // The same pair swapped: now the wi term 2 cos_h cos_i / (wo.h) = 2 cos 80 is the minimum.
  const CookTorrance lobe(std::array{0.5, 0.5});
  // ch=cos(radians(40)); F=0.5+0.5*(1-ch)**5; D=exp(-tan(radians(40))**2/0.5**2)/(pi*0.5**2*ch**4);
  // G=min(1, 2*ch*1/ch, 2*ch*cos(radians(80))/ch); print(G, repr(F*D*G/(4*cos(radians(80))*1)))
  expect_grey(lobe.eval(dir(80, 0), dir(0, 0)), 0.055336551938445375);
}

TEST(SpotCookTorrance, OffNormalHalfVectorWithUnitG) {
  // wi at 20 deg, wo at 40 deg on the other side: h is 10 deg off the normal, G = 1.
  const CookTorrance lobe(std::array{0.5, 0.5});
  // wi=d(20,0); wo=d(40,180); s=[a+b for a,b in zip(wi,wo)]; h=[x/sqrt(dot(s,s)) for x in s];
  // ch=h[2]; F=0.5+0.5*(1-dot(wi,h))**5; D=exp(-(1-ch*ch)/ch**2/0.5**2)/(pi*0.5**2*ch**4);
  // G=min(1, 2*ch*wo[2]/dot(wo,h), 2*ch*wi[2]/dot(wo,h)); print(G, repr(F*D*G/(4*wi[2]*wo[2])))
  expect_grey(lobe.eval(dir(20, 0), dir(40, 180)), 0.207578468911294);
}

// ---------------------------------------------------------------------------------------------
// Lafortune: N max(0, cxy (wi.x wo.x + wi.y wo.y) + cz wi.z wo.z)^n,
// cxy = -sqrt((1 - cz^2) / 2), N = (n+2) / (2 pi max(|cxy|, cz)^n)

TEST(SpotLafortune, PhongPointIsACosineLobeAroundTheMirror) {
  // cz = 1/sqrt(3) gives cxy = -1/sqrt(3), so the dot is (wi . mirror(wo)) / sqrt(3) and N
  // cancels the 1/sqrt(3)^n: lobe = (n+2)/(2 pi) cos^n(angle between wi and mirror(wo)).
  const Lafortune lobe(std::array{1 / std::sqrt(3.0), 20.0});
  // mirror(d(40, 0)) = d(40, 180); wi = d(55, 180) is 15 deg from it.
  // print(repr((20+2)/(2*pi)*cos(radians(15))**20))
  expect_grey(lobe.eval(dir(55, 180), dir(40, 0)), 1.7503237047947373);

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double ti = u(rng), pi = u(rng), to = u(rng), po = u(rng);  // drawn in this order
    const Vec3 wi = dir(90 * ti, 360 * pi), wo = dir(90 * to, 360 * po);
    const Vec3 mirror(-wo.x(), -wo.y(), wo.z());
    const double phong = (20 + 2) / (2 * kPi) * std::pow(std::max(0.0, wi.dot(mirror)), 20);
    expect_grey(lobe.eval(wi, wo), phong);
  }
}

TEST(SpotLafortune, CzBelowThePhongPointNormalisesByCxy) {
  // cz = 0.5: |cxy| = sqrt(0.375) = 0.612 > cz, so N divides by |cxy|^n.
  const Lafortune lobe(std::array{0.5, 8.0});
  // cz=0.5; cxy=-sqrt((1-cz*cz)/2); n=8; wi=d(25,200); wo=d(40,30);
  // s=cxy*(wi[0]*wo[0]+wi[1]*wo[1])+cz*wi[2]*wo[2];
  // print(repr((n+2)/(2*pi*max(abs(cxy),cz)**n)*max(0,s)**n))
  expect_grey(lobe.eval(dir(25, 200), dir(40, 30)), 0.37394186505507815);
}

TEST(SpotLafortune, CzAboveThePhongPointNormalisesByCz) {
  // cz = 0.8: |cxy| = sqrt(0.18) = 0.424 < cz, so N divides by cz^n.
  const Lafortune lobe(std::array{0.8, 3.0});
  // cz=0.8; cxy=-sqrt((1-cz*cz)/2); n=3; wi=d(25,200); wo=d(40,30);
  // s=cxy*(wi[0]*wo[0]+wi[1]*wo[1])+cz*wi[2]*wo[2];
  // print(repr((n+2)/(2*pi*max(abs(cxy),cz)**n)*max(0,s)**n))
  expect_grey(lobe.eval(dir(25, 200), dir(40, 30)), 0.4652024401282725);
}

// ---------------------------------------------------------------------------------------------
// GGX, written as Cycles 3.4 writes it (bsdf_microfacet_ggx_eval_reflect): the slopes of the
// unit half vector m, (sx, sy) = (-m.x / (m.z ax), -m.y / (m.z ay)),
// D = 1 / ((1 + sx^2 + sy^2)^2 pi ax ay m.z^4), and per direction w
// G1 = 2 / (1 + sqrt(1 + alpha_w^2 tan^2(theta_w))) with alpha_w^2 = cos^2(phi_w) ax^2 +
// sin^2(phi_w) ay^2; f = D G1(wi) G1(wo) / (4 cos_i cos_o), pdf = G1(wo) D / (4 cos_o).

TEST(SpotGgx, IsotropicWithBothDirectionsMasked) {
  const Ggx lobe(std::array{0.2, 0.2});
  const Vec3 wi = dir(25, 10), wo = dir(60, 170);
  // a=0.2; a2=a*a; wi=d(25,10); wo=d(60,170); H=[x+y for x,y in zip(wi,wo)];
  // c=H[2]/sqrt(dot(H,H)); t2=(1-c*c)/(c*c); D=a2/(pi*c**4*(a2+t2)**2);
  // G1=lambda ct: 2/(1+sqrt(1+a2*(1-ct*ct)/(ct*ct)));
  // print(repr(D*G1(wi[2])*G1(wo[2])/(4*wi[2]*wo[2]))); print(repr(G1(wo[2])*D/(4*wo[2])))
  expect_grey(lobe.eval(wi, wo), 0.32761123953544097);
  expect_rel(lobe.pdf(wi, wo), 0.2975608436229698);
  // Reciprocal: the same value with the directions swapped.
  expect_grey(lobe.eval(wo, wi), 0.32761123953544097);
}

TEST(SpotGgx, AlphaXStretchesTheLobeAlongX) {
  // wo = normal (G1 = 1), wi at 20 deg: the half vector leans 10 deg along x or along y.
  const Ggx lobe(std::array{0.3, 0.1});
  const Vec3 wo = dir(0, 0);
  // t=tan(radians(10)); c=cos(radians(10)); ci=cos(radians(20));
  // G1=lambda a,ct: 2/(1+sqrt(1+a*a*(1-ct*ct)/(ct*ct)));
  // print(repr(1/((1+(t/0.3)**2)**2*pi*0.3*0.1*c**4)*G1(0.3,ci)/(4*ci)))
  expect_grey(lobe.eval(dir(20, 0), wo), 1.6529065939505447);
  // print(repr(1/((1+(t/0.1)**2)**2*pi*0.3*0.1*c**4)*G1(0.1,ci)/(4*ci)))
  expect_grey(lobe.eval(dir(20, 90), wo), 0.17767884906614292);
}

TEST(SpotGgx, GeneralDirections) {
  const Ggx lobe(std::array{0.3, 0.1});
  // ax,ay=0.3,0.1; wi=d(35,30); wo=d(38,215); H=[a+b for a,b in zip(wi,wo)]; n=sqrt(dot(H,H));
  // m=[x/n for x in H]; sx=-m[0]/(m[2]*ax); sy=-m[1]/(m[2]*ay); L=1+sx*sx+sy*sy;
  // D=1/(L*L*pi*ax*ay*m[2]**4); G1=lambda w: 2/(1+sqrt(1+(w[0]**2*ax**2+w[1]**2*ay**2)/
  //   (w[0]**2+w[1]**2)*(1-w[2]**2)/w[2]**2));
  // print(repr(D*G1(wi)*G1(wo)/(4*wi[2]*wo[2]))); print(repr(G1(wo)*D/(4*wo[2])))
  expect_grey(lobe.eval(dir(35, 30), dir(38, 215)), 2.9552005246529407);
  expect_rel(lobe.pdf(dir(35, 30), dir(38, 215)), 2.441353649243159);
  EXPECT_EQ(lobe.eval(dir(95, 30), dir(38, 215))[0], 0.0);
  EXPECT_EQ(lobe.eval(dir(35, 30), dir(95, 215))[0], 0.0);
}

TEST(SpotGgx, TheKernelOverAnArrayOfDirectionsIsTheKernelAtEach) {
  // The renderer's kernel is the lobe times the cosine (the value of GeneralDirections).
  expect_rel(Ggx(std::array{0.3, 0.1}).bind(dir(38, 215)).eval_cos(dir(35, 30)),
             2.9552005246529407 * dir(35, 30).z());
  expect_array_kernel_is_the_kernel(
      Ggx(std::array{0.05, 0.005}).bind(dir(38, 215)), [](Eigen::Ref<Eigen::ArrayXd>) {}, 1e-13);
}

// ---------------------------------------------------------------------------------------------
// The closure: f = rho_d / pi + rho_s * lobe, per RGB channel

TEST(SpotClosure, ComposesRgbDiffuseAndLobe) {
  Material m = default_material(ModelId::ward);
  m.params = {0.3, 0.1};
  m.rho_d = Rgb(0.1, 0.2, 0.3);
  m.rho_s = Rgb(0.9, 0.5, 0.25);
  const Closure closure = make_closure(m);
  // The Ward pair of AlphaXStretchesTheLobeAlongX, lobe value l:
  // l=exp(-(tan(radians(10))/0.3)**2)/(4*pi*0.3*0.1*sqrt(cos(radians(20))));
  // print([repr(rd/pi+rs*l) for rd,rs in ((0.1,0.9),(0.2,0.5),(0.3,0.25))])
  const Rgb f = closure.eval(dir(20, 0), dir(0, 0));
  expect_rel(f[0], 1.7751949174473516);
  expect_rel(f[1], 1.032197493252854);
  expect_rel(f[2], 0.5797607238631851);
}

}  // namespace
}  // namespace brdfnav
