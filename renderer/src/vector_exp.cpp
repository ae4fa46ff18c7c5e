#include "vector_exp.h"

#include <brdfnav/core/cpu.h>

#include <immintrin.h>

#include <cmath>

// glibc's 4-lane AVX2 exp (the x86-64 vector function ABI name of exp, variant 'd': AVX2). Its
// arguments travel in AVX registers, so the declaration carries the target too (clang insists).
extern "C" __attribute__((target("avx2"))) __m256d _ZGVdN4v_exp(__m256d x);

namespace brdfnav {

namespace {

__attribute__((target("avx2,fma"))) void exp_avx2(double* v, Eigen::Index n) {
  Eigen::Index i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(v + i, _ZGVdN4v_exp(_mm256_loadu_pd(v + i)));
  for (; i < n; ++i) v[i] = std::exp(v[i]);
}

}  // namespace

void exp_in_place(Eigen::Ref<Eigen::ArrayXd> values) {
  static const bool avx2 = cpu_has_avx2_fma();
  if (avx2) return exp_avx2(values.data(), values.size());
  for (double& v : values) v = std::exp(v);
}

}  // namespace brdfnav
