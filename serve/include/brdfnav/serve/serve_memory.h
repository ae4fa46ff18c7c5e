// A server's memory: what it gives back between bursts, and how many heaps its allocator keeps.
// Under a page's clicks the server's caches fill to their budgets, and it holds more than they
// do: the pages of the database's embeddings that any query touched
// (ModelEmbedding::release_pages), and heap that the renders freed but the allocator keeps for
// its threads. None of it is needed while nobody asks; IdleRelease calls a release once the
// server has answered everything and heard nothing for a while.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace brdfnav::serve {

class IdleRelease {
 public:
  // Calls `release` on its own thread once no request has been in flight for `quiet`, once per
  // such spell: again only after another request.
  IdleRelease(std::chrono::milliseconds quiet, std::function<void()> release);
  ~IdleRelease();  // waits for a release under way
  IdleRelease(const IdleRelease&) = delete;
  IdleRelease& operator=(const IdleRelease&) = delete;

  // A request in flight, from construction to destruction.
  class Busy {
   public:
    explicit Busy(IdleRelease& idle);
    ~Busy();
    Busy(const Busy&) = delete;
    Busy& operator=(const Busy&) = delete;

   private:
    IdleRelease& idle_;
  };

 private:
  void run();

  const std::chrono::milliseconds quiet_;
  const std::function<void()> release_;
  std::mutex mutex_;
  std::condition_variable changed_;
  int in_flight_ = 0;
  bool used_ = false;  // a request since the last release
  bool stop_ = false;
  std::chrono::steady_clock::time_point last_end_;
  std::thread thread_;  // last: started once the rest is set
};

// Gives the heap the allocator keeps free back to the system (glibc's malloc_trim; nothing
// with another C library).
void trim_heap();

// Lets the allocator keep at most `arenas` heaps for the process's threads (glibc's
// M_ARENA_MAX, whose default is 8 per core; nothing with another C library). Call before the
// threads start. Each arena keeps the slack of what its threads freed, so that many arenas
// multiply it (measured in docs/SERVE.md, Memory).
// Whether the allocator took the limit.
bool limit_heap_arenas(int arenas);

}  // namespace brdfnav::serve
