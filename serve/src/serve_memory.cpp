#include <brdfnav/serve/serve_memory.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace brdfnav::serve {

IdleRelease::IdleRelease(std::chrono::milliseconds quiet, std::function<void()> release)
    : quiet_(quiet), release_(std::move(release)), thread_([this] { run(); }) {}

IdleRelease::~IdleRelease() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

IdleRelease::Busy::Busy(IdleRelease& idle) : idle_(idle) {
  const std::lock_guard lock(idle_.mutex_);
  ++idle_.in_flight_;
  idle_.used_ = true;
}

IdleRelease::Busy::~Busy() {
  {
    const std::lock_guard lock(idle_.mutex_);
    --idle_.in_flight_;
    idle_.last_end_ = std::chrono::steady_clock::now();
  }
  idle_.changed_.notify_all();
}

void IdleRelease::run() {
  std::unique_lock lock(mutex_);
  while (!stop_) {
    if (in_flight_ > 0 || !used_) {
      changed_.wait(lock);
      continue;
    }
    // Quiet since the last request ended: wait out the spell, unless something changes.
    const auto due = last_end_ + quiet_;
    if (std::chrono::steady_clock::now() < due) {
      changed_.wait_until(lock, due);
      continue;  // look again: a request may have come, or the wait ended early
    }
    used_ = false;
    lock.unlock();
    release_();
    lock.lock();
  }
}

void trim_heap() {
#if defined(__GLIBC__)
  ::malloc_trim(0);
#endif
}

bool limit_heap_arenas(int arenas) {
#if defined(__GLIBC__)
  return arenas > 0 && ::mallopt(M_ARENA_MAX, arenas) == 1;
#else
  (void)arenas;
  return false;
#endif
}

}  // namespace brdfnav::serve
