// `brdfnav bench navigator`: the neighbour service's latency per tab, a tab's thumbnails through
// OCIO, and the resident memory with a database open (the navigator's targets), on this machine.
#include "bench_navigator.h"

#include "bench_figures.h"

#include <brdfnav/core/statistics.h>
#include <brdfnav/navigator/navigator.h>
#include <brdfnav/navigator/thumbnails.h>
#include <brdfnav/ocio/color_pipeline.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

namespace brdfnav::cli {

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

// Resident set size of this process in MiB (Linux /proc), or -1.
double resident_mib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return -1;
}

// Random materials of every model of the database: parameters uniform in each axis's scale.
std::vector<Material> random_materials(const Database& db, int per_model) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Material> out;
  for (const ProfileGrid& g : db.manifest().grids)
    for (int i = 0; i < per_model; ++i) {
      Material m = default_material(g.model);
      for (std::size_t d = 0; d < g.grid.dimensions(); ++d) {
        const ParamSpec& s = g.grid.specs()[d];
        const double lo = to_scale(s, g.grid.axis(d).front()),
                     hi = to_scale(s, g.grid.axis(d).back());
        m.params[d] = from_scale(s, lo + unit(rng) * (hi - lo));
      }
      m.rho_d = Rgb(unit(rng), unit(rng), unit(rng)) * 0.5;
      m.rho_s = Rgb(unit(rng), unit(rng), unit(rng)) * 0.8 + 0.05;
      out.push_back(m);
    }
  return out;
}

namespace {

struct Percentiles {
  double median, p99, max;
};
Percentiles percentiles(const std::vector<double>& ms) {
  return {quantile(ms, 0.5), quantile(ms, 0.99), quantile(ms, 1.0)};
}

}  // namespace

void run_navigator_bench(const NavigatorBenchOptions& o) {
  const double before = resident_mib();
  const auto start = Clock::now();
  const Navigator navigator = Navigator::open(o.db);
  BenchFigures figures("navigator");
  figures.add("rss_before_open_mib", before);
  figures.add("rss_open_mib", resident_mib());
  std::printf(
      "database %s (profile %s, %d x %d): opened in %.0f ms, resident memory %.1f MiB "
      "(%.1f MiB before opening)\n\n",
      o.db.c_str(), navigator.database().manifest().profile.c_str(),
      navigator.database().manifest().resolution, navigator.database().manifest().resolution,
      ms_since(start), resident_mib(), before);
  const std::vector<Material> materials = random_materials(navigator.database(), o.materials);
  std::printf("| tab | queries | median ms | p99 ms | max ms |\n|---|---|---|---|---|\n");
  for (Tab tab : kTabs) {
    std::vector<double> ms;
    for (const Material& m : materials) {
      const auto t = Clock::now();
      navigator.neighbors(m, o.radius, tab);
      ms.push_back(ms_since(t));
    }
    const Percentiles p = percentiles(ms);
    figures.add(std::string(tab_name(tab)) + "_p99_ms", p.p99);
    std::printf("| %s | %zu | %.3f | %.3f | %.3f |\n", std::string(tab_name(tab)).c_str(),
                ms.size(), p.median, p.p99, p.max);
  }
  const Thumbnails thumbnails(navigator.database(), o.thumbnail_size,
                              std::size_t(o.cache_mib) << 20);
  const ocio::ColorPipeline pipeline;
  const std::string display = pipeline.default_display(), view = pipeline.default_view(display);
  std::vector<double> cold, warm;
  for (const Material& m : materials) {
    const std::vector<Neighbor> tab = navigator.neighbors(m, o.radius, Tab::lobe);
    for (std::vector<double>* run : {&cold, &warm}) {
      const auto t = Clock::now();
      for (const Neighbor& n : tab) {
        const Image img = thumbnails.render(n.material);
        pipeline.apply(img.rgba.data(), img.width, img.height, display, view);
      }
      run->push_back(ms_since(t) * 10.0 / std::max<std::size_t>(tab.size(), 1));
    }
  }
  const Percentiles c = percentiles(cold), w = percentiles(warm);
  figures.add("thumbnails_first_p99_ms", c.p99);
  figures.add("thumbnails_cached_p99_ms", w.p99);
  figures.add("rss_after_mib", resident_mib());
  std::printf(
      "\n10 thumbnails at %d x %d through OCIO (%s / %s), per lobe tab scaled to 10, image cache "
      "%d MiB:\n"
      "first view (images read from disk): median %.1f ms, p99 %.1f ms; again (cached): "
      "median %.1f ms, p99 %.1f ms\nresident memory after: %.1f MiB\n",
      o.thumbnail_size, o.thumbnail_size, display.c_str(), view.c_str(), o.cache_mib, c.median,
      c.p99, w.median, w.p99, resident_mib());
  figures.write(o.json);
}

}  // namespace brdfnav::cli
