// `brdfnav bench render`: the pre-renderer's speed and accuracy (docs/RENDERER.md) on this
// machine, as Markdown tables, and with --json its figures (bench_figures.h).
#include "bench_render.h"

#include "bench_figures.h"

#include <brdfnav/core/grid.h>
#include <brdfnav/renderer/render.h>
#include <brdfnav/studies/render_accuracy.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <optional>
#include <span>

namespace brdfnav::cli {

namespace {

// Mean wall-clock milliseconds per image of render(), called `repeats` times, each making
// `images` images.
template <typename Render>
double ms_per_image(int repeats, double images, Render&& render) {
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) render();
  const std::chrono::duration<double, std::milli> elapsed =
      std::chrono::steady_clock::now() - start;
  return elapsed.count() / (repeats * images);
}

// Mean wall-clock milliseconds of one specular image of the setting, without what the renderer
// computes once for all images of the model (Renderer::prepare).
double time_image(Renderer& renderer, const AccuracySetting& s, int repeats) {
  const Lobe lobe = make_lobe(s.model, s.params);
  renderer.prepare(lobe);
  return ms_per_image(repeats, 1, [&] { renderer.specular(lobe); });
}

// The parameter of `s`'s model that the renderer batches along (its Fresnel parameter: He's eta,
// Cook-Torrance's f0), found as the one whose change alone keeps two lobes in one quadrature
// (shares_quadrature), with the table's first kFresnelBatch grid nodes of it (one pass); none
// for other models.
struct FresnelBatch {
  std::size_t param;        // index into the model's parameter table
  std::vector<Lobe> lobes;  // the setting's lobe at the parameter's first grid nodes
};
std::optional<FresnelBatch> fresnel_batch(const AccuracySetting& s) {
  const std::span<const ParamSpec> specs = model_info(s.model).params;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    std::vector<Lobe> lobes;
    for (double node : grid_nodes(specs[k])) {
      if (lobes.size() == std::size_t(kFresnelBatch)) break;
      std::vector<double> p = s.params;
      p[k] = node;
      lobes.push_back(make_lobe(s.model, p));
    }
    if (shares_quadrature(lobes[0], lobes[1])) return FresnelBatch{k, std::move(lobes)};
  }
  return std::nullopt;
}

// The precompute's images along each model's Fresnel parameter (fresnel_batch): ms per image
// rendered alone and rendered together in one pass (Renderer::specular of a span).
void fresnel_batch_rows(Renderer& renderer, int repeats, const std::string& model,
                        BenchFigures& figures) {
  std::printf(
      "\n| setting | batched parameter | ms per image, alone | ... in one pass | ratio |\n");
  std::printf("|---|---|---|---|---|\n");
  std::map<std::string, std::pair<double, int>> together_ms;  // per model: ms, settings
  for (const AccuracySetting& s : accuracy_settings()) {
    const ModelInfo& info = model_info(s.model);
    if (!model.empty() && model != info.name) continue;
    const auto batch = fresnel_batch(s);
    if (!batch) continue;
    const std::vector<Lobe>& lobes = batch->lobes;
    auto ms_of = [&](auto&& render) { return ms_per_image(repeats, double(lobes.size()), render); };
    renderer.prepare(lobes.front());
    const double alone = ms_of([&] {
      for (const Lobe& l : lobes) renderer.specular(l);
    });
    const double together = ms_of([&] { renderer.specular(lobes); });
    auto& [sum, settings] = together_ms[std::string(info.name)];
    sum += together;
    ++settings;
    std::printf("| %s %s | %s (%zu nodes) | %.1f | %.1f | %.2f |\n", std::string(info.name).c_str(),
                s.name.c_str(), std::string(info.params[batch->param].name).c_str(), lobes.size(),
                alone, together, together / alone);
    std::fflush(stdout);
  }
  for (const auto& [name, sum] : together_ms)
    figures.add(name + "_batched_ms", sum.first / sum.second);
}

