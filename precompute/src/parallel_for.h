// parallel_for(): independent tasks spread over a few threads, for the precompute's phases.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace brdfnav {

// Threads to use for a setting of `threads` (0 or less: one per hardware thread).
inline int worker_threads(int threads) {
  return threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
}

// Runs task(i) for every i in [0, count) on `threads` workers (the calling thread is one), each
// taking the next index. The tasks must be independent, so that what they compute does not
// depend on the scheduling. After the first exception no new task starts; it is rethrown once
// every worker has stopped.
template <typename Task>
void parallel_for(std::size_t count, int threads, Task&& task) {
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::exception_ptr failure;
  const auto worker = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        task(i);
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!failure) failure = std::current_exception();
        next = count;
      }
    }
  };
  {
    std::vector<std::jthread> pool;
    const auto helpers = std::min<std::size_t>(std::size_t(std::max(threads, 1)), count);
    for (std::size_t t = 1; t < helpers; ++t) pool.emplace_back(worker);
    worker();
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace brdfnav
