// `brdfnav bench fits` (bench/cli/bench_fits.cpp).
#pragma once

#include <string>

namespace brdfnav::cli {

// Fits of `per_model` grid nodes of every model by every other model (default FitOptions, one
// thread), as a Markdown table; with `json`, the mean ms per fit (bench_figures.h).
void run_fit_bench(int per_model, const std::string& json);

}  // namespace brdfnav::cli
