#pragma once
// Labelled contact sheets in the manner of Photoshop's Variations: the current material in the
// centre, highlighted (and larger once there are more than 8 variations), its variations on a
// ring around it, each tile with label lines under it. Written as PNG with OpenImageIO
// (brdfnav::contact_sheet; the colour pipeline alone is brdfnav::ocio).

#include <brdfnav/core/error.h>
#include <brdfnav/ocio/color_pipeline.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace brdfnav::ocio {

// A bad tile, a missing font, or a sheet that could not be written (the message names the file).
using ContactSheetError = LayerError<struct ContactSheetErrorTag, ErrorCode::io>;

struct SheetTile {
  // A display-encoded thumbnail (color_pipeline.h). Only RGB is drawn: the pipeline has already
  // composited uncovered pixels over its background.
  Thumbnail image;
  std::vector<std::string> label;  // lines under the image, e.g. {"alpha_x+", "d=0.050"}
};

struct SheetOptions {
  int tile_size = 128;  // a variation's image is fitted into tile_size x tile_size (aspect kept)
  int gap = 12;         // pixels around and between cells; at least 5 (the highlight frame)
  int font_size = 13;   // pixels
  std::string font = "DejaVuSans";  // an OIIO font name or a .ttf path
  std::string title;                // an optional line above the grid
};

// Where the tiles go, in cells of a square grid `side` cells wide. cells[0] is the centre, a
// span x span block; cells[1 + i] is variation i, one cell on the ring around the centre. The
// centre spans the smallest k >= 1 whose ring (4k + 4 cells) holds all n variations, so 8 give a
// 3x3 grid, 9 to 12 a 4x4 grid with a 2x2 centre. The ring is walked clockwise from the top-left
// corner and variation i takes ring cell floor(i * ring / n): the variations spread evenly, and
// for even n variations i and i + n/2 sit opposite each other across the centre, so ordering
// them a+, b+, ..., a-, b-, ... puts each -/+ pair on one line through the current material.
struct GridCell {
  int col = 0;
  int row = 0;
  int span = 1;
};
struct VariationGrid {
  int side = 1;
  std::vector<GridCell> cells;
};
VariationGrid variation_grid(int variations);

// The sheet's geometry, with g = gap, L = font_size + font_size / 3 (the line height), lines =
// the most label lines of any tile, cell_w = max(tile_size, widest label), cell_h = tile_size +
// (lines > 0 ? 6 + lines * L : 0): width = side * cell_w + (side + 1) * g, height = side * cell_h
// + (side + 1) * g, plus L + g with a title (which is not wrapped: a long one is cut at the
// sheet's edge). Background dark grey; the centre's image is framed in orange.
struct SheetSize {
  int width = 0;
  int height = 0;
};

// Writes the sheet to `path`, which must end in .png, as PNG through a temporary file in the
// same directory that is then renamed over `path`: on any failure no file is left (the previous
// one, if any, is untouched) and ContactSheetError names `path`.
SheetSize write_contact_sheet(const std::string& path, const SheetTile& centre,
                              const std::vector<SheetTile>& variations,
                              const SheetOptions& options = {});

}  // namespace brdfnav::ocio
