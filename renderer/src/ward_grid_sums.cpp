#include "ward_grid_sums.h"

#include "vector_exp.h"

#include <brdfnav/core/cpu.h>

#include <immintrin.h>

#include <algorithm>
#include <cmath>

namespace brdfnav::ward_grid {

namespace {

// Exponents below this are this: exp(-50) = 2e-22 adds nothing, and products of two factors stay
// clear of subnormal numbers, which are slow.
constexpr double kMinExponent = -50;
// Slopes squared and variances beyond this are this in single precision: their factors are 0.
constexpr double kHuge = 1e30;
// Factors below exp(-23) = 1e-10 are left out of the sums.
constexpr double kNegligibleExponent = -23;

// The first alpha whose exponent is not negligible: the exponents increase with alpha.
int first_not_negligible(const double* exponents, int alphas) {
  int first = alphas;
  while (first > 0 && exponents[first - 1] > kNegligibleExponent) --first;
  return first;
}

// With r = 1 / (1 + 2 v / alpha^2): the exponent -s^2 r / alpha^2 into out, sqrt(r) into scratch.
void exponents_plain(const Factors& f) {
  const int stride = padded(f.alphas);
  for (int k = 0; k < f.nodes; ++k) {
    const double s2 = f.slopes[k] * f.slopes[k], v2 = 2 * f.variances[k];
    double* exponent = f.out + std::size_t(k) * stride;
    double* spread = f.scratch + std::size_t(k) * stride;
    for (int i = 0; i < stride; ++i) {
      const double r = 1 / (1 + v2 * f.inv_alpha2[i]);
      exponent[i] = std::max(-s2 * f.inv_alpha2[i] * r, kMinExponent);
      spread[i] = std::sqrt(r);
    }
    f.first[k] = first_not_negligible(exponent, f.alphas);
  }
}

// The same in single precision, eight at a time: sqrt(r) from the reciprocal square root estimate
// and one Newton step (about 23 bits), r as its square.
__attribute__((target("avx2,fma"))) void exponents_avx2(const Factors& f) {
  const int stride = padded(f.alphas);
  const __m256 one = _mm256_set1_ps(1.f), half = _mm256_set1_ps(0.5f);
  const __m256 three_halves = _mm256_set1_ps(1.5f), floor = _mm256_set1_ps(float(kMinExponent));
  for (int k = 0; k < f.nodes; ++k) {
    // Clamped into float's range (slopes grow without bound toward a grazing horizon).
    const __m256 minus_s2 = _mm256_set1_ps(-float(std::min(f.slopes[k] * f.slopes[k], kHuge)));
    const __m256 v2 = _mm256_set1_ps(float(std::min(2 * f.variances[k], kHuge)));
    double* exponent = f.out + std::size_t(k) * stride;
    double* spread = f.scratch + std::size_t(k) * stride;
    for (int i = 0; i < stride; i += 8) {
      const __m256 inv_alpha2 = _mm256_loadu_ps(f.inv_alpha2 + i);
      const __m256 q = _mm256_fmadd_ps(v2, inv_alpha2, one);
      __m256 y = _mm256_rsqrt_ps(q);
      y = _mm256_mul_ps(
          y, _mm256_fnmadd_ps(_mm256_mul_ps(half, q), _mm256_mul_ps(y, y), three_halves));
      const __m256 e = _mm256_max_ps(
          _mm256_mul_ps(_mm256_mul_ps(minus_s2, inv_alpha2), _mm256_mul_ps(y, y)), floor);
      _mm256_storeu_pd(exponent + i, _mm256_cvtps_pd(_mm256_castps256_ps128(e)));
      _mm256_storeu_pd(exponent + i + 4, _mm256_cvtps_pd(_mm256_extractf128_ps(e, 1)));
      _mm256_storeu_pd(spread + i, _mm256_cvtps_pd(_mm256_castps256_ps128(y)));
      _mm256_storeu_pd(spread + i + 4, _mm256_cvtps_pd(_mm256_extractf128_ps(y, 1)));
    }
    f.first[k] = first_not_negligible(exponent, f.alphas);
  }
}

void accumulate_plain(const Products& p) {
  const int stride_x = padded(p.nx), stride_y = padded(p.ny);
  for (int k = 0; k < p.nodes; ++k) {
    const double* gx = p.gx + std::size_t(k) * stride_x;
    const double* gy = p.gy + std::size_t(k) * stride_y;
    for (int c = 0; c < 3; ++c) {
      const double w = p.weight[c][k];
      for (int i = p.first_x[k]; i < p.nx; ++i) {
        const double a = w * gx[i];
        double* row = p.sums + std::size_t((c * p.nx + i) * stride_y);
        for (int j = p.first_y[k]; j < p.ny; ++j) row[j] += a * gy[j];
      }
    }
  }
}

// Four products at a time from the multiple of four at or below first_y through the padding: the
// few extra terms are negligible (or padding, never read). The three channels share each load of
// gy.
__attribute__((target("avx2,fma"))) void accumulate_avx2(const Products& p) {
  const int stride_x = padded(p.nx), stride_y = padded(p.ny);
  const std::size_t channel = std::size_t(p.nx) * stride_y;
  for (int k = 0; k < p.nodes; ++k) {
    const double* gx = p.gx + std::size_t(k) * stride_x;
    const double* gy = p.gy + std::size_t(k) * stride_y;
    const int j0 = p.first_y[k] / 4 * 4;
    const __m256d w0 = _mm256_set1_pd(p.weight[0][k]), w1 = _mm256_set1_pd(p.weight[1][k]),
                  w2 = _mm256_set1_pd(p.weight[2][k]);
    for (int i = p.first_x[k]; i < p.nx; ++i) {
      const __m256d g = _mm256_set1_pd(gx[i]);
      const __m256d a0 = _mm256_mul_pd(w0, g), a1 = _mm256_mul_pd(w1, g), a2 = _mm256_mul_pd(w2, g);
      double* r0 = p.sums + std::size_t(i) * stride_y;
      double* r1 = r0 + channel;
      double* r2 = r1 + channel;
      for (int j = j0; j < stride_y; j += 4) {
        const __m256d y = _mm256_loadu_pd(gy + j);
        _mm256_storeu_pd(r0 + j, _mm256_fmadd_pd(a0, y, _mm256_loadu_pd(r0 + j)));
        _mm256_storeu_pd(r1 + j, _mm256_fmadd_pd(a1, y, _mm256_loadu_pd(r1 + j)));
        _mm256_storeu_pd(r2 + j, _mm256_fmadd_pd(a2, y, _mm256_loadu_pd(r2 + j)));
      }
    }
  }
}

}  // namespace

void gaussian_factors(const Factors& f) {
  static const bool avx2 = cpu_has_avx2_fma();
  avx2 ? exponents_avx2(f) : exponents_plain(f);
  const Eigen::Index size = Eigen::Index(f.nodes) * padded(f.alphas);
  Eigen::Map<Eigen::ArrayXd> out(f.out, size);
  exp_in_place(out);
  out *= Eigen::Map<const Eigen::ArrayXd>(f.scratch, size);
}

void accumulate(const Products& p) {
  static const bool avx2 = cpu_has_avx2_fma();
  avx2 ? accumulate_avx2(p) : accumulate_plain(p);
}

}  // namespace brdfnav::ward_grid
