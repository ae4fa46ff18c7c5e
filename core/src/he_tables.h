// The series table behind he_detail::tabulated_series_sum (core/src/he_tables.cpp), per channel.
#pragma once

namespace brdfnav::he_detail {

// With log_g = ln(g), which the caller may have at hand for less than a log().
double tabulated_series_sum(double g, double log_g, double t);

}  // namespace brdfnav::he_detail
