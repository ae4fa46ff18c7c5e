// Thumbnails of any material, fast enough for the navigator (issue #5): the database's
// pre-rendered images of the nodes around the material on its grid, each composed with the
// material's rho_d and rho_s, blended with the embedding's cubic weights in cube-root space
// (negative values, which a spline may overshoot to in dark pixels, are clamped to 0) and cubed
// back. At a grid node that is exactly the pre-rendered image of the material; between nodes it
// is the image whose cube root the embedding interpolates, so what the thumbnail shows and the
// distances the navigator measures agree.
#pragma once

#include <brdfnav/core/material.h>
#include <brdfnav/precompute/database.h>
#include <brdfnav/precompute/image.h>

#include <map>
#include <memory>
#include <mutex>
#include <utility>

namespace brdfnav {

class Thumbnails {
 public:
  // `resolution` 0: the database's own. The database must outlive this object.
  explicit Thumbnails(const Database& database, int resolution = 128);

  int resolution() const { return resolution_; }
  // Linear RGBA at resolution() x resolution(), alpha the database's mask. Throws
  // MaterialError for an invalid material, DatabaseError for a model the database lacks or an
  // unreadable image. Thread-safe.
  Image render(const Material& m) const;

 private:
  using Key = std::pair<int, std::size_t>;  // (model, node); model -1 is the diffuse image
  // The image at thumbnail resolution, read and resampled on first use, then kept.
  std::shared_ptr<const Image> image(Key key) const;

  const Database& database_;
  int resolution_;
  mutable std::mutex mutex_;
  mutable std::map<Key, std::shared_ptr<const Image>> cache_;
};

}  // namespace brdfnav
