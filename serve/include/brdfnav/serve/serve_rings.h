// Which rings a page has left. The page numbers the rings it draws (one client id per page);
// once it asks for a later ring, the renders still waiting for an earlier one are not worth
// their seconds: nobody will see them. The server then answers them 409 instead of rendering
// (docs/SERVE.md, "Rings left").
#pragma once

#include <brdfnav/core/lru_cache.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>

namespace brdfnav::serve {

// What a request names: a page (`client`) and the number of its ring.
struct RingId {
  std::string client;
  std::uint64_t ring = 0;
};

// Thrown by the work of a ring its page has left: before a render it would start, or between
// the rows of one under way (ExactThumbnails::render).
class RingLeft : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class LeftRings {
 public:
  // `clients`: how many pages it remembers (the least recently heard from forgotten first).
  explicit LeftRings(std::size_t clients = 1024) : latest_(clients) {}

  // Records that `id.client` now asks for `id.ring` (a page's rings only go up; an older number
  // arriving late changes nothing).
  void enter(const RingId& id);
  // Whether `id.client` has asked for a later ring than `id.ring`.
  bool left(const RingId& id) const;
  // A predicate for the work of `id`, which throws RingLeft once the ring is left.
  std::function<void()> check(const RingId& id) const;

 private:
  mutable std::mutex mutex_;
  LruCache<std::string, std::uint64_t> latest_;  // each page's latest ring, a page costing 1
};

}  // namespace brdfnav::serve
