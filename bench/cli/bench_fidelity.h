// `brdfnav bench fidelity` (bench/cli/bench_fidelity.cpp): what the artist sees against exact
// renders.
#pragma once

#include <string>

namespace brdfnav::cli {

struct FidelityBenchOptions {
  std::string db;
  double radius = 0.03;  // eps of the steps; the thumbnails' errors are given in eps too
  int materials = 4;     // random materials per model
  bool exact = false;    // the offers moved to eps by rendering (ExactSteps), as serve does
  std::string json;      // where to write the figures (BenchFigures), if anywhere
};
// Per model: the thumbnails' distance to an exact render of their material (median and worst, in
// eps), and per tab the offers' exact rendered distance from the current material against eps
// (median and 90th percentile of |rendered / eps - 1|), with the targets' verdicts.
void run_fidelity_bench(const FidelityBenchOptions& options);

}  // namespace brdfnav::cli
