// The final images (app/final_images.h) and the server's thumbnails on the shared test database,
// whose build records a blend check per cell: a material in a cell the check vouches for shows
// its blend, any other its exact render, and exact steps are measured on what is shown.
#include "final_images.h"
#include "serve_api.h"

#include "cli_runner.h"

#include <brdfnav/navigator/navigation_json.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>

namespace brdfnav::cli {
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

// A coloured material at the midpoint of the first cell of `model` whose check is (or is not)
// within FinalImages::kFaithfulBlend.
std::optional<Material> material_in(ModelId model, bool vouched) {
  const ParamGrid& grid = suite().db->embedding(model)->grid();
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    Material m = default_material(model);
    m.params = grid.cell_midpoint(c);
    m.rho_d = Rgb(0.3, 0.2, 0.1), m.rho_s = Rgb(0.2, 0.2, 0.25);
    if ((*suite().db->blend_error(m) <= FinalImages::kFaithfulBlend) == vouched) return m;
  }
  return std::nullopt;
}

// An unvouched material of any model: the test database's He cells are (0.2 to 0.8 eps at their
// midpoints, as on the default database), whatever the others'.
Material unvouched() {
  for (const ProfileGrid& g : suite().db->manifest().grids)
    if (std::optional<Material> m = material_in(g.model, false)) return *m;
  throw std::runtime_error("the test database vouches for every cell");
}

TEST(FinalImages, AVouchedCellShowsItsBlendAndAnyOtherItsRender) {
  const Thumbnails blends(*suite().db, suite().resolution);
  const ExactThumbnails exact(*suite().db, suite().resolution);
  const FinalImages finals(blends, exact);
  const int res = suite().resolution;
  const std::optional<Material> ward = material_in(ModelId::ward, true);
  ASSERT_TRUE(ward) << "no Ward cell of the test database is vouched for";
  EXPECT_TRUE(finals.shows_blend(*ward, res));
  EXPECT_EQ(finals.image(*ward, res)->rgba, blends.render(*ward).rgba);
  // Larger than the database's images: always the render.
  EXPECT_FALSE(finals.shows_blend(*ward, 2 * res));
  EXPECT_EQ(finals.image(*ward, 2 * res)->rgba, exact.render(*ward, 2 * res)->rgba);
  // A stricter bar than any check: the render.
  const FinalImages strict(blends, exact, 0.0);
  EXPECT_FALSE(strict.shows_blend(*ward, res));
  EXPECT_EQ(strict.image(*ward, res)->rgba, exact.render(*ward)->rgba);
  const Material other = unvouched();
  EXPECT_FALSE(finals.shows_blend(other, res));
  EXPECT_EQ(finals.image(other, res)->rgba, exact.render(other)->rgba);
}

TEST(FinalImages, StepsAreMeasuredOnTheImagesShown) {
  const Thumbnails blends(*suite().db, suite().resolution);
  const ExactThumbnails exact(*suite().db, suite().resolution);
  const FinalImages finals(blends, exact);
  const std::optional<Material> a = material_in(ModelId::ward, true);
  ASSERT_TRUE(a);
  Material b = *a;
  b.params[0] *= 1.05;  // the same cell, vouched for alike
  ASSERT_TRUE(finals.shows_blend(b, suite().resolution));
  EXPECT_EQ(finals.steps_from(*a, 0.03).distance(b),
            image_distance(blends.render(*a), blends.render(b)));
  const Material other = unvouched();
  EXPECT_EQ(finals.steps_from(*a, 0.03).distance(other),
            image_distance(blends.render(*a), *exact.render(other)));
  // With no blend vouched for, the steps are ExactThumbnails' own.
  const FinalImages strict(blends, exact, 0.0);
  EXPECT_EQ(strict.steps_from(*a, 0.03).distance(b), exact.steps_from(*a).distance(b));
  // A radius so small that no check is within a tenth of it: renders too.
  EXPECT_EQ(finals.steps_from(*a, 1e-9).distance(b), exact.steps_from(*a).distance(b));
}

// The server answers the final image and says which it is.
TEST(FinalImages, TheServerSaysWhetherAThumbnailIsABlendOrARender) {
  const NavigatorApi api(ApiOptions{suite().dir, suite().resolution});
  const auto kind = [&](const std::string& material, const std::string& extra) {
    const ApiResponse answer =
        api.handle({"POST", "/api/thumbnail", {}, R"({"material": )" + material + extra + "}"});
    EXPECT_EQ(answer.status, 200) << answer.body;
    for (const auto& [name, value] : answer.headers)
      if (name == "X-Brdfnav-Image") return value;
    return std::string("none");
  };
  const auto json = [](const Material& m) { return material_json(m).dump(); };
  const std::optional<Material> ward = material_in(ModelId::ward, true);
  ASSERT_TRUE(ward);
  EXPECT_EQ(kind(json(*ward), ""), "blend");
  EXPECT_EQ(kind(json(unvouched()), ""), "render");
  EXPECT_EQ(kind(json(unvouched()), R"(, "preview": true)"), "blend");
}

}  // namespace
}  // namespace brdfnav::cli
