// Thumbnails rendered exactly, under the database's map and scene, at the thumbnails' resolution
// or a larger one (a sharp centre on a screen of device pixel ratio 2). A blend between grid
// nodes can show another material (Lafortune across its switch at cz = 1/sqrt(3): up to 5 eps
// from the exact render, `brdfnav bench fidelity`); the renderer's image is the material itself.
// What the server answers is FinalImages' choice (final_images.h): these renders, or the blend
// where the database's blend check vouches for it.
#pragma once

#include <brdfnav/core/image.h>
#include <brdfnav/core/material.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/navigator/navigator.h>

#include <cstddef>
#include <functional>
#include <memory>

namespace brdfnav::lookdev {

class ExactThumbnails {
 public:
  // The map (checked against the database's record of its pixels) and the scene are loaded on
  // the first render, not at start-up, and shared by the renderers of every resolution.
  // `cache_images`: how many lobes' images of `resolution` the cache keeps (larger ones count
  // as several), least recently used first out.
  ExactThumbnails(const Database& database, int resolution, std::size_t cache_images = 512);
  ~ExactThumbnails();

  int resolution() const;
  // Linear RGBA at resolution() (or `resolution`) squared, alpha the coverage: the image
  // Renderer::render gives, its colours composed onto the render of its lobe. Renders one lobe
  // at a time per resolution (each render uses every core), so a large render does not hold the
  // small ones back; a cached lobe comes back at once, in any colours. Throws DatabaseError when
  // the database's map has changed or is gone, MaterialError for an invalid material. `check`, when
  // given, is called once the renderer is free, just before a render it would start (not for a
  // cached lobe), then from the renderer's progress while it runs (after each row the calling
  // thread finishes): its exception, if any, leaves the work undone or stops it (a ring the page
  // has left: serve_rings.h), and nothing of a stopped render is cached.
  std::shared_ptr<const Image> render(const Material& m) const;
  std::shared_ptr<const Image> render(const Material& m, int resolution,
                                      const std::function<void()>& check = {}) const;
  // The map the renders are lit by, as a picture `width` wide for people (database_env.h,
  // environment_picture()); loads the map as the first render would, with its errors.
  Image environment_picture(int width) const;
  // Steps measured on these renders (Navigator::neighbors): the image metric's distance from
  // `current`'s render, at `resolution` (0: resolution()), which is rendered here, once. The
  // renders stay in the cache, so the thumbnails of the offers are ready once their steps are.
  // Keeps a reference to *this.
  ExactSteps steps_from(const Material& current, int resolution = 0,
                        std::function<void()> check = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace brdfnav::lookdev
