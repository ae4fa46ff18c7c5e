// The claim behind the lobe tab: a neighbour at embedded distance eps looks eps away. Renders the
// current material and each lobe neighbour with the pre-renderer, at the database's resolution
// and render quality, and compares the exact cube-root RMS distance (image_distance) with eps.
// The deviations depend on the database (grid density, coefficients kept) and on the
// renderer's accuracy; BRDFNAV_TEST_DATABASE=DIR measures another database than the test
// profile's.
#include "navigator_fixture.h"

#include <brdfnav/core/statistics.h>
#include <brdfnav/navigator.h>
#include <brdfnav/precompute/render.h>
#include <gtest/gtest.h>

#include <cstdio>

namespace brdfnav {
namespace {

TEST(NavigatorRendered, LobeNeighboursLookEpsAway) {
  const Navigator nav = Navigator::open(test::NavigationDatabase::get().dir());
  const Manifest& manifest = nav.database().manifest();
  if (manifest.profile == "smoke") GTEST_SKIP() << "the smoke profile makes no accuracy claim";
  const EnvMap env = EnvMap::load(manifest.env_path, {}, [](const std::string&) {});
  ASSERT_EQ(env.pixel_hash(), manifest.env_hash);
  ASSERT_EQ(manifest.scene, "sphere");
  RenderOptions options;
  options.quality = make_profile(manifest.profile).quality;
  const Scene scene = Scene::sphere();  // the renderer keeps a reference
  Renderer renderer(env, scene, manifest.resolution, options);

  std::mt19937_64 rng(2006);
  std::vector<double> errors;
  std::printf("%-14s %-10s %9s %9s %9s\n", "model", "label", "eps", "rendered", "error");
  for (const ProfileGrid& g : manifest.grids) {
    std::vector<double> model_errors;
    // 10 materials per model: with 3, the 90th percentile moved by several points from one seed
    // to the next.
    for (int trial = 0; trial < 10; ++trial) {
      const Material m = test::random_material(g.model, g.grid, rng, 0.3, 0.2, 1.0);
      const Image current = renderer.render(m);
      for (double eps : {0.01, 0.03}) {
        for (const Neighbor& n : nav.neighbors(m, eps, Tab::lobe)) {
          if (n.at_boundary) continue;  // nearer than eps by design
          const double rendered = image_distance(current, renderer.render(n.material));
          model_errors.push_back(std::abs(rendered / eps - 1));
          std::printf("%-14s %-10s %9.4f %9.4f %+8.1f%%\n",
                      std::string(model_info(g.model).name).c_str(), n.label.c_str(), eps, rendered,
                      100 * (rendered / eps - 1));
        }
      }
    }
    if (model_errors.empty()) continue;
    std::printf("%s: %zu neighbours, median |error| %.1f%%, p90 %.1f%%\n",
                std::string(model_info(g.model).name).c_str(), model_errors.size(),
                100 * quantile(model_errors, 0.5), 100 * quantile(model_errors, 0.9));
    errors.insert(errors.end(), model_errors.begin(), model_errors.end());
  }
  ASSERT_FALSE(errors.empty());
  const double median = quantile(errors, 0.5), p90 = quantile(errors, 0.9);
  std::printf("all: %zu neighbours, median |error| %.1f%%, p90 %.1f%% (database %s, %d px)\n",
              errors.size(), 100 * median, 100 * p90, manifest.profile.c_str(),
              manifest.resolution);
  // Issue #5: a median of 5% and a 90th percentile of 10% (measured 2.0% / 6.9% on the test
  // profile, docs/NAVIGATION.md).
  EXPECT_LE(median, 0.05);
  EXPECT_LE(p90, 0.10);
}

}  // namespace
}  // namespace brdfnav
