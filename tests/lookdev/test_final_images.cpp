// The final images (lookdev/include/brdfnav/lookdev/final_images.h) and the server's thumbnails on
// the shared test database, whose build records a blend check per cell: a material in a cell whose
// check is within the bar shows its blend, any other its exact render, and exact steps are measured
// on what is shown.
#include <brdfnav/lookdev/final_images.h>
#include <brdfnav/serve/serve_api.h>

#include "cli_runner.h"

#include <brdfnav/navigator/navigation_json.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <utility>

namespace brdfnav::lookdev {
namespace {

struct Suite {
  std::filesystem::path dir;
  std::optional<Database> db;
  int resolution = 0;
};

const Suite& suite() {
  static const Suite s = [] {
    Suite out;
    std::string error;
    out.dir = test::suite_database(std::filesystem::temp_directory_path() / "brdfnav_final_images",
                                   error);
    if (out.dir.empty()) throw std::runtime_error(error);
    out.db.emplace(Database::open(out.dir));
    out.resolution = out.db->manifest().resolution;
    return out;
  }();
  return s;
}

// A coloured material at a cell's midpoint, and its cell's check.
struct Checked {
  Material material;
  double error;
};

// The cells with the smallest and the largest check over every model of the suite's database.
// The tests set the bar between them, so that they hold on any database, the smoke profile's
// (whose sparse grids vouch for no cell at kFaithfulBlend) as well as the test profile's.
std::pair<Checked, Checked> extreme_cells() {
  std::optional<Checked> low, high;
  for (const ProfileGrid& g : suite().db->manifest().grids)
    for (std::size_t c = 0; c < g.grid.cell_count(); ++c) {
      Material m = default_material(g.model);
      m.params = g.grid.cell_midpoint(c);
      m.rho_d = Rgb(0.3, 0.2, 0.1), m.rho_s = Rgb(0.2, 0.2, 0.25);
      const Checked checked{m, *suite().db->blend_error(m)};
      if (!low || checked.error < low->error) low = checked;
      if (!high || checked.error > high->error) high = checked;
    }
  if (!(low->error < high->error)) throw std::runtime_error("every cell has the same check");
  return {*low, *high};
}

TEST(FinalImages, AVouchedCellShowsItsBlendAndAnyOtherItsRender) {
  const Thumbnails blends(*suite().db, suite().resolution);
  const ExactThumbnails exact(*suite().db, suite().resolution);
  const auto [low, high] = extreme_cells();
  const FinalImages finals(blends, exact, low.error);
  const int res = suite().resolution;
  const Material& m = low.material;
  EXPECT_TRUE(finals.shows_blend(m, res));
  EXPECT_EQ(finals.image(m, res)->rgba, blends.render(m).rgba);
  // Larger than the database's images: always the render.
  EXPECT_FALSE(finals.shows_blend(m, 2 * res));
  EXPECT_EQ(finals.image(m, 2 * res)->rgba, exact.render(m, 2 * res)->rgba);
  // A bar below the check: the render.
  const FinalImages strict(blends, exact, 0.5 * low.error);
  EXPECT_FALSE(strict.shows_blend(m, res));
  EXPECT_EQ(strict.image(m, res)->rgba, exact.render(m)->rgba);
  EXPECT_FALSE(finals.shows_blend(high.material, res));
  EXPECT_EQ(finals.image(high.material, res)->rgba, exact.render(high.material)->rgba);
}

// A material on a node shows the node's image, the database's own render, even where the cells
// around it are not vouched for.
TEST(FinalImages, AMaterialOnANodeShowsItsImage) {
  const Thumbnails blends(*suite().db, suite().resolution);
  const ExactThumbnails exact(*suite().db, suite().resolution);
  const auto [low, high] = extreme_cells();
  const FinalImages finals(blends, exact, low.error);
  const int res = suite().resolution;
  Material m = high.material;
  EXPECT_FALSE(finals.shows_blend(m, res));
  const ParamGrid& grid = suite().db->embedding(m.model)->grid();
  for (std::size_t d = 0; d < grid.dimensions(); ++d) {  // the cell's lowest corner
    const auto i = static_cast<std::size_t>(std::floor(grid.grid_coordinate(d, m.params[d])));
    m.params[d] = grid.axis(d)[std::min(i, grid.axis(d).size() - 2)];
  }
  EXPECT_TRUE(finals.shows_blend(m, res));
  EXPECT_EQ(finals.image(m, res)->rgba, blends.render(m).rgba);
}

TEST(FinalImages, StepsAreMeasuredOnTheImagesShown) {
  const Thumbnails blends(*suite().db, suite().resolution);
  const ExactThumbnails exact(*suite().db, suite().resolution);
  const auto [low, high] = extreme_cells();
  const FinalImages finals(blends, exact, low.error);
  const Material& a = low.material;
  Material b = a;
  b.rho_d = Rgb(0.1, 0.3, 0.2);  // the same cell, another colour
  ASSERT_TRUE(finals.shows_blend(b, suite().resolution));
  // A radius whose tenth clears the check: blends.
  const double radius = 1.01 * low.error / FinalImages::kStepShare;
  EXPECT_EQ(finals.steps_from(a, radius).distance(b),
            image_distance(blends.render(a), blends.render(b)));
  EXPECT_EQ(finals.steps_from(a, radius).distance(high.material),
            image_distance(blends.render(a), *exact.render(high.material)));
  // A radius so small that no check is within a tenth of it, or a bar no check clears: renders,
  // the steps of ExactThumbnails.
  const double rendered = exact.steps_from(a).distance(b);
  EXPECT_EQ(finals.steps_from(a, 0.5 * radius).distance(b), rendered);
  EXPECT_EQ(FinalImages(blends, exact, 0.5 * low.error).steps_from(a, radius).distance(b),
            rendered);
}

// The server answers the final image and says which it is.
TEST(FinalImages, TheServerSaysWhetherAThumbnailIsABlendOrARender) {
  const auto [low, high] = extreme_cells();
  const serve::NavigatorApi api(serve::ApiOptions{suite().dir, suite().resolution, low.error});
  const auto kind = [&](const Material& m, const std::string& extra) {
    const serve::ApiResponse answer = api.handle(
        {"POST", "/api/thumbnail", {}, R"({"material": )" + material_json(m).dump() + extra + "}"});
    EXPECT_EQ(answer.status, 200) << answer.body;
    for (const auto& [name, value] : answer.headers)
      if (name == "X-Brdfnav-Image") return value;
    return std::string("none");
  };
  EXPECT_EQ(kind(low.material, ""), "blend");
  EXPECT_EQ(kind(high.material, ""), "render");
  EXPECT_EQ(kind(high.material, R"(, "preview": true)"), "blend");
}

}  // namespace
}  // namespace brdfnav::lookdev
