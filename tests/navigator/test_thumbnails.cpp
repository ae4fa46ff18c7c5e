// Thumbnails of any material from a test-profile database: exact at grid nodes, close to the
// exactly rendered image between them, resampled to any size, thread-safe, and through OCIO (the
// navigator's display thumbnails too).
#include "navigator/navigator_fixture.h"

#include <brdfnav/navigator/display_thumbnails.h>
#include <brdfnav/navigator/image_input.h>
#include <brdfnav/navigator/navigator.h>
#include <brdfnav/navigator/thumbnails.h>
#include <brdfnav/ocio/color_pipeline.h>
#include <brdfnav/renderer/render.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <thread>

namespace brdfnav::test {
namespace {

const Database& database() {
  static const Database db = Database::open(NavigationDatabase::get().dir());
  return db;
}

Material ward(double ax, double ay) {
  Material m = default_material(ModelId::ward);
  m.params = {ax, ay};
  m.rho_d = Rgb(0.3, 0.2, 0.1), m.rho_s = Rgb(0.4, 0.5, 0.6);
  return m;
}

TEST(Thumbnails, AtAGridNodeTheyAreThePreRenderedImage) {
  const Thumbnails thumbnails(database(), 0);
  const ParamGrid& grid = database().embedding(ModelId::ward)->grid();
  const std::size_t node = 4;
  const std::vector<double> p = grid.node_values(node);
  const Material m = ward(p[0], p[1]);
  const Image thumb = thumbnails.render(m);
  const Image expected =
      compose(read_image(database().diffuse_path()),
              read_image(database().image_path(ModelId::ward, node)), m.rho_d, m.rho_s);
  ASSERT_EQ(thumb.width, expected.width);
  for (std::size_t i = 0; i < thumb.rgba.size(); ++i)
    ASSERT_NEAR(thumb.rgba[i], expected.rgba[i], 1e-5 * (1 + expected.rgba[i])) << i;
}

// The blend works on the pixels the diffuse image's mask covers: there it is the weighted sum of
// the composed images' cube roots, cubed back; elsewhere it is transparent black, whatever the
// images hold.
TEST(Blend, ComposesCoveredPixelsAndLeavesTheRestBlack) {
  Image diffuse(3, 1), a(3, 1), b(3, 1);
  for (int x = 0; x < 3; ++x)
    for (int c = 0; c < 3; ++c) {
      diffuse.pixel(x, 0)[c] = 0.5f + x, a.pixel(x, 0)[c] = 2.f + c, b.pixel(x, 0)[c] = 8.f;
    }
  diffuse.pixel(0, 0)[3] = diffuse.pixel(2, 0)[3] = 1.f;  // the middle pixel is not covered
  const std::vector<ParamGrid::Corner> corners{{0, 0.25}, {1, 0.75}};
  const std::vector<const Image*> images{&a, &b};
  const Rgb rho_d(0.1, 0.2, 0.3), rho_s(1.0, 0.5, 0.25);
  const Image out = blend_images(diffuse, corners, images, rho_d, rho_s);
  for (int x : {0, 2})
    for (int c = 0; c < 3; ++c) {
      const double d = rho_d[c] * diffuse.pixel(x, 0)[c];
      const double root = 0.25 * std::cbrt(d + rho_s[c] * a.pixel(x, 0)[c]) +
                          0.75 * std::cbrt(d + rho_s[c] * b.pixel(x, 0)[c]);
      EXPECT_NEAR(out.pixel(x, 0)[c], root * root * root, 1e-5 * root * root * root) << x << c;
    }
  for (int x = 0; x < 3; ++x) EXPECT_EQ(out.pixel(x, 0)[3], diffuse.pixel(x, 0)[3]);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(out.pixel(1, 0)[c], 0.f);
}

// Between nodes a thumbnail is the image whose cube root the embedding interpolates: its
// distance to a corner's image is the distance the navigator measures (up to the embedding's
// truncation to 24 coefficients), and it lies within the grid cell's span of the exact image.
// The test profile's Ward axis steps by 10x, so nothing closer than the cell's span is asked.
TEST(Thumbnails, BetweenNodesTheyAreWhatTheEmbeddingMeasures) {
  const Thumbnails thumbnails(database(), 0);
  const Navigator navigator(Database::open(NavigationDatabase::get().dir()));
  const ParamGrid& grid = database().embedding(ModelId::ward)->grid();
  const double lo = grid.axis(0)[0], hi = grid.axis(0)[1];
  const double mid = std::sqrt(lo * hi);  // the axis is logarithmic
  const Image thumb = thumbnails.render(ward(mid, hi));
  const Image corner = thumbnails.render(ward(hi, hi));
  const double measured = navigator.distance(ward(mid, hi), ward(hi, hi));
  EXPECT_NEAR(image_distance(thumb, corner), measured, 0.05 * measured);

  const EnvMap env = EnvMap::load(kDefaultEnvPath, {}, [](const std::string&) {});
  const Scene sphere = Scene::sphere();
  Renderer renderer(env, sphere, database().manifest().resolution);
  const Image exact = renderer.render(ward(mid, hi));
  EXPECT_LT(image_distance(thumb, exact), image_distance(renderer.render(ward(lo, hi)), corner));
}

TEST(Thumbnails, AreResampledToTheAskedSizeWithABinaryMask) {
  const Thumbnails thumbnails(database(), 128);
  const Image t = thumbnails.render(ward(0.05, 0.02));
  ASSERT_EQ(t.width, 128);
  ASSERT_EQ(t.height, 128);
  int covered = 0;
  for (int y = 0; y < 128; ++y)
    for (int x = 0; x < 128; ++x) {
      const float a = t.pixel(x, y)[3];
      ASSERT_TRUE(a == 0.f || a == 1.f);
      covered += a == 1.f;
      if (a == 1.f) {
        ASSERT_GE(t.pixel(x, y)[1], 0.f);
      }
    }
  // The unit disk covers pi/4 of the image.
  EXPECT_NEAR(covered / (128.0 * 128.0), kPi / 4, 0.03);
}

TEST(Thumbnails, RejectsInvalidMaterials) {
  const Thumbnails thumbnails(database(), 32);
  Material bad = ward(0.05, 0.05);
  bad.rho_d[0] = std::nan("");
  EXPECT_THROW(thumbnails.render(bad), MaterialError);
  // The database's images are lin_rec709: rho in another space would be shown as if it were.
  Material acescg = ward(0.05, 0.05);
  acescg.colorspace = "acescg";
  EXPECT_THROW(thumbnails.render(acescg), MaterialError);
}

std::vector<Material> ward_row() {
  std::vector<Material> materials;
  for (int i = 0; i < 16; ++i) materials.push_back(ward(0.006 + 0.03 * i, 0.2 - 0.01 * i));
  return materials;
}

// Bytes of `count` cached images at `size` x `size`.
std::size_t images_bytes(int count, int size) {
  return std::size_t(count) * size * size * 4 * sizeof(float);
}

TEST(Thumbnails, ACacheHeldToItsBudgetGivesTheSameImages) {
  const Thumbnails unbounded(database(), 32, SIZE_MAX), small(database(), 32, images_bytes(5, 32));
  for (const Material& m : ward_row()) {
    EXPECT_EQ(small.render(m).rgba, unbounded.render(m).rgba);
    EXPECT_LE(small.cached_bytes(), images_bytes(5, 32));
  }
  // The row blends more than 5 distinct nodes: the small cache dropped some, the other none.
  EXPECT_EQ(small.cached_bytes(), images_bytes(5, 32));
  EXPECT_GT(unbounded.cached_bytes(), images_bytes(5, 32));
}

TEST(Thumbnails, ConcurrentRendersMatchSerialOnes) {
  // `small` drops images while other threads use them.
  const Thumbnails serial(database(), 64), shared(database(), 64),
      small(database(), 64, images_bytes(3, 64));
  const std::vector<Material> materials = ward_row();
  std::vector<Image> expected;
  for (const Material& m : materials) expected.push_back(serial.render(m));
  std::vector<std::vector<Image>> got(8);
  std::vector<std::jthread> pool;
  for (int t = 0; t < 8; ++t)
    pool.emplace_back([&, t] {
      for (const Material& m : materials) got[t].push_back((t % 2 ? small : shared).render(m));
    });
  pool.clear();
  for (const auto& run : got)
    for (std::size_t i = 0; i < materials.size(); ++i) EXPECT_EQ(run[i].rgba, expected[i].rgba);
  EXPECT_LE(small.cached_bytes(), images_bytes(3, 64));
}

double srgb_encode(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}

// Through OCIO's Standard sRGB view a thumbnail is the sRGB encoding of its linear pixels over the
// pipeline's grey background, to one code value (the built-in config's matrices are an identity
// only to ~1e-6, which rounding can move across a code boundary; docs/COLOR.md).
TEST(Thumbnails, ThroughOcioMatchTheSrgbEncoding) {
  const Thumbnails thumbnails(database(), 48);
  const Image t = thumbnails.render(ward(0.02, 0.02));
  ocio::PipelineOptions options;
  options.config_path = "";
  const ocio::ColorPipeline pipeline(options);
  const std::vector<std::uint8_t> bytes =
      pipeline.apply(t.rgba.data(), t.width, t.height, "sRGB", "Standard");
  ASSERT_EQ(bytes.size(), t.rgba.size());
  for (std::size_t p = 0; p < t.rgba.size(); p += 4) {
    const double a = t.rgba[p + 3];
    for (int c = 0; c < 3; ++c) {
      const double linear = t.rgba[p + c] + (1 - a) * options.background[c];
      ASSERT_NEAR(bytes[p + c], 255 * srgb_encode(linear), 1.0) << p << " " << c;
    }
  }
}

// The navigator's display thumbnails are display_encode() of its linear thumbnails, byte for
// byte, on every display and view of the config: what the server shows. Inside the sphere (alpha
// 1 before and after the edge is antialiased) they are the pipeline's encoding of the linear
// thumbnail.
TEST(DisplayThumbnails, AreTheDisplayEncodingOfTheLinearThumbnail) {
  const Thumbnails thumbnails(database(), 48);
  const DisplayThumbnails display(thumbnails);
  EXPECT_EQ(display.resolution(), 48);
  ASSERT_TRUE(shows_sphere(database()));
  EXPECT_EQ(&display.linear(), &thumbnails);
  const ocio::ColorPipeline reference;
  const Material m = ward(0.02, 0.05);
  const Image linear = thumbnails.render(m);
  int pairs = 0;
  for (const std::string& d : reference.displays())
    for (const std::string& v : reference.views(d)) {
      SCOPED_TRACE(d + " / " + v);
      const ocio::Thumbnail t = display.render(m, d, v);
      EXPECT_EQ(t.width, 48);
      EXPECT_EQ(t.height, 48);
      EXPECT_EQ(t.rgba, display_encode(linear, true, reference, d, v).rgba);
      const std::vector<std::uint8_t> piped =
          reference.apply(linear.rgba.data(), linear.width, linear.height, d, v);
      const std::size_t centre = (24 * 48 + 24) * 4;
      for (std::size_t i = centre; i < centre + 4; ++i) EXPECT_EQ(t.rgba[i], piped[i]) << i;
      ++pairs;
    }
  EXPECT_GE(pairs, 1);
  // Each (display, view) processor is built once and reused.
  const std::string d = display.pipeline().default_display();
  const std::string v = display.pipeline().default_view(d);
  EXPECT_EQ(display.pipeline().processor(d, v), display.pipeline().processor(d, v));
}

// An unknown display or view is named, with the valid ones, before anything is rendered.
TEST(DisplayThumbnails, NameAnUnknownDisplayOrViewBeforeRendering) {
  const Thumbnails thumbnails(database(), 16, SIZE_MAX);
  const DisplayThumbnails display(thumbnails);
  const std::string d = display.pipeline().default_display();
  const std::string v = display.pipeline().default_view(d);
  const auto message = [&](const std::string& display_name, const std::string& view_name) {
    try {
      display.render(ward(0.05, 0.05), display_name, view_name);
    } catch (const ocio::ColorError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string no_display = message("Nonesuch", v), no_view = message(d, "Nonesuch");
  EXPECT_NE(no_display.find("display 'Nonesuch'"), std::string::npos) << no_display;
  EXPECT_NE(no_display.find("'" + d + "'"), std::string::npos) << no_display;
  EXPECT_NE(no_view.find("view 'Nonesuch'"), std::string::npos) << no_view;
  EXPECT_NE(no_view.find("'" + v + "'"), std::string::npos) << no_view;
  EXPECT_EQ(thumbnails.cached_bytes(), 0u);
}

}  // namespace
}  // namespace brdfnav::test
