// GGX with MaterialX's terms (renderer/src/materialx_ggx.h), which the MaterialX export measures
// the ggx closure against: spot values written in MaterialX's own GLSL form, and its images.
// The python one-liners use P of tests/core/test_spot_values.cpp, E the albedo fit below.
#include "materialx_ggx.h"
#include "render_fixtures.h"

#include <gtest/gtest.h>

#include <array>

namespace brdfnav {
namespace {

Vec3 dir(double theta_deg, double phi_deg) {
  const double t = theta_deg * kPi / 180, p = phi_deg * kPi / 180;
  return spherical_direction(std::sin(t), std::cos(t), p);
}

// E(x, y): r = c0 + c1 x + c2 y + c3 x y + c4 x^2 + c5 y^2 + c6 x^2 y + c7 x y^2 + c8 x^2 y^2
// per component with MaterialX's coefficients, E = clamp(r0 / r2) + clamp(r1 / r3).
TEST(MaterialxGgx, AlbedoFit) {
  EXPECT_NEAR(materialx_ggx_albedo(std::cos(38 * kPi / 180), std::sqrt(0.03)), 0.9453689495170674,
              1e-12);
  EXPECT_NEAR(materialx_ggx_albedo(1.0, 0.01), 1.0023980602379619, 1e-12);  // the fit's > 1
  EXPECT_NEAR(materialx_ggx_albedo(0.5, 1.0), 0.45874547819051315, 1e-12);
}

TEST(MaterialxGgx, SpotValuesInMaterialxsForm) {
  // ax,ay=0.3,0.1; wi=d(35,30); wo=d(38,215); H=normalised wi+wo; He=(H[0]/ax,H[1]/ay);
  // den=He[0]**2+He[1]**2+H[2]**2; D=1/(pi*ax*ay*den**2); a2=ax*ay;
  // lam=lambda c: sqrt(a2+(1-a2)*c*c); G2=2/(lam(wi[2])/wi[2]+lam(wo[2])/wo[2]);
  // print(repr(D*G2/(4*wo[2]))); e=E(wo[2],sqrt(a2)); print(repr(D*G2/(4*wo[2])*(1-e)/e))
  const Vec3 wi = dir(35, 30), wo = dir(38, 215);
  const MaterialxGgx plain{0.3, 0.1, false}, compensation{0.3, 0.1, true};
  EXPECT_NEAR(plain.bind(wo).eval_cos(wi), 2.4447536525550126, 1e-9 * 2.44);
  EXPECT_NEAR(compensation.bind(wo).eval_cos(wi), 0.14127760413465487, 1e-9 * 0.14);
  EXPECT_EQ(plain.bind(dir(95, 0)).eval_cos(wi), 0.0);
  EXPECT_EQ(plain.bind(wo).eval_cos(dir(95, 0)), 0.0);
}

// Its images: close to the ggx closure's for a smooth isotropic lobe, where only G differs and
// both are near 1; the compensation, of a smooth lobe, small.
TEST(MaterialxGgx, ItsImagesAreNearTheClosuresForASmoothLobe) {
  const Scene sphere = Scene::sphere();
  Renderer renderer(test::interior(), sphere, 16);
  const Ggx lobe(std::array{0.05, 0.05});
  const Image ggx = renderer.specular(lobe);
  const Image plain = renderer.materialx_ggx(lobe, false);
  EXPECT_GT(image_distance(ggx, plain), 0.0);
  EXPECT_LT(image_distance(ggx, plain), 0.02);
  const Image compensation = renderer.materialx_ggx(lobe, true);
  double mean = 0, ggx_mean = 0;
  for (std::size_t i = 0; i < ggx.rgba.size(); i += 4)
    mean += compensation.rgba[i], ggx_mean += ggx.rgba[i];
  EXPECT_LT(std::abs(mean), 0.05 * ggx_mean);
}

}  // namespace
}  // namespace brdfnav
