// Thumbnails rendered exactly: what `POST /api/thumbnail` answers unless a preview (the blend of
// the database's images, brdfnav/navigator/thumbnails.h) is asked for. A blend between grid
// nodes can show another material (Lafortune across its switch at cz = 1/sqrt(3): up to 5 eps
// from the exact render, `brdfnav bench fidelity`); the renderer's image is the material itself,
// under the database's map and scene, at the thumbnails' resolution.
#pragma once

#include <brdfnav/core/material.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/navigator/image.h>
#include <brdfnav/navigator/navigator.h>

#include <cstddef>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace brdfnav::cli {

class ExactThumbnails {
 public:
  // The renderer (the database's map, checked against its recorded pixels, and scene) is made
  // on the first render, not at start-up. `cache_images`: rendered images kept, least recently
  // used first out.
  ExactThumbnails(const Database& database, int resolution, std::size_t cache_images = 512);
  ~ExactThumbnails();

  // Linear RGBA at `resolution` x `resolution`, alpha the coverage. Renders one material at a
  // time (each render uses every core); a cached one comes back at once. Throws DatabaseError
  // when the database's map has changed or is gone, MaterialError for an invalid material.
  std::shared_ptr<const Image> render(const Material& m) const;
  // Steps measured on these renders (Navigator::neighbors): the image metric's distance from
  // `current`'s render, at this resolution. The renders stay in the cache, so the thumbnails of
  // the offers are ready once their steps are. Keeps a reference to *this.
  ExactSteps steps_from(const Material& current) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace brdfnav::cli
