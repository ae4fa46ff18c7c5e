// Thumbnails as a display shows them: a linear render through an ocio::ColorPipeline for one OCIO
// (display, view), 8-bit display-encoded RGBA whose alpha is the coverage, not associated with the
// colour. One encoding for every thumbnail a person sees: the server's PNGs (brdfnav serve) and
// the lookdev hosts' (the C ABI's brdfnav_navigator_thumbnail, through DisplayThumbnails). The
// pipeline is built once with its config, and each (display, view) processor once on first use;
// every thumbnail after reuses them.
#pragma once

#include <brdfnav/core/image.h>
#include <brdfnav/core/material.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/navigator/thumbnails.h>
#include <brdfnav/ocio/color_pipeline.h>

#include <string>

namespace brdfnav {

// Whether the database's images show the sphere scene, whose silhouette display_encode()
// antialiases (a mesh's is kept as rendered).
bool shows_sphere(const Database& database);

// What a display shows of `linear` (linear RGBA in the pipeline's source space, alpha the
// renderer's 0/1 mask): RGB the display encoding of the surface's own colour, composited over
// nothing; A the fraction of the pixel the surface covers, straight (PNG's convention, what a
// host composites "over" with). With `sphere` the silhouette is antialiased first (silhouette.h:
// partial alpha at the edge); otherwise A is 0 or 255 as rendered. A pixel nothing covers is
// 0 0 0 0. The metric's images keep their 0/1 mask: this is for display only. Throws
// ocio::ColorError for an unknown display or view, ImageError for a sphere that is not square.
ocio::Thumbnail display_encode(Image linear, bool sphere, const ocio::ColorPipeline& pipeline,
                               const std::string& display, const std::string& view);

class DisplayThumbnails {
 public:
  // Loads the OCIO config of `options` ($OCIO when set, else the built-in one: color_pipeline.h);
  // throws ocio::ColorError naming the config when it does not load. `thumbnails` (and its
  // database) must outlive this object; its image cache is shared with whoever else uses it.
  explicit DisplayThumbnails(const Thumbnails& thumbnails, ocio::PipelineOptions options = {});

  const ocio::ColorPipeline& pipeline() const { return pipeline_; }
  const Thumbnails& linear() const { return thumbnails_; }
  int resolution() const { return thumbnails_.resolution(); }

  // The thumbnail of `m` for (display, view): resolution() x resolution(), exactly
  // display_encode() of linear().render(m). The display and view are checked before anything is
  // rendered: an unknown one throws ocio::ColorError naming it and listing the valid ones. Then
  // Thumbnails::render's errors. Thread-safe.
  ocio::Thumbnail render(const Material& m, const std::string& display,
                         const std::string& view) const;

 private:
  const Thumbnails& thumbnails_;
  bool sphere_;
  ocio::ColorPipeline pipeline_;
};

}  // namespace brdfnav
