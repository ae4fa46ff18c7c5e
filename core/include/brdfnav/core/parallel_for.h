// parallel_for(): independent tasks spread over a few threads, for the precompute's phases and the
// thumbnails' reads.
#pragma once

#include <algorithm>
#include <atomic>
#include <concepts>
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

// Called on the calling thread with the number of tasks finished so far.
struct NoProgress {
  void operator()(std::size_t) const {}
};

// Runs task(i), or task(i, worker), for every i in [0, count) on `threads` workers, each taking
// the next index; `worker` in [0, threads) names the thread that runs the task (the calling
// thread is 0), for scratch memory of its own. The tasks must be independent, so that what they
// compute does not depend on the scheduling. The calling thread calls progress(finished) after
// each of its tasks and, unless a task failed, progress(count) once all are done: the last report
// always says "all", however the tasks fell to the threads. After the first exception, a task's or
// progress's (a caller that stops the work: a render nobody waits for), no new task starts; it is
// rethrown once every worker has stopped.
template <typename Task, typename Progress = NoProgress>
void parallel_for(std::size_t count, int threads, Task&& task, Progress progress = {}) {
  std::atomic<std::size_t> next{0}, finished{0};
  std::size_t reported = 0;  // the calling thread's last report
  std::mutex mutex;
  std::exception_ptr failure;
  const auto worker = [&](int id) {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        if constexpr (std::invocable<Task&, std::size_t, int>)
          task(i, id);
        else
          task(i);
        const std::size_t now = ++finished;
        if (id == 0) progress(reported = now);
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
    for (std::size_t t = 1; t < helpers; ++t) pool.emplace_back(worker, int(t));
    worker(0);
  }
  if (failure) std::rethrow_exception(failure);
  if (reported != count) progress(count);
}

}  // namespace brdfnav
