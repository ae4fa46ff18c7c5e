// The series table behind he_detail::tabulated_series_sum (core/src/he_tables.cpp), per channel.
#pragma once

namespace brdfnav::he_detail {

double tabulated_series_sum(double g, double t);

}  // namespace brdfnav::he_detail
