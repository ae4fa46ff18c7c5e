// A server's memory: IdleRelease's release runs once per quiet spell after requests, never while
// one is in flight, and not before the first; the heap's arenas take a limit.
#include <brdfnav/serve/serve_memory.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <optional>
#include <thread>

namespace brdfnav::serve {
namespace {

using namespace std::chrono_literals;

constexpr auto kQuiet = 50ms;

// Polls until `count` reaches `want` or several seconds pass (a loaded machine delays the
// release thread; only the count is asserted, never a duration).
bool reaches(const std::atomic<int>& count, int want) {
  for (int i = 0; i < 500 && count.load() < want; ++i) std::this_thread::sleep_for(10ms);
  return count.load() >= want;
}

TEST(IdleRelease, ReleasesOnceAfterAQuietSpellAndAgainOnlyAfterAnotherRequest) {
  std::atomic<int> releases{0};
  IdleRelease idle(kQuiet, [&] { ++releases; });
  { const IdleRelease::Busy request(idle); }
  ASSERT_TRUE(reaches(releases, 1));
  std::this_thread::sleep_for(10 * kQuiet);
  EXPECT_EQ(releases.load(), 1) << "released again with no request between";
  { const IdleRelease::Busy request(idle); }
  ASSERT_TRUE(reaches(releases, 2));
}

TEST(IdleRelease, NeverReleasesBeforeTheFirstRequest) {
  std::atomic<int> releases{0};
  {
    IdleRelease idle(kQuiet, [&] { ++releases; });
    std::this_thread::sleep_for(10 * kQuiet);
  }
  EXPECT_EQ(releases.load(), 0);
}

TEST(IdleRelease, WaitsWhileARequestIsInFlight) {
  std::atomic<int> releases{0};
  IdleRelease idle(kQuiet, [&] { ++releases; });
  std::optional<IdleRelease::Busy> slow;
  slow.emplace(idle);
  { const IdleRelease::Busy quick(idle); }  // ends while `slow` is still in flight
  std::this_thread::sleep_for(10 * kQuiet);
  EXPECT_EQ(releases.load(), 0) << "released with a request in flight";
  slow.reset();
  EXPECT_TRUE(reaches(releases, 1));
}

TEST(IdleRelease, AStopWhileIdleReturnsAtOnce) {
  std::atomic<int> releases{0};
  const auto started = std::chrono::steady_clock::now();
  {
    IdleRelease idle(std::chrono::hours(1), [&] { ++releases; });
    const IdleRelease::Busy request(idle);
  }
  EXPECT_EQ(releases.load(), 0);
  // Not a speed target: an hour's wait not cut short would hang the test until CTest's timeout.
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::minutes(1));
}

// A sanitizer's allocator replaces glibc's and refuses mallopt(): limit_heap_arenas says so.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define BRDFNAV_SANITIZER_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define BRDFNAV_SANITIZER_ALLOCATOR 1
#endif
#endif

#if defined(__GLIBC__) && !defined(BRDFNAV_SANITIZER_ALLOCATOR)
TEST(HeapArenas, GlibcTakesALimitAndRefusesNone) {
  EXPECT_TRUE(limit_heap_arenas(2));
  EXPECT_FALSE(limit_heap_arenas(0));
}
#else
TEST(HeapArenas, AnotherAllocatorRefusesTheLimit) {
  EXPECT_FALSE(limit_heap_arenas(2));
}
#endif

}  // namespace
}  // namespace brdfnav::serve
