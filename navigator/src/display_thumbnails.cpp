#include <brdfnav/navigator/display_thumbnails.h>

#include <brdfnav/navigator/silhouette.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace brdfnav {

bool shows_sphere(const Database& database) {
  return database.manifest().scene == "sphere";
}

ocio::Thumbnail display_encode(Image linear, bool sphere, const ocio::ColorPipeline& pipeline,
                               const std::string& display, const std::string& view) {
  if (sphere) antialias_sphere_silhouette(linear);
  std::vector<float> coverage(linear.rgba.size() / 4);
  for (std::size_t i = 0; i < coverage.size(); ++i)
    coverage[i] = std::exchange(linear.rgba[4 * i + 3], 1.f);  // opaque: nothing composited
  ocio::Thumbnail shown{
      linear.width, linear.height,
      pipeline.apply(linear.rgba.data(), linear.width, linear.height, display, view)};
  for (std::size_t i = 0; i < coverage.size(); ++i) {
    std::uint8_t* p = &shown.rgba[4 * i];
    p[3] = std::uint8_t(std::lround(255.f * std::clamp(coverage[i], 0.f, 1.f)));
    if (p[3] == 0) p[0] = p[1] = p[2] = 0;  // what the view makes of black is nobody's colour
  }
  return shown;
}

DisplayThumbnails::DisplayThumbnails(const Thumbnails& thumbnails, ocio::PipelineOptions options)
    : thumbnails_(thumbnails),
      sphere_(shows_sphere(thumbnails.database())),
      pipeline_(std::move(options)) {}

ocio::Thumbnail DisplayThumbnails::render(const Material& m, const std::string& display,
                                          const std::string& view) const {
  pipeline_.validate(display, view);
  return display_encode(thumbnails_.render(m), sphere_, pipeline_, display, view);
}

}  // namespace brdfnav
