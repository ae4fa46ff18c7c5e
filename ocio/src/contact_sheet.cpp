#include <brdfnav/ocio/contact_sheet.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace brdfnav::ocio {

namespace {

namespace fs = std::filesystem;
namespace IBA = OIIO::ImageBufAlgo;

// Display-encoded sheet colours: a dark neutral surround (so the mid-grey tile backgrounds read
// as tiles), light text, an orange frame for the current material.
constexpr float kSheetGrey[3] = {0.16f, 0.16f, 0.16f};
constexpr float kTextColor[3] = {0.88f, 0.88f, 0.88f};
constexpr float kHighlight[3] = {1.0f, 0.62f, 0.1f};
constexpr int kFrameOffset = 2;  // the frame's inner edge, pixels outside the image
constexpr int kFrameWidth = 3;
constexpr int kLabelPad = kFrameOffset + kFrameWidth + 1;  // image bottom to first label line

// Cell (col, row) of the ring around a k x k centre, clockwise from the top-left corner.
GridCell ring_cell(int index, int side) {
  const int edge = side - 1;
  if (index < edge) return {index, 0, 1};
  if (index < 2 * edge) return {edge, index - edge, 1};
  if (index < 3 * edge) return {edge - (index - 2 * edge), edge, 1};
  return {0, edge - (index - 3 * edge), 1};
}

struct Geometry {
  int gap = 0, line = 0, lines = 0, label_h = 0, cell_w = 0, cell_h = 0, title_h = 0;
  VariationGrid grid;

  int x(int col) const { return gap + col * (cell_w + gap); }
  int y(int row) const { return title_h + gap + row * (cell_h + gap); }
  int block_w(int span) const { return span * cell_w + (span - 1) * gap; }
  int block_h(int span) const { return span * cell_h + (span - 1) * gap; }
  SheetSize size() const { return {x(grid.side), y(grid.side)}; }
};

int text_width(const std::string& text, const SheetOptions& options) {
  if (text.empty()) return 0;
  const OIIO::ROI box = IBA::text_size(text, options.font_size, options.font);
  if (!box.defined())
    throw ContactSheetError("font '" + options.font +
                            "' not found (install fonts-dejavu-core, or give a .ttf path)");
  return box.width();
}

Geometry layout(const std::vector<const SheetTile*>& tiles, const SheetOptions& options) {
  Geometry g;
  g.gap = options.gap;
  g.line = options.font_size + options.font_size / 3;
  g.cell_w = options.tile_size;
  for (const SheetTile* tile : tiles) {
    g.lines = std::max(g.lines, static_cast<int>(tile->label.size()));
    for (const auto& text : tile->label) g.cell_w = std::max(g.cell_w, text_width(text, options));
  }
  if (g.lines > 0) g.label_h = kLabelPad + g.lines * g.line;
  g.cell_h = options.tile_size + g.label_h;
  if (!options.title.empty()) g.title_h = g.line + g.gap;
  g.grid = variation_grid(static_cast<int>(tiles.size()) - 1);
  return g;
}

void check_input(const std::vector<const SheetTile*>& tiles, const SheetOptions& options) {
  if (options.tile_size < 1 || options.font_size < 1 || options.gap < kFrameOffset + kFrameWidth)
    throw ContactSheetError(
        "contact sheet: tile_size and font_size must be positive and gap at "
        "least " +
        std::to_string(kFrameOffset + kFrameWidth));
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const Thumbnail& t = tiles[i]->image;
    const auto expected = 4 * static_cast<std::size_t>(std::max(t.width, 0)) *
                          static_cast<std::size_t>(std::max(t.height, 0));
    if (t.width < 1 || t.height < 1 || t.rgba.size() != expected)
      throw ContactSheetError(
          "contact sheet: " +
          (i == 0 ? std::string("centre tile") : "variation " + std::to_string(i - 1)) + " is " +
          std::to_string(t.width) + "x" + std::to_string(t.height) + " with " +
          std::to_string(t.rgba.size()) + " bytes, not 4 bytes per pixel");
  }
}

// The thumbnail fitted into side x side, aspect ratio kept.
OIIO::ImageBuf fitted(const Thumbnail& t, int side) {
  OIIO::ImageBuf src(OIIO::ImageSpec(t.width, t.height, 4, OIIO::TypeDesc::UINT8));
  src.set_pixels(src.roi(), OIIO::TypeDesc::UINT8, t.rgba.data());
  const double scale = std::min(double(side) / t.width, double(side) / t.height);
  const int w = std::max(1, static_cast<int>(std::lround(t.width * scale)));
  const int h = std::max(1, static_cast<int>(std::lround(t.height * scale)));
  if (w == t.width && h == t.height) return src;
  return IBA::resize(src, "", 0.0f, OIIO::ROI(0, w, 0, h, 0, 1, 0, 4));
}

