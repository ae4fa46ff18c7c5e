// The series table behind he_detail::tabulated_series_sum (core/src/he_tables.cpp), per channel.
#pragma once

#include <brdfnav/core/math.h>

namespace brdfnav::he_detail {

// With log_g = ln(g), which the caller may have at hand for less than a log().
double tabulated_series_sum(double g, double log_g, double t);
// The three channels at once, equal to the above per channel to rounding: four lanes wide on CPUs
// with AVX2 and FMA (checked at run time) when all three are inside the table.
Rgb tabulated_series_sums(const Rgb& g, const Rgb& log_g, const Rgb& t);

}  // namespace brdfnav::he_detail
