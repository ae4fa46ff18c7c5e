#include <brdfnav/serve/serve_rings.h>

#include <algorithm>

namespace brdfnav::serve {

void LeftRings::enter(const RingId& id) {
  const std::lock_guard lock(mutex_);
  const auto it = latest_.find(id.client);
  if (it != latest_.end()) {
    it->second.ring = std::max(it->second.ring, id.ring);
    uses_.splice(uses_.begin(), uses_, it->second.use);
    return;
  }
  uses_.push_front(id.client);
  latest_.emplace(id.client, Client{id.ring, uses_.begin()});
  while (latest_.size() > capacity_) {
    latest_.erase(uses_.back());
    uses_.pop_back();
  }
}

bool LeftRings::left(const RingId& id) const {
  const std::lock_guard lock(mutex_);
  const auto it = latest_.find(id.client);
  return it != latest_.end() && it->second.ring > id.ring;
}

std::function<void()> LeftRings::check(const RingId& id) const {
  return [this, id] {
    if (left(id))
      throw RingLeft("ring: " + std::to_string(id.ring) + " of this page was left for a later one");
  };
}

}  // namespace brdfnav::serve
