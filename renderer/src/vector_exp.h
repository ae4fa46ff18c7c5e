// exp of every element of an array, a vector of them at a time where the CPU allows: the
// quadrature's Ward kernel exponentiates one value per node of its window (docs/RENDERER.md).
#pragma once

#include <Eigen/Core>

namespace brdfnav {

// values[i] = exp(values[i]). With AVX2 and FMA (checked at run time), through glibc's vector
// math library (libmvec, at most 4 ulp from the correctly rounded result), four at a time;
// otherwise std::exp. The same inputs on the same CPU give the same bits.
void exp_in_place(Eigen::Ref<Eigen::ArrayXd> values);

}  // namespace brdfnav
