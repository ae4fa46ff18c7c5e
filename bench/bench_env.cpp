// The renderer's setup on a large environment map: reading nothing from disk, a Renderer over an
// in-memory map builds the environment pyramid (renderer/src/env_pyramid.h, one thread) and
// traces an 8 x 8 camera, so the time is the pyramid's. For a 1024 x 512 map (Blender's studio
// lights) and a 4096 x 2048 one (a production HDRI).
// No target of its own; figures in docs/RENDERER.md, Speed.
#include <benchmark/benchmark.h>
#include <brdfnav/renderer/render.h>

#include <cmath>

namespace brdfnav {
namespace {

// A sky of smooth gradients with a few lamps far brighter than the mean, as interior.exr has.
EnvMap synthetic_map(int width) {
  const int height = width / 2;
  std::vector<float> rgb(3 * std::size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* p = &rgb[3 * (std::size_t(y) * width + x)];
      const float u = float(x) / width, v = float(y) / height;
      p[0] = 0.5f + 0.4f * std::sin(7 * u) * v;
      p[1] = 0.6f + 0.3f * std::cos(5 * v);
      p[2] = 0.8f - 0.5f * v;
      if ((x / 16) % 37 == 3 && (y / 16) % 23 == 5) p[0] = p[1] = p[2] = 3e4f;
    }
  return EnvMap(width, height, std::move(rgb), "synthetic");
}

void BM_RendererSetup(benchmark::State& state) {
  const EnvMap env = synthetic_map(int(state.range(0)));
  const Scene sphere = Scene::sphere();
  for (auto _ : state) {
    Renderer renderer(env, sphere, 8);
    benchmark::DoNotOptimize(renderer.resolution());
  }
}
BENCHMARK(BM_RendererSetup)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace brdfnav
