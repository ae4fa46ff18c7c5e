// Per-call cost of Closure::eval, pdf and sample for each model at its default (medium)
// parameters, over pre-generated inputs so that random-number generation is not measured.
// Targets (single thread; bench/results.py holds them, the table of bench/RESULTS.md shows the
// figures): eval <= 50 ns for every model but He, <= 1 us for He.
#include <benchmark/benchmark.h>
#include <brdfnav/core/material.h>

#include <random>
#include <utility>
#include <vector>

namespace brdfnav {
namespace {

// A power of two, so the index wraps with a mask; small enough to stay in L1/L2.
constexpr std::size_t kInputs = 4096;

struct Inputs {
  std::vector<Vec3> wi, wo;
  std::vector<double> uc;
  std::vector<Vec2> u;
};

// The model's default material, or with `params` in place of its default parameters.
Closure default_closure(ModelId id, std::vector<double> params = {}) {
  Material m = default_material(id);
  if (!params.empty()) m.params = std::move(params);
  m.rho_d = Rgb(0.2, 0.15, 0.1);
  m.rho_s = Rgb::Constant(0.5);
  return make_closure(m);
}

// wo cosine-distributed, as a camera ray sees a surface; wi half from the closure's own sampler
// (directions inside the lobe, where the costly branches run) and half uniform over the
// hemisphere (light samples), so neither the fast zero paths nor the lobe peak dominate.
Inputs make_inputs(const Closure& closure) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const auto u2 = [&] {
    const double u0 = uniform(rng), u1 = uniform(rng);
    return Vec2(u0, u1);
  };
  Inputs in;
  while (in.wo.size() < kInputs) {
    const Vec3 wo = sample_cosine_hemisphere(u2());
    if (wo.z() <= 1e-3) continue;
    Vec3 wi = sample_cos_power(u2(), 0.0);  // uniform over the hemisphere
    if (in.wo.size() % 2 == 0) {
      const double uc = uniform(rng);
      const auto s = closure.sample(wo, uc, u2());
      if (!s) continue;
      wi = s->wi;
    }
    in.wo.push_back(wo);
    in.wi.push_back(wi);
    in.uc.push_back(uniform(rng));
    in.u.push_back(u2());
  }
  return in;
}

void BM_Eval(benchmark::State& state, ModelId id, std::vector<double> params = {}) {
  const Closure closure = default_closure(id, std::move(params));
  const Inputs in = make_inputs(closure);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(closure.eval(in.wi[i], in.wo[i]));
    i = (i + 1) & (kInputs - 1);
  }
}

void BM_Pdf(benchmark::State& state, ModelId id) {
  const Closure closure = default_closure(id);
  const Inputs in = make_inputs(closure);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(closure.pdf(in.wi[i], in.wo[i]));
    i = (i + 1) & (kInputs - 1);
  }
}

void BM_Sample(benchmark::State& state, ModelId id) {
  const Closure closure = default_closure(id);
  const Inputs in = make_inputs(closure);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(closure.sample(in.wo[i], in.uc[i], in.u[i]));
    i = (i + 1) & (kInputs - 1);
  }
}

#define BRDFNAV_BENCH_MODEL(model)                   \
  BENCHMARK_CAPTURE(BM_Eval, model, ModelId::model); \
  BENCHMARK_CAPTURE(BM_Pdf, model, ModelId::model);  \
  BENCHMARK_CAPTURE(BM_Sample, model, ModelId::model)

BRDFNAV_BENCH_MODEL(blinn_phong);
BRDFNAV_BENCH_MODEL(ward);
BRDFNAV_BENCH_MODEL(cook_torrance);
BRDFNAV_BENCH_MODEL(lafortune);
BRDFNAV_BENCH_MODEL(he);
BRDFNAV_BENCH_MODEL(ggx);
// He's eval at the renderer's smooth, medium and rough settings (accuracy_settings()): g at the
// mirror from below 1 (smooth, grazing) to about 1800 (rough, blue, normal incidence).
BENCHMARK_CAPTURE(BM_Eval, he_smooth, ModelId::he, std::vector<double>{0.1, 10, 1.5});
BENCHMARK_CAPTURE(BM_Eval, he_medium, ModelId::he, std::vector<double>{0.3, 8, 2});
BENCHMARK_CAPTURE(BM_Eval, he_rough, ModelId::he, std::vector<double>{1.5, 4, 4});

}  // namespace
}  // namespace brdfnav
