#include <brdfnav/serve/serve_rings.h>

#include <algorithm>

namespace brdfnav::serve {

void LeftRings::enter(const RingId& id) {
  const std::lock_guard lock(mutex_);
  if (std::uint64_t* ring = latest_.find(id.client))
    *ring = std::max(*ring, id.ring);
  else
    latest_.insert(id.client, id.ring, 1);
}

bool LeftRings::left(const RingId& id) const {
  const std::lock_guard lock(mutex_);
  const std::uint64_t* ring = latest_.peek(id.client);
  return ring && *ring > id.ring;
}

std::function<void()> LeftRings::check(const RingId& id) const {
  return [this, id] {
    if (left(id))
      throw RingLeft("ring: " + std::to_string(id.ring) + " of this page was left for a later one");
  };
}

}  // namespace brdfnav::serve
