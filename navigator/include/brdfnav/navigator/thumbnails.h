// Thumbnails of any material, fast enough for the navigator (docs/NAVIGATION.md): the database's
// pre-rendered images of the nodes around the material on its grid, each composed with the
// material's rho_d and rho_s, blended with the embedding's cubic weights in cube-root space
// (negative values, which a spline may overshoot to in dark pixels, are clamped to 0) and cubed
// back. At a grid node that is exactly the pre-rendered image of the material; between nodes it
// is the image whose cube root the embedding interpolates, so what the thumbnail shows and the
// distances the navigator measures agree.
#pragma once

#include <brdfnav/core/image.h>
#include <brdfnav/core/lru_cache.h>
#include <brdfnav/core/material.h>
#include <brdfnav/navigator/blend.h>
#include <brdfnav/navigator/database.h>

#include <cstddef>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace brdfnav {

class Thumbnails {
 public:
  // 64 MiB: 256 database images at 128 x 128, more than the nodes a tab's 10 He thumbnails blend
  // (64 each, mostly shared); a default database's images are several times that. Its effect on
  // memory and speed: docs/NAVIGATION.md, Speed and memory.
  static constexpr std::size_t kDefaultCacheBytes = std::size_t{64} << 20;

  // `resolution` 0: the database's own. The database must outlive this object. The images read
  // are kept, least recently used first out, up to `cache_bytes` (at least the last one read).
  explicit Thumbnails(const Database& database, int resolution = 128,
                      std::size_t cache_bytes = kDefaultCacheBytes);

  int resolution() const { return resolution_; }
  const Database& database() const { return database_; }
  // Linear RGBA at resolution() x resolution(), alpha the database's mask. Throws
  // MaterialError for an invalid material, DatabaseError for a model the database lacks or an
  // unreadable image. Thread-safe.
  Image render(const Material& m) const;
  // The bytes of pixels the cache holds now.
  std::size_t cached_bytes() const;

 private:
  using Key = std::pair<int, std::size_t>;  // (model, node); model -1 is the diffuse image
  static constexpr Key kDiffuse{-1, 0};
  // The images of `keys` at thumbnail resolution: the cached ones, and the others read (in
  // parallel) and cached.
  std::vector<std::shared_ptr<const Image>> images(const std::vector<Key>& keys) const;
  // One database image, read and resampled to thumbnail resolution.
  std::shared_ptr<const Image> read(Key key) const;
  // Holds `image` as the most recently used; drops the least recently used over the budget.
  std::shared_ptr<const Image> keep(Key key, std::shared_ptr<const Image> image) const;

  const Database& database_;
  int resolution_;
  mutable std::mutex mutex_;
  // The images by key, each costing its pixels' bytes.
  mutable LruCache<Key, std::shared_ptr<const Image>> cache_;
};

}  // namespace brdfnav
