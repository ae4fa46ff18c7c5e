// Ward's grid rendered in one pass (Renderer::ward_grid, renderer/src/ward_grid.h): the
// accuracy of its images, their order, determinism, their dependence on the grid through its
// alpha ranges alone, self-shadowing on a mesh, and bad grids.
#include "render_fixtures.h"

#include <limits>
#include <optional>

namespace brdfnav {
namespace {

using namespace test;

// The pre-renderer's accuracy target at a small size, for the three settings and the lobes that
// bend (the sliver 0.5 x 0.005 included).
TEST(WardGrid, ErrorIsATenthOfATenPercentStep) {
  const Scene sphere = Scene::sphere();
  Renderer renderer(interior(), sphere, 16);
  Renderer reference = reference_renderer(interior(), sphere, 16);
  std::vector<AccuracySetting> settings = bending_ward_settings();
  for (const AccuracySetting& s : accuracy_settings())
    if (s.model == ModelId::ward) settings.push_back(s);
  for (const AccuracySetting& s : settings) {
    const Image image = grid_image(renderer, s);
    expect_a_tenth_of_a_step(measure_accuracy(std::span(&image, 1), reference, s).front(), s.name);
  }
}

// images[i * alpha_y.size() + j] is the lobe (alpha_x[i], alpha_y[j]): nearer specular()'s image
// of that lobe than of any other of the grid.
TEST(WardGrid, ImagesAreInAlphaXMajorOrder) {
  const Scene sphere = Scene::sphere();
  Renderer renderer(interior(), sphere, 16);
  const std::vector<double> ax{0.02, 0.3}, ay{0.01, 0.08, 0.4};
  const std::vector<Image> images = renderer.ward_grid(ax, ay);
  ASSERT_EQ(images.size(), ax.size() * ay.size());
  std::vector<Image> alone;
  for (double x : ax)
    for (double y : ay)
      alone.push_back(renderer.specular(make_lobe(ModelId::ward, std::vector<double>{x, y})));
  for (std::size_t k = 0; k < images.size(); ++k) {
    const double own = image_distance(images[k], alone[k]);
    for (std::size_t other = 0; other < alone.size(); ++other) {
      if (other == k) continue;
      EXPECT_LT(own, image_distance(images[k], alone[other])) << k << " " << other;
    }
  }
}

TEST(WardGrid, DeterministicWhateverTheThreadCount) {
  const Scene sphere = Scene::sphere();
  const std::vector<double> ax{0.005, 0.05, 0.5}, ay{0.01, 0.2};
  std::optional<std::vector<Image>> first;
  for (int threads : {1, 2, 5}) {
    RenderOptions o;
    o.threads = threads;
    Renderer renderer(interior(), sphere, 12, o);
    std::vector<Image> images = renderer.ward_grid(ax, ay);
    if (!first) {
      first = std::move(images);
      continue;
    }
    for (std::size_t k = 0; k < images.size(); ++k)
      EXPECT_EQ(images[k].rgba, (*first)[k].rgba) << threads << " threads, image " << k;
  }
}

// The nodes depend on the smallest and largest alpha of each list alone: a lobe renders the same
// in any grid of those ranges, up to the float rounding of terms below 1e-10 of a pixel (which
// four-wide sums may add or leave out).
TEST(WardGrid, DependsOnTheGridThroughItsAlphaRangesAlone) {
  const Scene sphere = Scene::sphere();
  Renderer renderer(interior(), sphere, 12);
  const std::vector<double> y{0.01, 0.05, 0.3};
  const Image coarse = renderer.ward_grid(std::vector<double>{0.01, 0.05, 0.3}, y)[4];
  const Image fine = renderer.ward_grid(std::vector<double>{0.01, 0.02, 0.05, 0.1, 0.3}, y)[7];
  ASSERT_EQ(coarse.rgba.size(), fine.rgba.size());
  for (std::size_t k = 0; k < coarse.rgba.size(); ++k)
    EXPECT_NEAR(coarse.rgba[k], fine.rgba[k], 1e-6 * std::abs(coarse.rgba[k])) << k;
  const Image wider = renderer.ward_grid(std::vector<double>{0.005, 0.05, 0.3}, y)[4];
  EXPECT_NE(coarse.rgba, wider.rgba);
}

// On a mesh the environment is seen past the mesh alone: at the bottom of a bowl a broad lobe is
// darker than on the sphere, as specular() renders it there.
TEST(WardGrid, ConcaveMeshShadowsItself) {
  const EnvMap env = constant_env(1.f);
  const std::filesystem::path obj = write_bowl();
  const Scene bowl = Scene::load_obj(obj);
  const Scene sphere = Scene::sphere();
  const int res = 33;  // odd: a pixel centre at the middle of the image
  Renderer on_bowl(env, bowl, res), on_sphere(env, sphere, res);
  const std::vector<double> alphas{0.5};
  const float bottom = on_bowl.ward_grid(alphas, alphas)[0].pixel(res / 2, res / 2)[1];
  const float centre = on_sphere.ward_grid(alphas, alphas)[0].pixel(res / 2, res / 2)[1];
  const float alone = on_bowl.specular(make_lobe(ModelId::ward, std::vector<double>{0.5, 0.5}))
                          .pixel(res / 2, res / 2)[1];
  EXPECT_LT(bottom, 0.9 * centre);
  // 2%: the two quadratures' nodes differ, and the horizon the rim makes is sharp.
  EXPECT_NEAR(bottom, alone, 0.02 * alone);
  std::filesystem::remove(obj);
}

// Under a constant environment each lobe's image is its directional albedo, whatever the
// quadrature: the grid's agree with specular()'s, on a map whose pyramid has nodes of 0.2 rad and
// on one whose texels are 0.2 rad (the walk then starts at the texels; there lobes much narrower
// than a texel are beyond max_split for both).
TEST(WardGrid, ConstantEnvironmentGivesTheAlbedoOfSpecular) {
  const Scene sphere = Scene::sphere();
  struct Case {
    int width;
    std::vector<double> alphas;
  };
  for (const Case& c : {Case{64, {0.01, 0.1, 0.5}}, Case{32, {0.1, 0.5}}}) {
    const int w = c.width, h = c.width / 2;
    const EnvMap env(w, h, std::vector<float>(std::size_t(3 * w * h), 1.f), "constant");
    Renderer renderer(env, sphere, 12);
    const std::vector<Image> images = renderer.ward_grid(c.alphas, c.alphas);
    for (std::size_t i = 0; i < c.alphas.size(); ++i)
      for (std::size_t j = 0; j < c.alphas.size(); ++j) {
        const Image alone = renderer.specular(
            make_lobe(ModelId::ward, std::vector<double>{c.alphas[i], c.alphas[j]}));
        // 1%: both integrate the same albedo, with nodes of their own near the horizon.
        EXPECT_NEAR(mean(images[i * c.alphas.size() + j], 1), mean(alone, 1), 0.01 * mean(alone, 1))
            << w << " x " << h << ", " << c.alphas[i] << " x " << c.alphas[j];
      }
  }
}

TEST(WardGrid, RejectsBadAlphas) {
  const Scene sphere = Scene::sphere();
  Renderer renderer(interior(), sphere, 4);
  const std::vector<double> good{0.01, 0.1};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const std::vector<double>& bad : std::vector<std::vector<double>>{
           {}, {0.0, 0.1}, {-0.1, 0.1}, {0.01, nan}, {0.01, inf}, {0.1, 0.01}}) {
    EXPECT_THROW(renderer.ward_grid(bad, good), RenderError);
    EXPECT_THROW(renderer.ward_grid(good, bad), RenderError);
  }
}

}  // namespace
}  // namespace brdfnav
