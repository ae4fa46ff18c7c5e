// Line plots written as PNG with OpenImageIO's drawing primitives: axes with tick labels, a
// title, axis labels and a legend. Used by `brdfnav demo` and the validation report.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace brdfnav::cli {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
  std::array<float, 3> color;
};

struct PlotSpec {
  std::string title, x_label, y_label;
  bool log_y = false;  // log10 axis; non-positive values are left out
  int width = 1100, height = 600;
};

// Ten distinct line colours (Tableau 10), indexed modulo their count.
std::array<float, 3> plot_colour(std::size_t index);

// Writes the plot atomically; throws std::runtime_error naming the file on failure.
void write_line_plot(const std::filesystem::path& png, const PlotSpec& spec,
                     const std::vector<PlotSeries>& series);

}  // namespace brdfnav::cli
