// How accurate the pre-renderer is, in the metric's own terms: for a material and one of its
// parameters,
//   ratio = d(image at default quality, converged reference) / d(reference at p, reference at p')
// with p' the parameter changed by 10%. A ratio of 0.1 means the renderer's error is a tenth of
// the smallest step a user would take; the pre-rendered grids need <= 0.1 everywhere.
#pragma once

#include <brdfnav/core/material.h>
#include <brdfnav/renderer/render.h>

#include <span>
#include <string>
#include <vector>

namespace brdfnav {

// Smooth, medium and rough settings of every model: the points where accuracy is measured.
struct AccuracySetting {
  ModelId model;
  std::string name;            // "smooth", "medium", "rough"
  std::vector<double> params;  // in model_info(model).params order
};
const std::vector<AccuracySetting>& accuracy_settings();
// Strongly anisotropic Ward lobes, beyond the three settings per model above, which bend far from
// the ellipse around their peak (the quadrature's window follows their slopes: docs/RENDERER.md).
const std::vector<AccuracySetting>& anisotropic_settings();
// Ward 0.5 x 0.005, whose window is a sliver as long as a hemisphere and 1/100 as wide: it fills
// the per-pixel node budget (RenderQuality::max_nodes), and its reference takes minutes at
// 128 x 128 (its ratios: docs/RENDERER.md, Accuracy). Benchmarked, not tested.
const AccuracySetting& sliver_setting();

struct AccuracyResult {
  std::string param;  // the parameter changed by 10%
  double error;       // d(default, reference) at the setting
  double step;        // d(reference at p, reference at p changed by 10%)
  double ratio() const { return error / step; }
};

// The reference quality: 4x finer (16x the samples).
RenderQuality reference_quality(const RenderQuality& quality);

// One result per non-linear parameter of the setting, for its lobe alone (rho_d = 0, rho_s = 1:
// the hardest case for the cube root, and the images the embedding is built from). Both
// renderers must share the environment, scene and resolution.
std::vector<AccuracyResult> measure_accuracy(Renderer& renderer, Renderer& reference,
                                             const AccuracySetting& setting);
// ... of images of the setting's lobe made otherwise (grid_image()), against the same
// reference images: one list of results per image.
std::vector<std::vector<AccuracyResult>> measure_accuracy(std::span<const Image> images,
                                                          Renderer& reference,
                                                          const AccuracySetting& setting);

// A setting's lobe as the precompute renders it, Renderer::grid_images(): in a grid of its
// model's table ranges, each axis the table's ends and the setting's value (Ward's one pass over
// the grid depends on them, and they are the ends of every profile's grid). Differs from
// specular() of the lobe only where grid_images_differ().
Image grid_image(Renderer& renderer, const AccuracySetting& setting);

}  // namespace brdfnav
