// parallel_for() (brdfnav/core/parallel_for.h), which the renderer, the PCA and the
// conversion fits run on: every task once, on a worker id below the thread count, progress on the
// calling thread only and ending at the count, and the first exception (a task's or progress's)
// rethrown after the workers stop.
#include <brdfnav/core/parallel_for.h>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace brdfnav {
namespace {

TEST(ParallelFor, RunsEveryTaskOnceWhateverTheThreadCount) {
  for (const int threads : {1, 2, 3, 8}) {
    constexpr std::size_t kCount = 1000;
    std::vector<std::atomic<int>> runs(kCount);
    std::atomic<int> bad_worker{0};
    parallel_for(kCount, threads, [&](std::size_t i, int worker) {
      ++runs[i];
      if (worker < 0 || worker >= threads) ++bad_worker;
    });
    for (std::size_t i = 0; i < kCount; ++i) ASSERT_EQ(runs[i], 1) << i << ", " << threads;
    EXPECT_EQ(bad_worker, 0) << threads << " threads";
  }
}

TEST(ParallelFor, ReportsProgressOnTheCallingThreadOnly) {
  const auto caller = std::this_thread::get_id();
  std::vector<std::size_t> reports;
  bool elsewhere = false;
  parallel_for(
      200, 3, [](std::size_t) {},
      [&](std::size_t finished) {
        elsewhere |= std::this_thread::get_id() != caller;
        reports.push_back(finished);
      });
  EXPECT_FALSE(elsewhere);
  ASSERT_FALSE(reports.empty());
  for (std::size_t k = 1; k < reports.size(); ++k) EXPECT_GT(reports[k], reports[k - 1]);
  EXPECT_EQ(reports.back(), 200u);  // also when the helpers ran every task
}

TEST(ParallelFor, StopsAtTheFirstExceptionAndRethrowsIt) {
  std::atomic<int> started{0};
  // Every other task takes a millisecond: with instant tasks, the other threads could run all
  // 1000 before the failing one is scheduled again to report (seen on a loaded 2-core machine).
  const auto task = [&](std::size_t i) {
    ++started;
    if (i == 10) throw std::runtime_error("task 10 failed");
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  };
  EXPECT_THROW(parallel_for(1000, 1, task), std::runtime_error);
  EXPECT_EQ(started, 11);  // one thread: tasks 0 to 10, nothing after the failure
  started = 0;
  try {
    parallel_for(1000, 4, task);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "task 10 failed");
  }
  EXPECT_LT(started, 1000);
}

// A progress that throws (a render whose ring was left) stops the work as a failing task does.
// The helpers hold their first task until the calling thread's first report has thrown, so the
// test does not depend on the scheduling: without the stop they would then run all 1000 tasks.
TEST(ParallelFor, AnExceptionFromProgressStopsNewTasks) {
  constexpr int kThreads = 3;
  std::atomic<int> started{0};
  std::atomic<bool> thrown{false};
  // The helpers' tasks wait for the throw, then take a millisecond each: between the throw and
  // the catch that stops new tasks (the exception's unwinding, slow under TSan: about a hundred
  // instant tasks ran in that window) a helper may still start a few.
  const auto task = [&](std::size_t, int worker) {
    ++started;
    if (worker == 0) return;
    while (!thrown) std::this_thread::yield();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  };
  const auto progress = [&](std::size_t) {
    thrown = true;
    throw std::runtime_error("left");
  };
  try {
    parallel_for(1000, kThreads, task, progress);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "left");
  }
  // Far fewer than the 1000 that ran when an exception from progress left the helpers running
  // every remaining task.
  EXPECT_LT(started, 100);
}

}  // namespace
}  // namespace brdfnav
