// The exact thumbnails of `brdfnav serve` (lookdev/include/brdfnav/lookdev/exact_thumbnails.h)
// under a ring's check, on the small fixture database of the fuzzers (tests/fuzz/database): a ring
// the page leaves while its render runs stops that render, and nothing of it is cached.
#include <brdfnav/lookdev/exact_thumbnails.h>
#include <brdfnav/serve/serve_rings.h>

#include <brdfnav/core/atomic_file.h>
#include <brdfnav/lookdev/database_env.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/renderer/render.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <ctime>
#include <filesystem>
#include <functional>

namespace brdfnav::lookdev {
namespace {

const Database& database() {
  static const Database db =
      Database::open(std::filesystem::path(BRDFNAV_SOURCE_DIR) / "tests/fuzz/database");
  return db;
}

Material ward(double alpha_x) {
  Material m;
  m.model = ModelId::ward;
  m.params = {alpha_x, 0.05};
  return m;
}

// CPU seconds of the whole process, every thread's: what a render costs, whatever else the
// machine runs.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

constexpr int kSize = 128;

// The check is called before the render and after each row the calling thread renders; the page
// moves on to ring 2 at the first row of ring 1's render, which then stops: two calls, a small
// part of a full render's CPU time, a 409 for the request (RingLeft). The same material rendered
// after is that of a fresh ExactThumbnails to the bit: nothing half-made was kept.
TEST(ExactThumbnails, ARingLeftWhileItsRenderRunsStopsIt) {
  const ExactThumbnails exact(database(), 8);
  exact.render(ward(0.3), kSize);  // loads the map and makes the renderer, its diffuse image
  serve::LeftRings rings;
  const serve::RingId ring{"page", 1};
  rings.enter(ring);
  int calls = 0;
  const std::function<void()> check = [&] {
    if (++calls == 2) rings.enter({"page", 2});
    rings.check(ring)();
  };
  const double start = cpu_seconds();
  EXPECT_THROW(exact.render(ward(0.1), kSize, check), serve::RingLeft);
  const double stopped = cpu_seconds() - start;
  EXPECT_EQ(calls, 2);

  // The same render in full, by a fresh ExactThumbnails whose renderer is made alike.
  const ExactThumbnails fresh(database(), 8);
  fresh.render(ward(0.3), kSize);
  int full_calls = 0;
  const double full_start = cpu_seconds();
  const auto full = fresh.render(ward(0.1), kSize, [&] { ++full_calls; });
  const double whole = cpu_seconds() - full_start;
  EXPECT_GT(full_calls, 2);
  EXPECT_LT(stopped, whole / 4) << "stopped after " << stopped << " s of CPU, a render takes "
                                << whole << " s";
  EXPECT_EQ(exact.render(ward(0.1), kSize)->rgba, full->rgba);
}

// A check that throws before the render starts leaves the renderer free for the next request.
TEST(ExactThumbnails, ARingLeftBeforeItsRenderStartsRendersNothing) {
  const ExactThumbnails exact(database(), 8);
  serve::LeftRings rings;
  rings.enter({"page", 2});
  int calls = 0;
  const std::function<void()> check = [&] {
    ++calls;
    rings.check({"page", 1})();
  };
  EXPECT_THROW(exact.render(ward(0.1), 8, check), serve::RingLeft);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(exact.render(ward(0.1), 8)->rgba,
            ExactThumbnails(database(), 8).render(ward(0.1))->rgba);
}

// A material is its lobe's render with its colours composed onto it: the image is the renderer's
// own (Renderer::render, to the bit), and the same lobe in other colours (a colour tab's offers)
// renders nothing more: the check, called before every render, is not called.
TEST(ExactThumbnails, AMaterialInOtherColoursSharesItsLobesRender) {
  Material first = ward(0.1), other = ward(0.1);
  first.rho_d = Rgb(0.2, 0.3, 0.4), first.rho_s = Rgb(0.5, 0.5, 0.5);
  other.rho_d = Rgb(0.6, 0.1, 0.05), other.rho_s = Rgb(0.9, 1.2, 0.3);
  const ExactThumbnails exact(database(), 8);
  int renders = 0;
  exact.render(first, kSize, [&] { ++renders; });
  EXPECT_GT(renders, 0);
  renders = 0;
  const auto image = exact.render(other, kSize, [&] { ++renders; });
  EXPECT_EQ(renders, 0);

  const EnvMap env = load_database_env(database());
  const Scene scene = Scene::load(database().manifest().scene);
  RenderOptions options;
  options.quality = quality_from_record(database().manifest().render_quality);
  Renderer renderer(env, scene, kSize, options);
  EXPECT_EQ(image->rgba, renderer.render(other).rgba);
  EXPECT_EQ(exact.render(first, kSize)->rgba, renderer.render(first).rgba);
}

// A manifest whose recorded render quality the renderer cannot take is a damaged database: the
// render is refused naming the manifest and the knob.
TEST(ExactThumbnails, ADamagedRenderQualityNamesTheManifest) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("brdfnav_exact_quality_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::copy(database().dir(), dir, std::filesystem::copy_options::recursive);
  const std::filesystem::path manifest = dir / "manifest.yaml";
  std::string text = read_file(manifest);
  const std::size_t at = text.find("render_quality: {");
  ASSERT_NE(at, std::string::npos) << text;
  text.insert(at + std::string("render_quality: {").size(), "shininess: 3, ");
  write_file_atomic(manifest, text);
  const Database damaged = Database::open(dir);
  const ExactThumbnails exact(damaged, 8);
  try {
    exact.render(ward(0.1), kSize);
    ADD_FAILURE() << "rendered at a quality it could not read";
  } catch (const DatabaseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(manifest.string()), std::string::npos) << what;
    EXPECT_NE(what.find("unknown knob 'shininess'"), std::string::npos) << what;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace brdfnav::lookdev
