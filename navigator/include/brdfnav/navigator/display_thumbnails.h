// Thumbnails as a display shows them, for lookdev hosts (the C ABI's brdfnav_navigator_thumbnail):
// a Thumbnails' linear RGBA through an ocio::ColorPipeline for one OCIO (display, view), 8-bit
// display-encoded RGBA with the uncovered pixels over the pipeline's background. The pipeline is
// built once with its config, and each (display, view) processor once on first use; every
// thumbnail after reuses them.
#pragma once

#include <brdfnav/core/material.h>
#include <brdfnav/navigator/thumbnails.h>
#include <brdfnav/ocio/color_pipeline.h>

#include <string>

namespace brdfnav {

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
  // pipeline().apply() of linear().render(m). The display and view are checked before anything is
  // rendered: an unknown one throws ocio::ColorError naming it and listing the valid ones. Then
  // Thumbnails::render's errors. Thread-safe.
  ocio::Thumbnail render(const Material& m, const std::string& display,
                         const std::string& view) const;

 private:
  const Thumbnails& thumbnails_;
  ocio::ColorPipeline pipeline_;
};

}  // namespace brdfnav
