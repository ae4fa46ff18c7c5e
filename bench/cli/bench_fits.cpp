// `brdfnav bench fits`: the model-to-model conversion fits (paper, section 4) timed.
#include "bench_fits.h"

#include "bench_figures.h"

#include <brdfnav/core/grid.h>
#include <brdfnav/core/models.h>
#include <brdfnav/precompute/fit.h>

#include <chrono>
#include <cstdio>

namespace brdfnav::cli {

// Fits of grid nodes of every model by every other model (default FitOptions, one thread): mean
// milliseconds per fit into each target model, and overall.
void run_fit_bench(int per_model, const std::string& json) {
  std::printf(
      "| target model | fits | mean ms per fit | mean relative error |\n|---|---|---|---|\n");
  double total_ms = 0;
  int total = 0;
  for (const ModelInfo& to : models()) {
    double ms = 0, error = 0;
    int count = 0;
    for (const ModelInfo& from : models()) {
      if (from.id == to.id) continue;
      const ParamGrid grid(from.params);
      for (int i = 0; i < per_model; ++i) {
        const std::size_t node = (i * 7919u + 13u) % grid.node_count();
        const Lobe target = make_lobe(from.id, grid.node_values(node));
        const auto start = std::chrono::steady_clock::now();
        const LobeFit fit = fit_lobe(target, to.id);
        ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                  .count();
        error += fit.relative_error;
        ++count;
      }
    }
    std::printf("| %s | %d | %.1f | %.3f |\n", std::string(to.name).c_str(), count, ms / count,
                error / count);
    total_ms += ms, total += count;
  }
  std::printf("\nall fits: %d, mean %.1f ms per fit (one thread)\n", total, total_ms / total);
  BenchFigures figures("fits");
  figures.add("mean_ms_per_fit", total_ms / total);
  figures.write(json);
}

}  // namespace brdfnav::cli
