#include "bench_figures.h"

#include <brdfnav/core/atomic_file.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace brdfnav::cli {

void BenchFigures::write(const std::string& path) const {
  if (path.empty()) return;
  // Names are the benchmarks' own ASCII identifiers, so they need no escaping.
  std::string json = "{\"bench\": \"" + bench_ + "\", \"figures\": {";
  for (std::size_t i = 0; i < figures_.size(); ++i) {
    const auto& [name, value] = figures_[i];
    if (!std::isfinite(value))
      throw std::runtime_error(path + ": figure " + name + " is not a finite number");
    char number[32];
    std::snprintf(number, sizeof number, "%.6g", value);
    json += (i ? ", \"" : "\"") + name + "\": " + number;
  }
  json += "}}\n";
  write_file_atomic(path, json);
}

}  // namespace brdfnav::cli
