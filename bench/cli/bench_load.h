// `brdfnav bench load` (bench/cli/bench_load.cpp).
#pragma once

#include <string>

namespace brdfnav::cli {

struct LoadBenchOptions {
  std::string db;
  int threads = 8;
  int queries = 100000;  // per thread
};
// Throws std::runtime_error when a concurrent answer differs from the serial one.
void run_load_bench(const LoadBenchOptions& options);

}  // namespace brdfnav::cli
