// `brdfnav bench navigator` (app/bench_navigator.cpp).
#pragma once

#include <string>

namespace brdfnav::cli {

struct NavigatorBenchOptions {
  std::string db;
  double radius = 0.05;
  int materials = 40;  // random materials per model
  int thumbnail_size = 128;
};
void run_navigator_bench(const NavigatorBenchOptions& options);

}  // namespace brdfnav::cli
