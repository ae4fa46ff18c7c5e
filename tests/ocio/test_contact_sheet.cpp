#include <brdfnav/ocio/contact_sheet.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scratch_dir.h"

#include <OpenImageIO/imagebuf.h>

#include <array>
#include <set>
#include <utility>

namespace brdfnav::ocio {
namespace {

using test::ScratchDir;
using ::testing::HasSubstr;

using Rgb = std::array<std::uint8_t, 3>;

Thumbnail solid(int w, int h, Rgb rgb) {
  Thumbnail t{w, h, {}};
  for (int i = 0; i < w * h; ++i) t.rgba.insert(t.rgba.end(), {rgb[0], rgb[1], rgb[2], 255});
  return t;
}

// Distinct, saturated colours, so each tile can be found in the sheet by its colour.
Rgb tile_color(int i) {
  return {static_cast<std::uint8_t>(40 + 23 * i), static_cast<std::uint8_t>(220 - 19 * i),
          static_cast<std::uint8_t>(i % 2 ? 200 : 30)};
}

std::vector<SheetTile> ring_tiles(int n, int size) {
  std::vector<SheetTile> tiles;
  for (int i = 0; i < n; ++i)
    tiles.push_back({solid(size, size, tile_color(i)),
                     {"alpha_x" + std::string(i % 2 ? "-" : "+"), "d=0.050"}});
  return tiles;
}

Rgb pixel(const OIIO::ImageBuf& image, int x, int y) {
  float v[3];
  image.getpixel(x, y, v, 3);
  return {static_cast<std::uint8_t>(v[0] * 255 + 0.5f),
          static_cast<std::uint8_t>(v[1] * 255 + 0.5f),
          static_cast<std::uint8_t>(v[2] * 255 + 0.5f)};
}

bool opposite(const GridCell& a, const GridCell& b, int side) {
  return a.col + b.col == side - 1 && a.row + b.row == side - 1;
}

TEST(VariationGrid, EightVariationsMakeARingAroundTheCentre) {
  const VariationGrid grid = variation_grid(8);
  EXPECT_EQ(grid.side, 3);
  ASSERT_EQ(grid.cells.size(), 9u);
  EXPECT_EQ(grid.cells[0].col, 1);
  EXPECT_EQ(grid.cells[0].row, 1);
  EXPECT_EQ(grid.cells[0].span, 1);
  std::set<std::pair<int, int>> used{{1, 1}};
  for (int i = 1; i <= 8; ++i) used.insert({grid.cells[i].col, grid.cells[i].row});
  EXPECT_EQ(used.size(), 9u);  // every cell of the 3x3 grid, once
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(opposite(grid.cells[1 + i], grid.cells[5 + i], 3)) << i;
}

TEST(VariationGrid, TenVariationsGetALargerCentreAndPairsFaceEachOther) {
  const VariationGrid grid = variation_grid(10);  // 2 colour + 8 lobe variations
  EXPECT_EQ(grid.side, 4);
  EXPECT_EQ(grid.cells[0].span, 2);
  std::set<std::pair<int, int>> used;
  for (int i = 1; i <= 10; ++i) {
    const GridCell& c = grid.cells[i];
    EXPECT_TRUE(c.col == 0 || c.col == 3 || c.row == 0 || c.row == 3) << "not on the ring: " << i;
    used.insert({c.col, c.row});
  }
  EXPECT_EQ(used.size(), 10u);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(opposite(grid.cells[1 + i], grid.cells[6 + i], 4)) << i;
}

TEST(VariationGrid, SmallCounts) {
  EXPECT_EQ(variation_grid(0).side, 1);
  EXPECT_EQ(variation_grid(2).side, 3);
  EXPECT_TRUE(opposite(variation_grid(2).cells[1], variation_grid(2).cells[2], 3));
  EXPECT_EQ(variation_grid(13).side, 5);
  EXPECT_THROW(variation_grid(-1), ContactSheetError);
}

TEST(ContactSheet, WritesACentreAndEightLabelledVariations) {
  ScratchDir dir;
  const auto path = (dir.path() / "sheet.png").string();
  const SheetTile centre{solid(128, 128, {128, 128, 128}), {"current", "at_boundary"}};
  const auto ring = ring_tiles(8, 128);
  const SheetSize size = write_contact_sheet(path, centre, ring);
  // SheetSize's documented geometry: 3 cells of 128 + 6 + 2 label lines of 13 + 13/3 = 17
  // pixels, 4 gaps of 12.
  const int cell_h = 128 + 6 + 2 * 17;
  EXPECT_EQ(size.width, 3 * 128 + 4 * 12);
  EXPECT_EQ(size.height, 3 * cell_h + 4 * 12);

  OIIO::ImageBuf sheet(path);
  ASSERT_TRUE(sheet.read()) << sheet.geterror();
  EXPECT_EQ(sheet.spec().width, size.width);
  EXPECT_EQ(sheet.spec().height, size.height);
  EXPECT_EQ(sheet.spec().format, OIIO::TypeDesc::UINT8);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"sheet.png"});  // no temporary left over

