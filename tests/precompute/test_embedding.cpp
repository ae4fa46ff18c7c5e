#include <brdfnav/precompute/embedding.h>
#include <brdfnav/renderer/render.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace brdfnav {
namespace {

constexpr const char* kInterior = "/usr/share/blender/datafiles/studiolights/world/interior.exr";
constexpr int kRes = 16;

// A small two-model embedding (Ward 4 x 4, Blinn-Phong 6) under interior.exr, shared by the
// tests: rendering it once keeps the suite fast.
struct Fixture {
  EnvMap env = EnvMap::load(kInterior, {}, [](const std::string&) {});
  Scene scene = Scene::sphere();
  Renderer renderer{env, scene, kRes};
  std::vector<ModelImages> models;
  std::vector<double> q = diffuse_fraction_nodes(5);
  Embedding embedding;

  Fixture() {
    add(ModelId::ward, {{0.02, 0.05, 0.12, 0.3}, {0.02, 0.05, 0.12, 0.3}});
    add(ModelId::blinn_phong, {{5, 20, 80, 300, 1200, 5000}});
    PcaOptions o;
    o.components = 400;  // more than the data's rank: the projection is then lossless
    embedding = build_embedding(renderer.diffuse(), models, q, o);
  }
  void add(ModelId id, std::vector<std::vector<double>> axes) {
    ModelImages m{id, ParamGrid(model_info(id).params, std::move(axes)), {}};
    for (std::size_t n = 0; n < m.grid.node_count(); ++n)
      m.specular.push_back(renderer.specular(make_lobe(id, m.grid.node_values(n))));
    models.push_back(std::move(m));
  }
  const ModelEmbedding& of(ModelId id) const {
    return embedding.models[id == ModelId::ward ? 0 : 1];
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

Material material(ModelId id, std::vector<double> params, Rgb rho_d, Rgb rho_s) {
  Material m = default_material(id);
  m.params = std::move(params), m.rho_d = rho_d, m.rho_s = rho_s;
  return m;
}

// On grid nodes and on q nodes nothing is interpolated: with a lossless basis the embedded
// distance equals the metric between the rendered images, for coloured materials across models.
TEST(Embedding, IsExactOnTheGridForColoredMaterials) {
  Fixture& f = fixture();
  // rho_d / (rho_d + rho_s) = q nodes 1/64, 1/8 and 27/64 in the three channels.
  const Material a = material(ModelId::ward, {0.05, 0.12}, Rgb(0.01, 0.05, 0.27) * 0.5,
                              Rgb(0.63, 0.35, 0.37) * 0.5);
  const Material b = material(ModelId::blinn_phong, {300}, Rgb(0.0, 0.3, 0.1),
                              Rgb(0.2, 0.0, 0.3));  // q = 0, 1, 1/4 (the last off its node)
  const Material c = material(ModelId::ward, {0.3, 0.02}, Rgb(0.2, 0.2, 0.2), Rgb::Zero());
  for (const auto& [x, y] : {std::pair{a, c}, std::pair{a, a}}) {
    const double exact = image_distance(f.renderer.render(x), f.renderer.render(y));
    const double embedded = embedding_distance(f.of(x.model).embed(x), f.of(y.model).embed(y));
    EXPECT_NEAR(embedded, exact, 1e-4 * exact + 1e-6);
  }
  // Cross-model with an off-node q: interpolation along q only (a few percent at most).
  const double exact = image_distance(f.renderer.render(a), f.renderer.render(b));
  const double embedded = embedding_distance(f.of(a.model).embed(a), f.of(b.model).embed(b));
  EXPECT_NEAR(embedded, exact, 0.05 * exact);
}

// Scaling every colour by t scales the cube-root image, and so the embedding, by cbrt(t).
TEST(Embedding, ScalesWithTheCubeRootOfTheColors) {
  const ModelEmbedding& ward = fixture().of(ModelId::ward);
  const Material m = material(ModelId::ward, {0.07, 0.2}, Rgb(0.1, 0.2, 0.05), Rgb(0.3, 0.1, 0.4));
  Material scaled = m;
  scaled.rho_d *= 8, scaled.rho_s *= 8;
  EXPECT_TRUE(ward.embed(scaled).isApprox(2.0f * ward.embed(m), 1e-5f));
}

// Off the grid the embedding interpolates: it stays close to the metric between rendered images
// (this coarse 4 x 4 grid is far sparser than any profile's; the bound is for it).
TEST(Embedding, InterpolatesBetweenNodes) {
  Fixture& f = fixture();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> alpha(std::log(0.02), std::log(0.3)), rho(0.02, 0.4);
  std::vector<double> errors;
  for (int i = 0; i < 8; ++i) {
    const auto m = [&] {
      // Braced lists draw in order; a function's arguments would not (clang and gcc differ).
      const std::vector<double> alphas{std::exp(alpha(rng)), std::exp(alpha(rng))};
      const Rgb rho_d{rho(rng), rho(rng), rho(rng)}, rho_s{rho(rng), rho(rng), rho(rng)};
      return material(ModelId::ward, alphas, rho_d, rho_s);
    };
    const Material a = m(), b = m();
    const double exact = image_distance(f.renderer.render(a), f.renderer.render(b));
    const double embedded = embedding_distance(f.of(a.model).embed(a), f.of(b.model).embed(b));
    errors.push_back(std::abs(embedded - exact) / exact);
  }
  // The upper of the two middle errors of the eight is below 5%: five of them are.
  EXPECT_GE(std::count_if(errors.begin(), errors.end(), [](double e) { return e < 0.05; }), 5);
}

TEST(Embedding, RejectsImagesWithAnotherMask) {
  Fixture& f = fixture();
  Image other = f.renderer.diffuse();
  other.rgba[4 * (kRes / 2 * kRes + kRes / 2) + 3] = 0;  // uncover the centre pixel
  std::vector<ModelImages> models{f.models[1]};
  models[0].specular[0] = other;
  EXPECT_THROW(build_embedding(f.renderer.diffuse(), models, f.q, {}), ImageError);
}

TEST(Embedding, DiffuseFractionNodesAreUniformInCubeRoot) {
  const auto q = diffuse_fraction_nodes(9);
  ASSERT_EQ(q.size(), 9u);
  EXPECT_EQ(q.front(), 0.0);
  EXPECT_EQ(q.back(), 1.0);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(std::cbrt(q[i]), i / 8.0, 1e-12);
}

}  // namespace
}  // namespace brdfnav
