#include <brdfnav/core/material.h>
#include <brdfnav/precompute/fit.h>
#include <gtest/gtest.h>

namespace brdfnav {
namespace {

Lobe lobe_of(const char* spec) {
  const Material m = parse_material_spec(spec);
  return make_lobe(m.model, m.params);
}

// Fitting a model to itself must recover the parameters (off-grid values, so LM has to move).
TEST(Fit, RecoversKnownParametersOfTheSameModel) {
  struct Case {
    const char* spec;
    ModelId model;
  };
  for (const Case& c : {Case{"ward:alpha_x=0.043,alpha_y=0.17", ModelId::ward},
                        Case{"blinn_phong:n=730", ModelId::blinn_phong},
                        Case{"cook_torrance:f0=0.23,m=0.21", ModelId::cook_torrance},
                        Case{"lafortune:cz=0.55,n=240", ModelId::lafortune}}) {
    SCOPED_TRACE(c.spec);
    const Material truth = parse_material_spec(c.spec);
    const LobeFit fit = fit_lobe(lobe_of(c.spec), c.model);
    ASSERT_EQ(fit.params.size(), truth.params.size());
    for (std::size_t i = 0; i < truth.params.size(); ++i)
      EXPECT_NEAR(fit.params[i], truth.params[i], 1e-3 * truth.params[i]);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(fit.scale[ch], 1.0, 1e-3);
    EXPECT_LT(fit.relative_error, 1e-3);
  }
}

// The RGB scale is solved in closed form: a target scaled per channel comes back as that scale.
TEST(Fit, ScaleIsTheLinearFactor) {
  const Lobe target = lobe_of("ward:alpha_x=0.08,alpha_y=0.08");
  const LobeFit fit = fit_lobe(target, ModelId::ward);
  EXPECT_NEAR(fit.scale[0], 1.0, 1e-3);
  // Blinn-Phong with n = 2/alpha^2 - 2 is close to an isotropic Ward lobe: a good, not exact fit.
  const LobeFit bp = fit_lobe(target, ModelId::blinn_phong);
  EXPECT_GT(bp.params[0], 0.5 * (2 / (0.08 * 0.08) - 2));
  EXPECT_LT(bp.params[0], 2.0 * (2 / (0.08 * 0.08) - 2));
  EXPECT_LT(bp.relative_error, 0.5);
}

// A sharper target is fitted by a sharper lobe: the fit is monotone along the roughness axis.
TEST(Fit, FittedSharpnessFollowsTheTarget) {
  double previous = 0;
  for (const char* spec : {"ward:alpha_x=0.3,alpha_y=0.3", "ward:alpha_x=0.1,alpha_y=0.1",
                           "ward:alpha_x=0.03,alpha_y=0.03"}) {
    const double n = fit_lobe(lobe_of(spec), ModelId::blinn_phong).params[0];
    EXPECT_GT(n, previous) << spec;
    previous = n;
  }
}

TEST(Fit, QuadratureIntegratesTheCosineProduct) {
  // sum_k w_k approximates integral cos_i cos_o dwi dwo = pi^2 (the weights absorb the cosines).
  const FitQuadrature q = make_fit_quadrature(lobe_of("ward:alpha_x=0.2,alpha_y=0.2"), 16, 512);
  double total = 0;
  for (double w : q.weight) total += w;
  // Two-strategy quadrature with 16 x 512 points: a few percent of integration error.
  EXPECT_NEAR(total, kPi * kPi, 0.03 * kPi * kPi);
}

}  // namespace
}  // namespace brdfnav
