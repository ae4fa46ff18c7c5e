// `brdfnav bench fidelity`: renders what the navigator offers exactly, with the database's own
// renderer settings (map, scene, resolution, quality), and compares
// - each final image the server would show (the centre and every offer: lookdev::FinalImages, the
// blend
//   where the database's blend check vouches for it, else the render) with the exact render of
//   its material: the targets are 0.05 eps (median) and 0.25 eps (worst); and the previews (every
//   image a blend) alike, for comparison;
// - each offer's exact distance from the current material with eps, per tab: the targets are
//   5% (median) and 10% (90th percentile) of |rendered / eps - 1|. Offers flagged at a grid end,
//   at a colour limit or beyond the radius do not aim at eps and are counted apart.
#include "bench_fidelity.h"

#include <brdfnav/lookdev/exact_thumbnails.h>
#include <brdfnav/lookdev/final_images.h>
#include "bench_figures.h"
#include "bench_navigator.h"

#include <brdfnav/core/statistics.h>
#include <brdfnav/navigator/navigator.h>
#include <brdfnav/navigator/thumbnails.h>
#include <brdfnav/precompute/database.h>
#include <brdfnav/renderer/render.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace brdfnav::cli {

namespace {

struct Errors {
  std::vector<double> values;
  int flagged = 0;
};

const char* verdict(bool met) {
  return met ? "met" : "NOT met";
}

void print_steps(const std::string& model, Tab tab, const Errors& e, BenchFigures& figures) {
  if (e.values.empty()) {
    std::printf("| %s | %s | 0 | - | - | %d | - |\n", model.c_str(),
                std::string(tab_name(tab)).c_str(), e.flagged);
    return;
  }
  const double median = quantile(e.values, 0.5), p90 = quantile(e.values, 0.9);
  const std::string key = model + "_" + std::string(tab_name(tab));
  figures.add(key + "_step_median", median);
  figures.add(key + "_step_p90", p90);
  std::printf("| %s | %s | %zu | %.1f%% | %.1f%% | %d | %s |\n", model.c_str(),
              std::string(tab_name(tab)).c_str(), e.values.size(), 100 * median, 100 * p90,
              e.flagged, verdict(median <= 0.05 && p90 <= 0.10));
}

}  // namespace

void run_fidelity_bench(const FidelityBenchOptions& o) {
  const Navigator navigator = Navigator::open(o.db);
  const Database& db = navigator.database();
  const Manifest& manifest = db.manifest();
  // Exact renders with the database's map, scene, resolution and quality: what the server's
  // exact thumbnails and steps render.
  const lookdev::ExactThumbnails renders(db, manifest.resolution);
  const Thumbnails thumbnails(db, manifest.resolution);
  const lookdev::FinalImages finals(thumbnails, renders);
  const Tab tabs[] = {Tab::lobe, Tab::diffuse, Tab::specular, Tab::models};

  // Per model, in eps: the previews' and the final images' distances from the exact renders.
  std::map<std::string, std::vector<double>> preview_errors, final_errors;
  std::map<std::string, int> blends;  // final images that are blends, per model
  std::map<std::pair<std::string, Tab>, Errors> steps;
  const auto exact = [&](const Material& m) {
    const std::string model(model_info(m.model).name);
    const std::shared_ptr<const Image> image = renders.render(m);
    preview_errors[model].push_back(image_distance(*image, thumbnails.render(m)) / o.radius);
    final_errors[model].push_back(image_distance(*image, *finals.image(m, manifest.resolution)) /
                                  o.radius);
    blends[model] += finals.shows_blend(m, manifest.resolution);
    return image;
  };
  for (const Material& m : random_materials(db, o.materials)) {
    const std::string model(model_info(m.model).name);
    const std::shared_ptr<const Image> current = exact(m);
    // The server's exact steps: measured on the final images.
    const ExactSteps moved = finals.steps_from(m, o.radius);
    for (Tab tab : tabs) {
      Errors& e = steps[{model, tab}];
      for (const Neighbor& n :
           navigator.neighbors(m, o.radius, tab, 8, o.exact ? &moved : nullptr)) {
        const double rendered = image_distance(*current, *exact(n.material));
        if (n.at_boundary || n.clamped || n.beyond_radius)
          ++e.flagged;
        else
          e.values.push_back(std::abs(rendered / o.radius - 1));
      }
    }
    std::fprintf(stderr, "brdfnav: bench fidelity: %s done\n", model.c_str());
  }

  std::printf("database %s (profile %s, %d px), eps %.4g, %d random materials per model, %s\n\n",
              o.db.c_str(), manifest.profile.c_str(), manifest.resolution, o.radius, o.materials,
              o.exact ? "steps moved to eps by rendering (--exact)" : "steps from the embedding");
  std::printf(
      "Final images (blends where the database vouches for them, else renders) and previews "
      "(every image a blend) against exact renders (in eps; targets 0.05 median, 0.25 worst)\n\n");
  BenchFigures figures(o.exact ? "fidelity_exact" : "fidelity");
  std::printf(
      "| model | images | blends | final median | worst | verdict | preview median | worst |\n"
      "|---|---:|---:|---:|---:|---|---:|---:|\n");
  for (const auto& [model, errors] : final_errors) {
    const double median = quantile(errors, 0.5), worst = quantile(errors, 1.0);
    const std::vector<double>& preview = preview_errors[model];
    figures.add(model + "_final_median_eps", median);
    figures.add(model + "_final_worst_eps", worst);
    figures.add(model + "_final_blends", blends[model]);
    figures.add(model + "_thumbnail_median_eps", quantile(preview, 0.5));
    figures.add(model + "_thumbnail_worst_eps", quantile(preview, 1.0));
    std::printf("| %s | %zu | %d | %.3f | %.3f | %s | %.3f | %.3f |\n", model.c_str(),
                errors.size(), blends[model], median, worst,
                verdict(median <= 0.05 && worst <= 0.25), quantile(preview, 0.5),
                quantile(preview, 1.0));
  }
  std::printf(
      "\nSteps: |rendered / eps - 1| of the unflagged offers (targets 5%% median, 10%% "
      "90th percentile)\n\n");
  std::printf("| model | tab | offers | median | p90 | flagged | verdict |\n");
  std::printf("|---|---|---:|---:|---:|---:|---|\n");
  for (const auto& [key, errors] : steps) print_steps(key.first, key.second, errors, figures);
  figures.write(o.json);
}

}  // namespace brdfnav::cli