// Ward's grid (the table's 15 x 15 alphas) rendered in one pass, as the precompute renders it
// (Renderer::ward_grid): ms per image.
void ward_grid_rows(Renderer& renderer, int repeats, BenchFigures& figures) {
  const ParamGrid grid(Ward::kParams);
  const double ms = ms_per_image(repeats, double(grid.node_count()),
                                 [&] { renderer.ward_grid(grid.axis(0), grid.axis(1)); });
  figures.add("ward_grid_ms", ms);
  std::printf("\n| ward grid in one pass | ms per image |\n|---|---|\n| %zu x %zu | %.1f |\n",
              grid.axis(0).size(), grid.axis(1).size(), ms);
}

// The largest ratio of `results`, at least `so_far`.
double max_ratio(const std::vector<AccuracyResult>& results, double so_far) {
  for (const AccuracyResult& r : results) so_far = std::max(so_far, r.ratio());
  return so_far;
}

// "alpha_x 0.011, alpha_y 0.010"
std::string ratio_cell(const std::vector<AccuracyResult>& results) {
  std::string cell;
  for (const AccuracyResult& r : results) {
    char one[96];
    std::snprintf(one, sizeof one, "%s%s %.3f", cell.empty() ? "" : ", ", r.param.c_str(),
                  r.ratio());
    cell += one;
  }
  return cell;
}

}  // namespace

void run_render_bench(const RenderBenchOptions& o) {
  const EnvMap env = load_env(o.setup);
  const Scene scene = load_scene(o.setup);
  Renderer renderer(env, scene, o.setup.resolution);
  RenderOptions reference_options;
  reference_options.quality = reference_quality(renderer.options().quality);
  Renderer reference(env, scene, o.setup.resolution, reference_options);
  std::printf("resolution %d, %s, %s\n\n", o.setup.resolution, env.source().c_str(),
              scene.description().c_str());
  std::printf("| model | setting | ms per image | accuracy ratio per parameter |\n");
  std::printf("|---|---|---|---|\n");
  std::map<ModelId, std::pair<double, int>> total_ms;  // ms, images
  std::map<ModelId, double> worst_ratio;
  BenchFigures figures("render");
  figures.add("resolution", o.setup.resolution);
  auto wanted = [&](const AccuracySetting& s) {
    return o.model.empty() || o.model == model_info(s.model).name;
  };
  auto row = [&](const AccuracySetting& s) {
    const std::string name(model_info(s.model).name);
    const double ms = time_image(renderer, s, o.repeats);
    std::string ratios;
    if (o.accuracy) {
      // Also as the precompute renders it, in its grid, where that differs (Ward's one pass).
      std::vector<Image> images{renderer.specular(make_lobe(s.model, s.params))};
      if (grid_images_differ(s.model)) images.push_back(grid_image(renderer, s));
      const auto results = measure_accuracy(images, reference, s);
      ratios = ratio_cell(results[0]);
      for (const auto& r : results) worst_ratio[s.model] = max_ratio(r, worst_ratio[s.model]);
      if (results.size() > 1) ratios += " (in its grid: " + ratio_cell(results[1]) + ")";
    }
    std::printf("| %s | %s | %.1f | %s |\n", name.c_str(), s.name.c_str(), ms, ratios.c_str());
    std::fflush(stdout);
    return ms;
  };
  for (const AccuracySetting& s : accuracy_settings()) {
    if (!wanted(s)) continue;
    const double ms = row(s);
    total_ms[s.model].first += ms, ++total_ms[s.model].second;
  }
  if (o.anisotropic) {
    for (const AccuracySetting& s : anisotropic_settings())
      if (wanted(s)) row(s);
    if (wanted(sliver_setting())) row(sliver_setting());
  }
  fresnel_batch_rows(renderer, o.repeats, o.model, figures);
  if (o.model.empty() || o.model == "ward") ward_grid_rows(renderer, o.repeats, figures);
  std::printf("\n| model | mean ms per image (smooth, medium, rough) |\n|---|---|\n");
  for (const auto& [model, sum] : total_ms) {
    const std::string name(model_info(model).name);
    std::printf("| %s | %.1f |\n", name.c_str(), sum.first / sum.second);
    figures.add(name + "_alone_ms", sum.first / sum.second);
  }
  for (const auto& [model, ratio] : worst_ratio)
    figures.add(std::string(model_info(model).name) + "_max_ratio", ratio);
  figures.write(o.json);
}

}  // namespace brdfnav::cli
