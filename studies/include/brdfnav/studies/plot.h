// Line plots written as PNG with OpenImageIO's drawing primitives: axes with tick labels, a
// title, axis labels and a legend; and labelled strips of images. Used by `brdfnav demo` and the
// validation report.
#pragma once

#include <brdfnav/ocio/contact_sheet.h>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace brdfnav {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
  std::array<float, 3> color;
  bool markers = false;  // a dot at every point (sparse series)
};

struct PlotSpec {
  std::string title, x_label, y_label;
  bool log_y = false;  // log10 axis; non-positive values are left out
  int width = 1100, height = 600;
};

// Ten distinct line colours (Tableau 10), indexed modulo their count.
std::array<float, 3> plot_color(std::size_t index);

// Writes the plot atomically; throws std::runtime_error naming the file on failure.
void write_line_plot(const std::filesystem::path& png, const PlotSpec& spec,
                     const std::vector<PlotSeries>& series);

struct StripTile {
  ocio::Thumbnail image;  // display-encoded (ColorPipeline::apply)
  std::string label;
};

struct StripSize {
  int width = 0, height = 0;
};

// The tiles side by side under a title, each with its label centred below it, on a dark grey
// sheet (as the paper's Figures 8 and 9). Every cell is as wide as the widest tile or label.
// Written atomically as PNG; throws std::runtime_error naming the file on failure.
StripSize write_image_strip(const std::filesystem::path& png, const std::string& title,
                            const std::vector<StripTile>& tiles);

}  // namespace brdfnav
