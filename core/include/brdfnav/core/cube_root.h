// cube_root(): x^(1/3) of floats, for the cube-root images of the metric in bulk (the embedding's
// passes over every image, the thumbnails' blends). libm's cbrtf is a call per value that no loop
// vectorises, and cost as much as the embedding's matrix products.
#pragma once

#include <cstdint>
#include <cstring>

namespace brdfnav {

// x^(1/3) for finite x >= 0 to within 2 ulp of std::cbrt (tests/core/test_cube_root): a first
// guess from the bits (the exponent divided by 3, within 4%) and three Newton steps, each squaring
// the error. Subnormal x is scaled by 2^24 first so that its guess is as good. x <= 0 gives 0,
// infinity and NaN give NaN. Inline and free of branches, so that loops over it vectorise: its
// tests are on the bits, and its choices are products, because GCC keeps a choice between float
// operations a branch (either might trap).
inline float cube_root(float x) {
  std::int32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits &= ~(bits >> 31);  // negative x -> +0
  // 0 or 1 each: x is subnormal or 0, x is positive.
  const std::int32_t tiny = (bits < 0x00800000), positive = (bits > 0);
  std::memcpy(&x, &bits, sizeof bits);
  const float scaled = x * (1.f + float(tiny) * (0x1p24f - 1.f));
  std::memcpy(&bits, &scaled, sizeof bits);
  bits = std::int32_t(float(bits) * (1.f / 3.f)) + 0x2a5137a0;
  float y;
  std::memcpy(&y, &bits, sizeof y);
  for (int k = 0; k < 3; ++k) y = (2.f * y + scaled / (y * y)) * (1.f / 3.f);
  return y * (1.f - float(tiny) * (1.f - 0x1p-8f)) * float(positive);
}

}  // namespace brdfnav
