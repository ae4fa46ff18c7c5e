#include <brdfnav/studies/render_accuracy.h>

#include <brdfnav/core/grid.h>

#include <algorithm>
#include <stdexcept>

namespace brdfnav {

const std::vector<AccuracySetting>& accuracy_settings() {
  using M = ModelId;
  static const std::vector<AccuracySetting> settings{
      {M::blinn_phong, "smooth", {20000}},
      {M::blinn_phong, "medium", {300}},
      {M::blinn_phong, "rough", {5}},
      {M::ward, "smooth", {0.01, 0.014}},
      {M::ward, "medium", {0.08, 0.06}},
      {M::ward, "rough", {0.4, 0.3}},
      {M::cook_torrance, "smooth", {0.05, 0.015}},
      {M::cook_torrance, "medium", {0.2, 0.12}},
      {M::cook_torrance, "rough", {0.5, 0.5}},
      {M::lafortune, "smooth", {0.57, 5000}},
      {M::lafortune, "medium", {0.56, 200}},
      {M::lafortune, "rough", {0.5, 5}},
      {M::he, "smooth", {0.1, 10, 1.5}},
      {M::he, "medium", {0.3, 8, 2}},
      {M::he, "rough", {1.5, 4, 4}},
      {M::ggx, "smooth", {0.02, 0.03}},
      {M::ggx, "medium", {0.12, 0.08}},
      {M::ggx, "rough", {0.5, 0.6}},
  };
  return settings;
}

const std::vector<AccuracySetting>& anisotropic_settings() {
  static const std::vector<AccuracySetting> settings{
      {ModelId::ward, "0.2 x 0.02", {0.2, 0.02}},
      {ModelId::ward, "0.05 x 0.5", {0.05, 0.5}},
  };
  return settings;
}

const AccuracySetting& sliver_setting() {
  static const AccuracySetting setting{ModelId::ward, "0.5 x 0.005", {0.5, 0.005}};
  return setting;
}

RenderQuality reference_quality(const RenderQuality& quality) {
  return quality.finer(4);
}

std::vector<AccuracyResult> measure_accuracy(Renderer& renderer, Renderer& reference,
                                             const AccuracySetting& setting) {
  const Image image = renderer.specular(make_lobe(setting.model, setting.params));
  return measure_accuracy(std::span(&image, 1), reference, setting).front();
}

std::vector<std::vector<AccuracyResult>> measure_accuracy(std::span<const Image> images,
                                                          Renderer& reference,
                                                          const AccuracySetting& setting) {
  const ModelInfo& info = model_info(setting.model);
  const Image reference_image = reference.specular(make_lobe(setting.model, setting.params));
  std::vector<double> errors;
  for (const Image& image : images) errors.push_back(image_distance(image, reference_image));
  std::vector<std::vector<AccuracyResult>> results(images.size());
  for (std::size_t d = 0; d < info.params.size(); ++d) {
    std::vector<double> stepped = setting.params;
    // Up by 10%, or down where that would leave the valid range (cz near 1).
    stepped[d] *= stepped[d] * 1.1 <= info.params[d].valid_max ? 1.1 : 1 / 1.1;
    const double step =
        image_distance(reference_image, reference.specular(make_lobe(setting.model, stepped)));
    for (std::size_t k = 0; k < images.size(); ++k)
      results[k].push_back({std::string(info.params[d].name), errors[k], step});
  }
  return results;
}

Image grid_image(Renderer& renderer, const AccuracySetting& setting) {
  const ModelInfo& info = model_info(setting.model);
  const ParamGrid table(info.params);
  std::vector<std::vector<double>> axes;
  std::vector<std::size_t> at;
  for (std::size_t d = 0; d < table.dimensions(); ++d) {
    const double value = setting.params[d];
    std::vector<double> axis{table.axis(d).front(), value, table.axis(d).back()};
    std::sort(axis.begin(), axis.end());
    axis.erase(std::unique(axis.begin(), axis.end()), axis.end());
    at.push_back(
        static_cast<std::size_t>(std::find(axis.begin(), axis.end(), value) - axis.begin()));
    axes.push_back(std::move(axis));
  }
  const ParamGrid grid(info.params, std::move(axes));
  const std::size_t node = grid.node_index(at);
  return std::move(renderer.grid_images(setting.model, grid, std::span(&node, 1)).front());
}

}  // namespace brdfnav
