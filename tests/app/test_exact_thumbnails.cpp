// The exact thumbnails of `brdfnav serve` (app/exact_thumbnails.h) under a ring's check, on the
// small fixture database of the fuzzers (tests/fuzz/database): a ring the page leaves while its
// render runs stops that render, and nothing of it is cached.
#include "exact_thumbnails.h"
#include "serve_rings.h"

#include <brdfnav/navigator/database.h>
#include <gtest/gtest.h>

#include <ctime>
#include <filesystem>
#include <functional>

namespace brdfnav::cli {
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
  LeftRings rings;
  const RingId ring{"page", 1};
  rings.enter(ring);
  int calls = 0;
  const std::function<void()> check = [&] {
    if (++calls == 2) rings.enter({"page", 2});
    rings.check(ring)();
  };
  const double start = cpu_seconds();
  EXPECT_THROW(exact.render(ward(0.1), kSize, check), RingLeft);
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
  LeftRings rings;
  rings.enter({"page", 2});
  int calls = 0;
  const std::function<void()> check = [&] {
    ++calls;
    rings.check({"page", 1})();
  };
  EXPECT_THROW(exact.render(ward(0.1), 8, check), RingLeft);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(exact.render(ward(0.1), 8)->rgba,
            ExactThumbnails(database(), 8).render(ward(0.1))->rgba);
}

}  // namespace
}  // namespace brdfnav::cli