void check(bool ok, OIIO::ImageBuf& sheet, const char* what) {
  if (!ok) throw ContactSheetError(std::string("contact sheet: ") + what + ": " + sheet.geterror());
}

// One tile: its image centred at the top of the block, its label lines centred below.
void draw_tile(OIIO::ImageBuf& sheet, const SheetTile& tile, const GridCell& cell,
               const Geometry& g, const SheetOptions& options, bool highlight) {
  const int bx = g.x(cell.col), by = g.y(cell.row);
  const int bw = g.block_w(cell.span), side = std::min(bw, g.block_h(cell.span) - g.label_h);
  const OIIO::ImageBuf image = fitted(tile.image, side);
  const int iw = image.spec().width, ih = image.spec().height;
  const int ix = bx + (bw - iw) / 2, iy = by + (side - ih) / 2;
  check(IBA::paste(sheet, ix, iy, 0, 0, image, OIIO::ROI(0, iw, 0, ih, 0, 1, 0, 3)), sheet,
        "paste");
  for (int d = kFrameOffset; highlight && d < kFrameOffset + kFrameWidth; ++d)
    check(IBA::render_box(sheet, ix - d, iy - d, ix + iw - 1 + d, iy + ih - 1 + d, kHighlight),
          sheet, "frame");
  for (std::size_t i = 0; i < tile.label.size(); ++i) {
    if (tile.label[i].empty()) continue;
    check(IBA::render_text(sheet, bx + bw / 2, by + side + kLabelPad + static_cast<int>(i) * g.line,
                           tile.label[i], options.font_size, options.font, kTextColor,
                           IBA::TextAlignX::Center, IBA::TextAlignY::Top),
          sheet, "label");
  }
}

OIIO::ImageBuf render(const std::vector<const SheetTile*>& tiles, const Geometry& g,
                      const SheetOptions& options) {
  const SheetSize size = g.size();
  OIIO::ImageBuf sheet(OIIO::ImageSpec(size.width, size.height, 3, OIIO::TypeDesc::UINT8));
  check(IBA::fill(sheet, kSheetGrey), sheet, "fill");
  if (!options.title.empty())
    check(IBA::render_text(sheet, g.gap, g.gap, options.title, options.font_size, options.font,
                           kTextColor, IBA::TextAlignX::Left, IBA::TextAlignY::Top),
          sheet, "title");
  for (std::size_t i = 0; i < tiles.size(); ++i)
    draw_tile(sheet, *tiles[i], g.grid.cells[i], g, options, i == 0);
  return sheet;
}

fs::path temp_beside(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  // Appending, not "." + string: GCC 12 reports a false -Wrestrict for the latter.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return target.parent_path() / name;
}

// A sheet is written as PNG; under another extension it would pass for that format.
void check_png_name(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".png")
    throw ContactSheetError("cannot write contact sheet '" + path +
                            "': a PNG file name must end in .png");
}

void write_atomic(const OIIO::ImageBuf& sheet, const std::string& path) {
  const fs::path target(path);
  const fs::path temp = temp_beside(target);
  std::string error;
  if (!sheet.write(temp.string(), OIIO::TypeUnknown, "png")) {
    error = sheet.geterror();
  } else {
    std::error_code ec;
    fs::rename(temp, target, ec);
    if (ec) error = ec.message();
  }
  if (error.empty()) return;
  std::error_code ignored;
  fs::remove(temp, ignored);
  throw ContactSheetError("cannot write contact sheet '" + path + "': " + error);
}

}  // namespace

VariationGrid variation_grid(int variations) {
  if (variations < 0) throw ContactSheetError("contact sheet: negative number of variations");
  if (variations == 0) return {1, {GridCell{}}};
  int span = 1;
  while (4 * span + 4 < variations) ++span;
  VariationGrid grid{span + 2, {GridCell{1, 1, span}}};
  const int ring = 4 * span + 4;
  for (int i = 0; i < variations; ++i)
    grid.cells.push_back(ring_cell(i * ring / variations, grid.side));
  return grid;
}

SheetSize write_contact_sheet(const std::string& path, const SheetTile& centre,
                              const std::vector<SheetTile>& variations,
                              const SheetOptions& options) {
  check_png_name(path);
  std::vector<const SheetTile*> tiles{&centre};
  for (const auto& tile : variations) tiles.push_back(&tile);
  check_input(tiles, options);
  const Geometry g = layout(tiles, options);
  write_atomic(render(tiles, g, options), path);
  return g.size();
}

}  // namespace brdfnav::ocio