  const VariationGrid grid = variation_grid(8);
  auto cell_x = [](int col) { return 12 + col * (128 + 12); };
  auto cell_y = [&](int row) { return 12 + row * (cell_h + 12); };
  for (int i = 0; i < 8; ++i) {
    const GridCell& c = grid.cells[1 + i];
    EXPECT_EQ(pixel(sheet, cell_x(c.col) + 64, cell_y(c.row) + 64), tile_color(i)) << i;
    // Light label text on the dark sheet in the strip under the image.
    int lit = 0;
    for (int y = cell_y(c.row) + 128; y < cell_y(c.row) + cell_h; ++y)
      for (int x = cell_x(c.col); x < cell_x(c.col) + 128; ++x) lit += pixel(sheet, x, y)[0] > 128;
    EXPECT_GT(lit, 50) << "no label under variation " << i;
  }
  EXPECT_EQ(pixel(sheet, cell_x(1) + 64, cell_y(1) + 64), (Rgb{128, 128, 128}));
  const Rgb frame = pixel(sheet, cell_x(1) - 3, cell_y(1) + 64);  // the centre's highlight
  EXPECT_GT(frame[0], 200);
  EXPECT_LT(frame[2], 80);
  EXPECT_NE(pixel(sheet, cell_x(0) - 3, cell_y(0) + 64), frame);  // variations are not framed
}

TEST(ContactSheet, TenVariationsEnlargeTheCentreAndFitOddSizes) {
  ScratchDir dir;
  const auto path = (dir.path() / "ten.png").string();
  const SheetTile centre{solid(64, 32, {128, 128, 128}), {"current"}};
  SheetOptions options;
  options.title = "ward: Standard view";
  const SheetSize size = write_contact_sheet(path, centre, ring_tiles(10, 96), options);
  const int cell_h = 128 + 6 + 2 * 17;
  EXPECT_EQ(size.width, 4 * 128 + 5 * 12);
  EXPECT_EQ(size.height, 17 + 12 + 4 * cell_h + 5 * 12);
  OIIO::ImageBuf sheet(path);
  ASSERT_TRUE(sheet.read()) << sheet.geterror();
  // The 64x32 centre is fitted into the 2x2 block's 268-pixel square: 268 x 134, centred.
  const int block_x = 12 + 140, block_y = 17 + 12 + 12 + cell_h + 12, side = 2 * 128 + 12;
  const int top = block_y + (side - 134) / 2;
  EXPECT_EQ(pixel(sheet, block_x + 1, top + 1), (Rgb{128, 128, 128}));
  EXPECT_EQ(pixel(sheet, block_x + side - 2, top + 132), (Rgb{128, 128, 128}));
  EXPECT_NE(pixel(sheet, block_x + side / 2, top - 10), (Rgb{128, 128, 128}));  // letterbox
}

TEST(ContactSheet, UnwritableTargetLeavesNoFileAndNamesIt) {
  ScratchDir dir;
  const SheetTile centre{solid(16, 16, {128, 128, 128}), {"current"}};
  const auto ring = ring_tiles(4, 16);
  dir.write("a_file", "x");
  std::filesystem::create_directories(dir.path() / "a_dir" / "inside");
  for (const auto& target :
       {dir.path() / "missing_dir" / "sheet.png", dir.path() / "a_file" / "sheet.png",
        dir.path() / "a_dir", dir.path() / "sheet.exr", dir.path() / "sheet"}) {
    try {
      write_contact_sheet(target.string(), centre, ring);
      FAIL() << "no error for " << target;
    } catch (const ContactSheetError& e) {
      EXPECT_THAT(e.what(), HasSubstr("'" + target.string() + "'"));
    }
    auto entries = dir.entries();
    std::sort(entries.begin(), entries.end());
    EXPECT_EQ(entries, (std::vector<std::string>{"a_dir", "a_file"})) << target;
  }
}

TEST(ContactSheet, RejectsMalformedTilesBeforeWriting) {
  ScratchDir dir;
  const auto path = (dir.path() / "bad.png").string();
  Thumbnail short_buffer = solid(8, 8, {1, 2, 3});
  short_buffer.rgba.pop_back();
  try {
    write_contact_sheet(path, {solid(8, 8, {1, 2, 3}), {}}, {{short_buffer, {"x"}}});
    FAIL() << "no error";
  } catch (const ContactSheetError& e) {
    EXPECT_THAT(e.what(), HasSubstr("variation 0"));
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ContactSheet, MissingFontIsAnError) {
  ScratchDir dir;
  SheetOptions options;
  options.font = "NoSuchFontAnywhere";
  EXPECT_THROW(write_contact_sheet((dir.path() / "f.png").string(),
                                   {solid(8, 8, {1, 2, 3}), {"label"}}, {}, options),
               ContactSheetError);
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace brdfnav::ocio
