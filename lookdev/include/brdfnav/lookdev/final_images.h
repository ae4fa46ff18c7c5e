// The images the navigator shows as final, and the steps measured on them (docs/NAVIGATION.md,
// "Final images", with what each costs). An exact render costs seconds; the blend of the
// database's images (Thumbnails) costs milliseconds and is, in most of each grid, as close to the
// exact render as two renders of one material at different qualities. The database's blend check
// (Database::blend_error()) says where: per cell, the blend's distance from an exact render at
// the cell's midpoint. Where that is within `faithful`, the blend is the final image; elsewhere
// (Lafortune across its switch at cz = 1/sqrt(3), a rough He lobe; a database without the check)
// the exact render (ExactThumbnails) is.
#pragma once

#include <brdfnav/lookdev/exact_thumbnails.h>

#include <brdfnav/navigator/thumbnails.h>

#include <functional>
#include <memory>

namespace brdfnav::lookdev {

class FinalImages {
 public:
  // 0.1 eps at the page's eps of 0.03: the blend check's midpoint is about the farthest a cell's
  // blend gets from its render, so a vouched cell's images stay well inside the fidelity target
  // (0.05 eps median, 0.25 eps worst), and exact steps measured on two of them err by at most
  // twice this (their fidelity, measured: `brdfnav bench fidelity --exact`).
  static constexpr double kFaithfulBlend = 0.003;

  // Both must outlive this object.
  FinalImages(const Thumbnails& blends, const ExactThumbnails& exact,
              double faithful = kFaithfulBlend);

  // Whether `m`'s final image at `size` is its blend: `size` is the database's resolution and
  // the blends', and the database's blend check of m's cell is within `faithful`.
  bool shows_blend(const Material& m, int size) const;
  // Linear RGBA at `size` squared: the blend where shows_blend(), else the exact render (with
  // ExactThumbnails::render's `check`, its cache and its errors).
  std::shared_ptr<const Image> image(const Material& m, int size,
                                     const std::function<void()>& check = {}) const;
  // Steps at `radius` measured at the database's resolution (the metric's) on blends where they
  // are faithful against the radius too, renders otherwise: an image is its blend where
  // shows_blend() and its cell's check is within kStepShare * radius. Two images then err by at
  // most 2 * kStepShare of the radius at their cells' midpoints (the same bar as the thumbnails'
  // at eps = 0.03, stricter below it). Makes `current`'s image now (with `check`).
  static constexpr double kStepShare = 0.1;
  ExactSteps steps_from(const Material& current, double radius,
                        std::function<void()> check = {}) const;

 private:
  // Whether `m`'s image at `size` may be its blend under `bar`: the database's resolution and the
  // blends', and m's cell's check within `bar`.
  bool blend_within(const Material& m, int size, double bar) const;

  const Thumbnails& blends_;
  const ExactThumbnails& exact_;
  double faithful_;
};

}  // namespace brdfnav::lookdev
