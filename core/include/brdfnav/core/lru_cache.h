// LruCache: values by key within a budget, the least recently used dropped first. Each value
// costs what its inserter says (bytes, pixels, or 1 for a count), and the cache keeps its total
// within the budget, save that the value inserted last always stays. Not thread-safe: each user
// holds its own lock around it (the thumbnails' image cache, the exact renders' cache, the rings
// a server remembers).
#pragma once

#include <cstddef>
#include <list>
#include <map>
#include <utility>

namespace brdfnav {

template <typename Key, typename Value>
class LruCache {
 public:
  explicit LruCache(std::size_t budget) : budget_(budget) {}

  // The value of `key`, now the most recently used, or nullptr.
  Value* find(const Key& key) {
    const auto it = entries_.find(key);
    if (it == entries_.end()) return nullptr;
    uses_.splice(uses_.begin(), uses_, it->second.use);
    return &it->second.value;
  }

  // `value` under `key` as the most recently used, costing `cost`; then the least recently used
  // others are dropped while the total is over the budget. A key already held keeps its value,
  // which is returned (two threads that made the same value: the first one kept wins).
  Value& insert(const Key& key, Value value, std::size_t cost) {
    if (const auto it = entries_.find(key); it != entries_.end()) return it->second.value;
    uses_.push_front(key);
    Entry& entry =
        entries_.emplace(key, Entry{std::move(value), cost, uses_.begin()}).first->second;
    total_ += cost;
    while (total_ > budget_ && uses_.size() > 1) {
      const auto oldest = entries_.find(uses_.back());
      total_ -= oldest->second.cost;
      entries_.erase(oldest);
      uses_.pop_back();
    }
    return entry.value;
  }

  // The value of `key` without counting it as a use, or nullptr.
  const Value* peek(const Key& key) const {
    const auto it = entries_.find(key);
    return it == entries_.end() ? nullptr : &it->second.value;
  }

  std::size_t size() const { return entries_.size(); }
  // The cost of what it holds now.
  std::size_t total() const { return total_; }

 private:
  struct Entry {
    Value value;
    std::size_t cost;
    typename std::list<Key>::iterator use;  // its place in uses_
  };
  std::size_t budget_;
  std::size_t total_ = 0;
  std::map<Key, Entry> entries_;
  std::list<Key> uses_;  // most recently used first
};

}  // namespace brdfnav
