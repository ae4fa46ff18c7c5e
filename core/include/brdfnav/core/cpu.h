// What the CPU running us can do, for the few loops that take a vector path when it can (checked
// at run time: the build targets plain x86-64).
#pragma once

namespace brdfnav {

// AVX2 and FMA: four doubles per instruction, and glibc's 4-lane vector math functions.
inline bool cpu_has_avx2_fma() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

}  // namespace brdfnav
