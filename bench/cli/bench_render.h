// `brdfnav bench render` (bench/cli/bench_render.cpp): each model's smooth, medium and rough
// setting rendered alone, the Fresnel batches and Ward's grid, against the reference quality.
#pragma once

#include <brdfnav/renderer/render_setup.h>

#include <string>

namespace brdfnav::cli {

struct RenderBenchOptions {
  RenderSetup setup;
  std::string model;  // empty: all
  int repeats = 3;
  bool accuracy = true;
  bool anisotropic = false;
  std::string json;  // where to write the figures, if anywhere
};
void run_render_bench(const RenderBenchOptions& options);

}  // namespace brdfnav::cli
