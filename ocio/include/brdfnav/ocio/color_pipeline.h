#pragma once
// Colour management for thumbnails: scene-linear float RGBA in, display-encoded RGBA out, through
// OpenColorIO. The config comes from $OCIO when set, otherwise from a config built in code from
// OCIO 2.1's built-in transforms (docs/COLOR.md lists its colour spaces, displays and views).
// brdfnav::ocio: OpenColorIO only (no OpenImageIO), so that the navigator's library can link it.

#include <OpenColorIO/OpenColorABI.h>  // OCIO_NAMESPACE, for the processor handle below
#include <brdfnav/core/error.h>
#include <brdfnav/core/material.h>
#include <brdfnav/core/warning.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace OCIO_NAMESPACE {
class CPUProcessor;
}

namespace brdfnav::ocio {

// Any colour-management failure. The message names the file, display, view or colour space. The
// caller's mistakes (an unknown display or view, a malformed image buffer) are
// ErrorCode::invalid_argument; the environment's (a config that does not load, lacks the source
// colour space or cannot build a processor) are ErrorCode::io.
using ColorError = LayerError<struct ColorErrorTag, ErrorCode::invalid_argument>;

// What describe() and config_source() report for the config built in code.
inline constexpr const char* kBuiltinConfigName = "built-in";
// The built-in config's displays and views; its scene-linear space is kDefaultColorspace
// (brdfnav/core/material.h), the materials' own.
inline constexpr const char* kDisplaySRGB = "sRGB";
inline constexpr const char* kDisplayRec1886 = "Rec.1886";
inline constexpr const char* kViewStandard = "Standard";
inline constexpr const char* kViewACES = "ACES 1.0 SDR-video";

// 8-bit display-encoded RGBA, row-major, row 0 at the top: what ColorPipeline::apply returns,
// with its size.
struct Thumbnail {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

struct PipelineOptions {
  // OCIO config file; empty means $OCIO when set (and not empty), else the built-in config.
  std::string config_path;
  // Colour space of the input buffers: a name, alias or role of the config. If the config has no
  // such space, its scene_linear role, then its default role, is used instead (with a warning).
  std::string source = kDefaultColorspace;
  // Linear RGB, in the source space, that uncovered pixels are composited over before the
  // display transform (mid grey by default).
  std::array<float, 3> background = {0.18f, 0.18f, 0.18f};
  WarningSink warn = warn_to_stderr;
};

// One loaded config and its processors. The constructor warns (once, through options.warn) when
// the default display/view leaves the source unchanged, as OCIO's raw config does: such a config
// does no colour management at all and must not be used silently.
//
// All const members are safe to call from several threads at once: each (display, view)
// processor is built once under a mutex, then shared; OCIO's CPU processors are immutable.
class ColorPipeline {
 public:
  // Throws ColorError if the config cannot be loaded or validated (naming the file), or if it has
  // no usable source colour space.
  explicit ColorPipeline(PipelineOptions options = {});
  ~ColorPipeline();
  ColorPipeline(ColorPipeline&&) noexcept;
  ColorPipeline& operator=(ColorPipeline&&) noexcept;

  // "OCIO config: <path or built-in>; source colour space: <name>".
  std::string describe() const;
  // The config file's path, or kBuiltinConfigName.
  const std::string& config_source() const;
  // The canonical name of the colour space the input buffers are read in.
  const std::string& source_colorspace() const;

  // Active displays and a display's views, in the config's order (the first is the default).
  std::vector<std::string> displays() const;
  std::vector<std::string> views(const std::string& display) const;
  std::string default_display() const;
  std::string default_view(const std::string& display) const;

  // Throws ColorError naming the unknown display (or view) and listing the valid ones.
  void validate(const std::string& display, const std::string& view) const;

  // The cached source -> (display, view) processor; the same object on every call.
  std::shared_ptr<const OCIO_NAMESPACE::CPUProcessor> processor(const std::string& display,
                                                                const std::string& view) const;

  // `rgba` is width x height linear RGBA in the source space, row-major, row 0 at the top.
  // Pixels are composited over the background ("over", premultiplied: rgb + (1 - a) * bg), then
  // transformed; RGB comes back display-encoded and clipped to [0, 1] (NaN -> 0), alpha is the
  // input's, clipped to [0, 1]. Throws ColorError for a null buffer, negative sizes or an unknown
  // display/view.
  std::vector<float> apply_float(const float* rgba, int width, int height,
                                 const std::string& display, const std::string& view) const;
  // The same, quantised to 8 bits per channel (round to nearest).
  std::vector<std::uint8_t> apply(const float* rgba, int width, int height,
                                  const std::string& display, const std::string& view) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace brdfnav::ocio
