#include <brdfnav/ocio/color_pipeline.h>

#include "builtin_config.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <mutex>
#include <utility>

namespace brdfnav::ocio {

namespace OCIO = OCIO_NAMESPACE;

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "'" : ", '") + name + "'";
  return out.empty() ? "(none)" : out;
}

// Where the config comes from: an explicit path, then $OCIO, then the built-in one.
std::string config_path(const PipelineOptions& options) {
  if (!options.config_path.empty()) return options.config_path;
  const char* env = std::getenv("OCIO");
  return env ? env : "";
}

OCIO::ConstConfigRcPtr load_config(const std::string& path, bool from_env) {
  if (path.empty()) return make_builtin_config();
  try {
    auto config = OCIO::Config::CreateFromFile(path.c_str());
    config->validate();
    return config;
  } catch (const OCIO::Exception& e) {
    throw ColorError("cannot load OCIO config '" + path + "'" + (from_env ? " (from $OCIO)" : "") +
                         ": " + e.what(),
                     ErrorCode::io);
  }
}

std::vector<std::string> colorspace_names(const OCIO::Config& config) {
  std::vector<std::string> names;
  const int n = config.getNumColorSpaces();
  for (int i = 0; i < n; ++i) names.emplace_back(config.getColorSpaceNameByIndex(i));
  return names;
}

// The requested space, else the config's scene_linear role, else its default role: a config
// that names linear Rec.709 differently still works, but never without saying so.
std::string resolve_source(const OCIO::Config& config, const PipelineOptions& options) {
  if (auto cs = config.getColorSpace(options.source.c_str())) return cs->getName();
  for (const char* role : {OCIO::ROLE_SCENE_LINEAR, OCIO::ROLE_DEFAULT}) {
    auto cs = config.getColorSpace(role);
    if (!cs) continue;
    options.warn("OCIO config has no colour space '" + options.source + "'; using its " + role +
                 " role '" + cs->getName() + "' for the thumbnails' input");
    return cs->getName();
  }
  throw ColorError("OCIO config has no colour space '" + options.source +
                       "' and no scene_linear or default role; its colour spaces: " +
                       join(colorspace_names(config)),
                   ErrorCode::io);
}

// Written so that NaN fails the comparison and becomes 0.
float clip01(float v) {
  return v > 0.0f ? std::min(v, 1.0f) : 0.0f;
}

}  // namespace

struct ColorPipeline::Impl {
  OCIO::ConstConfigRcPtr config;
  std::string config_source;
  std::string source;
  std::array<float, 3> background{};
  mutable std::mutex mutex;
  mutable std::map<std::pair<std::string, std::string>, OCIO::ConstCPUProcessorRcPtr> processors;
};

ColorPipeline::ColorPipeline(PipelineOptions options) : impl_(std::make_unique<Impl>()) {
  if (!options.warn) options.warn = warn_to_stderr;
  const std::string path = config_path(options);
  impl_->config = load_config(path, options.config_path.empty());
  impl_->config_source = path.empty() ? kBuiltinConfigName : path;
  impl_->source = resolve_source(*impl_->config, options);
  impl_->background = options.background;

  // OCIO's raw config (and any config like it) maps everything to itself: the thumbnails would
  // show scene-linear values as if they were display-encoded.
  const std::string display = default_display();
  const std::string view = default_view(display);
  if (processor(display, view)->isNoOp())
    options.warn("OCIO config '" + impl_->config_source + "' leaves '" + impl_->source +
                 "' unchanged on display '" + display + "', view '" + view +
                 "' (a raw config?): thumbnails are not colour-managed");
}

ColorPipeline::~ColorPipeline() = default;
ColorPipeline::ColorPipeline(ColorPipeline&&) noexcept = default;
ColorPipeline& ColorPipeline::operator=(ColorPipeline&&) noexcept = default;

std::string ColorPipeline::describe() const {
  return "OCIO config: " + impl_->config_source + "; source colour space: " + impl_->source;
}

const std::string& ColorPipeline::config_source() const {
  return impl_->config_source;
}
const std::string& ColorPipeline::source_colorspace() const {
  return impl_->source;
}

std::vector<std::string> ColorPipeline::displays() const {
  std::vector<std::string> out;
  const int n = impl_->config->getNumDisplays();
  for (int i = 0; i < n; ++i) out.emplace_back(impl_->config->getDisplay(i));
  return out;
}

std::vector<std::string> ColorPipeline::views(const std::string& display) const {
  const auto all = displays();
  if (std::find(all.begin(), all.end(), display) == all.end())
    throw ColorError("unknown OCIO display '" + display + "'; displays: " + join(all));
  std::vector<std::string> out;
  const int n = impl_->config->getNumViews(display.c_str());
  for (int i = 0; i < n; ++i) out.emplace_back(impl_->config->getView(display.c_str(), i));
  return out;
}

std::string ColorPipeline::default_display() const {
  return impl_->config->getDefaultDisplay();
}

std::string ColorPipeline::default_view(const std::string& display) const {
  views(display);  // throws for an unknown display
  return impl_->config->getDefaultView(display.c_str());
}

void ColorPipeline::validate(const std::string& display, const std::string& view) const {
  const auto valid = views(display);
  if (std::find(valid.begin(), valid.end(), view) == valid.end())
    throw ColorError("OCIO display '" + display + "' has no view '" + view +
                     "'; its views: " + join(valid));
}

std::shared_ptr<const OCIO::CPUProcessor> ColorPipeline::processor(const std::string& display,
                                                                   const std::string& view) const {
  validate(display, view);
  std::lock_guard lock(impl_->mutex);
  auto& cached = impl_->processors[{display, view}];
  if (!cached) {
    auto transform = OCIO::DisplayViewTransform::Create();
    transform->setSrc(impl_->source.c_str());
    transform->setDisplay(display.c_str());
    transform->setView(view.c_str());
    try {
      cached = impl_->config->getProcessor(transform)->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
      throw ColorError("cannot build the OCIO processor '" + impl_->source + "' -> display '" +
                           display + "', view '" + view + "': " + e.what(),
                       ErrorCode::io);
    }
  }
  return cached;
}

std::vector<float> ColorPipeline::apply_float(const float* rgba, int width, int height,
                                              const std::string& display,
                                              const std::string& view) const {
  if (width < 0 || height < 0 || (!rgba && width > 0 && height > 0))
    throw ColorError("bad RGBA buffer: " + std::to_string(width) + "x" + std::to_string(height) +
                     (rgba ? "" : ", null data"));
  const auto cpu = processor(display, view);
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  std::vector<float> out(rgba, rgba + 4 * pixels);
  const auto& bg = impl_->background;
  for (std::size_t p = 0; p < pixels; ++p) {
    float* px = &out[4 * p];
    const float uncovered = 1.0f - clip01(px[3]);
    for (int c = 0; c < 3; ++c) px[c] += uncovered * bg[c];
  }
  if (pixels == 0) return out;
  OCIO::PackedImageDesc image(out.data(), width, height, 4);
  cpu->apply(image);
  for (float& v : out) v = clip01(v);
  return out;
}

std::vector<std::uint8_t> ColorPipeline::apply(const float* rgba, int width, int height,
                                               const std::string& display,
                                               const std::string& view) const {
  const auto encoded = apply_float(rgba, width, height, display, view);
  std::vector<std::uint8_t> out(encoded.size());
  std::transform(encoded.begin(), encoded.end(), out.begin(),
                 [](float v) { return static_cast<std::uint8_t>(std::lround(v * 255.0f)); });
  return out;
}

}  // namespace brdfnav::ocio
