// The series table behind he_detail::tabulated_series_sum (core/src/he_tables.cpp), per channel.
#pragma once

#include <brdfnav/core/math.h>

namespace brdfnav::he_detail {

// With log_g = ln(g), which the caller may have at hand for less than a log().
double tabulated_series_sum(double g, double log_g, double t);
// The three channels at once, equal to the above per channel to rounding: four lanes wide on CPUs
// with AVX2 and FMA (checked at run time) when all three are inside the table.
Rgb tabulated_series_sums(const Rgb& g, const Rgb& log_g, const Rgb& t);

// ln of the Poisson weight exp(-g) g^m / m! for integer m >= 1, with log_g = ln(g), at any m and
// g: to about 1e-16 (1 + |m - g|) absolute for m >= 20 (Stirling's series, no large terms that
// cancel), to the rounding of m ln g - g below.
double log_poisson(double m, double g, double log_g);

}  // namespace brdfnav::he_detail
