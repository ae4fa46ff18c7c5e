#include <brdfnav/lookdev/final_images.h>

#include <algorithm>
#include <optional>

namespace brdfnav::lookdev {

FinalImages::FinalImages(const Thumbnails& blends, const ExactThumbnails& exact, double faithful)
    : blends_(blends), exact_(exact), faithful_(faithful) {}

bool FinalImages::blend_within(const Material& m, int size, double bar) const {
  const Database& db = blends_.database();
  if (size != db.manifest().resolution || size != blends_.resolution()) return false;
  const std::optional<double> error = db.blend_error(m);
  return error && *error <= bar;
}

bool FinalImages::shows_blend(const Material& m, int size) const {
  return blend_within(m, size, faithful_);
}

std::shared_ptr<const Image> FinalImages::image(const Material& m, int size,
                                                const std::function<void()>& check) const {
  if (shows_blend(m, size)) return std::make_shared<const Image>(blends_.render(m));
  return exact_.render(m, size, check);
}

ExactSteps FinalImages::steps_from(const Material& current, double radius,
                                   std::function<void()> check) const {
  const int res = blends_.database().manifest().resolution;
  const double bar = std::min(faithful_, kStepShare * radius);
  const auto step_image = [this, res, bar, check](const Material& m) {
    if (blend_within(m, res, bar)) return std::make_shared<const Image>(blends_.render(m));
    return exact_.render(m, res, check);
  };
  // The current material's image once, not per step (a He blend sums 64 images).
  std::shared_ptr<const Image> from = step_image(current);
  ExactSteps steps;
  steps.distance = [from = std::move(from), step_image](const Material& m) {
    return image_distance(*from, *step_image(m));
  };
  return steps;
}

}  // namespace brdfnav::lookdev
