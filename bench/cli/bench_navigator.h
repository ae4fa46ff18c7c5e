// `brdfnav bench navigator` (bench/cli/bench_navigator.cpp).
#pragma once

#include <brdfnav/core/material.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/navigator/thumbnails.h>

#include <string>
#include <vector>

namespace brdfnav::cli {

struct NavigatorBenchOptions {
  std::string db;
  double radius = 0.05;
  int materials = 40;  // random materials per model
  int thumbnail_size = 128;
  int cache_mib = int(Thumbnails::kDefaultCacheBytes >> 20);
  std::string json;  // where to write the figures (BenchFigures), if anywhere
};
void run_navigator_bench(const NavigatorBenchOptions& options);

// What `brdfnav bench load` shares with it:
// resident set size of this process in MiB (Linux /proc), or -1;
double resident_mib();
// random materials of every model of the database, parameters uniform in each axis's scale.
std::vector<Material> random_materials(const Database& db, int per_model);

}  // namespace brdfnav::cli
