#include <brdfnav/navigator/display_thumbnails.h>

#include <utility>

namespace brdfnav {

DisplayThumbnails::DisplayThumbnails(const Thumbnails& thumbnails, ocio::PipelineOptions options)
    : thumbnails_(thumbnails), pipeline_(std::move(options)) {}

ocio::Thumbnail DisplayThumbnails::render(const Material& m, const std::string& display,
                                          const std::string& view) const {
  pipeline_.validate(display, view);
  const Image linear = thumbnails_.render(m);
  return {linear.width, linear.height,
          pipeline_.apply(linear.rgba.data(), linear.width, linear.height, display, view)};
}

}  // namespace brdfnav
