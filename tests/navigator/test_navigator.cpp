// The neighbour service through its C++ API, on a test-profile database: every tab's neighbours
// are where the paper puts them (checked through the embedding, independently of the walk), the
// clustering is deterministic, concurrent queries agree with serial ones, and the YAML documents
// read back.
#include "navigator/navigator_fixture.h"

#include <brdfnav/core/cielab.h>
#include <brdfnav/io/material_yaml.h>
#include <brdfnav/navigator/database_format.h>
#include <brdfnav/navigator/navigation_json.h>
#include <brdfnav/navigator/navigation_yaml.h>
#include <brdfnav/navigator/navigator.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "closest.h"
#include "color.h"
#include "ring.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <thread>

namespace brdfnav {
namespace {

using test::random_material;
using ::testing::HasSubstr;

using test::navigator;

const ParamGrid& grid_of(ModelId id) {
  return navigator().database().embedding(id)->grid();
}

// A few random materials of every model, with the radii to query them at.
struct Case {
  Material material;
  double radius;
};
std::vector<Case> cases(int per_model, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Case> out;
  for (const ModelInfo& info : models())
    for (int i = 0; i < per_model; ++i)
      for (double radius : {0.005, 0.02})
        out.push_back({random_material(info.id, grid_of(info.id), rng), radius});
  return out;
}

std::string describe(const Case& c) {
  return format_material_spec(c.material) + " eps " + std::to_string(c.radius);
}

bool same(const Material& a, const Material& b) {
  return a.model == b.model && a.params == b.params && (a.rho_d == b.rho_d).all() &&
         (a.rho_s == b.rho_s).all() && a.colorspace == b.colorspace;
}

void expect_same(const std::vector<Neighbor>& a, const std::vector<Neighbor>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].tab, b[i].tab);
    EXPECT_EQ(a[i].label, b[i].label);
    EXPECT_EQ(a[i].distance, b[i].distance);
    EXPECT_EQ(a[i].at_boundary, b[i].at_boundary);
    EXPECT_EQ(a[i].clamped, b[i].clamped);
    EXPECT_TRUE(same(a[i].material, b[i].material)) << a[i].label;
  }
}

// The neighbour is at eps (recomputed through the embedding) unless the walk stopped early, and
// then it is inside the sphere.
void expect_on_sphere(const Case& c, const Neighbor& n, bool stopped) {
  const double d = navigator().distance(c.material, n.material);
  EXPECT_NEAR(d, n.distance, 1e-6 * c.radius) << n.label;
  if (stopped) {
    EXPECT_LE(d, c.radius * (1 + 1e-3)) << n.label;
  } else {
    EXPECT_NEAR(d, c.radius, 1e-3 * c.radius) << n.label;
  }
}

// The ring contract (navigator.h): each offer's opposite is the offer with the opposite label,
// each pair is i and i + n/2 when every offer has one, and every offer has words and a change.
void expect_ring(const std::vector<Neighbor>& ring) {
  const int n = static_cast<int>(ring.size());
  bool all_paired = true;
  for (int i = 0; i < n; ++i) {
    const Neighbor& a = ring[i];
    EXPECT_FALSE(a.words.empty()) << a.label;
    EXPECT_FALSE(a.change.empty()) << a.label;
    if (a.opposite < 0) {
      all_paired = false;
      continue;
    }
    ASSERT_LT(a.opposite, n) << a.label;
    EXPECT_EQ(ring[a.opposite].opposite, i) << a.label;
    EXPECT_EQ(nav::opposite_label(a.label), ring[a.opposite].label);
  }
  if (all_paired && n > 0)
    for (int i = 0; i < n / 2; ++i) EXPECT_EQ(ring[i].opposite, i + n / 2) << ring[i].label;
}

// A tab's offers by label.
std::map<std::string, Neighbor> by_label(const std::vector<Neighbor>& offers) {
  std::map<std::string, Neighbor> out;
  for (const Neighbor& n : offers) EXPECT_TRUE(out.emplace(n.label, n).second) << n.label;
  return out;
}

TEST(Navigator, LobeNeighboursAreAtTheRadiusOrAtTheEndOfTheGrid) {
  for (const Case& c : cases(3, 1)) {
    SCOPED_TRACE(describe(c));
    const ModelInfo& info = model_info(c.material.model);
    const std::vector<Neighbor> lobe = navigator().neighbors(c.material, c.radius, Tab::lobe);
    std::vector<std::string> labels;
    for (const ParamSpec& p : info.params)
      labels.insert(labels.end(), {std::string(p.name) + "+", std::string(p.name) + "-"});
    if (info.id == ModelId::ward) labels.insert(labels.end(), {"alpha+", "alpha-"});
    ASSERT_EQ(lobe.size(), labels.size());
    expect_ring(lobe);
    const std::map<std::string, Neighbor> found = by_label(lobe);
    for (const std::string& label : labels) {
      ASSERT_TRUE(found.contains(label)) << label;
      const Neighbor& n = found.at(label);
      // The table's words for the parameter's direction (Ward's alpha: "rougher" / "sharper").
      const std::string name = label.substr(0, label.size() - 1);
      const bool up = label.back() == '+';
      for (const ParamSpec& p : info.params)
        if (p.name == name) EXPECT_EQ(n.words, up ? p.more : p.less) << label;
      if (name == "alpha") EXPECT_EQ(n.words, up ? "rougher" : "sharper");
      EXPECT_EQ(n.tab, Tab::lobe);
      EXPECT_FALSE(n.clamped);
      EXPECT_NO_THROW(validate(n.material));
      expect_on_sphere(c, n, n.at_boundary);
    }
  }
}

// Beyond every distance the database holds, each walk ends at its grid end, and the distance it
// reports is that end's: not the radius plus (distance - radius), which rounds to 0 at 1e20.
TEST(Navigator, AHugeRadiusReportsTheDistancesReached) {
  const Material m = default_material(ModelId::ward);
  for (Tab tab : {Tab::lobe, Tab::diffuse, Tab::specular})
    for (const Neighbor& n : navigator().neighbors(m, 1e20, tab)) {
      SCOPED_TRACE(n.label);
      EXPECT_TRUE(n.at_boundary || n.clamped);
      EXPECT_NEAR(n.distance, navigator().distance(m, n.material), 1e-9);
    }
}

TEST(Navigator, PlusAndMinusMoveTheirParameterOnly) {
  for (const Case& c : cases(3, 2)) {
    SCOPED_TRACE(describe(c));
    const ParamGrid& grid = grid_of(c.material.model);
    for (const Neighbor& n : navigator().neighbors(c.material, c.radius, Tab::lobe)) {
      const bool up = n.label.back() == '+';
      const std::string name = n.label.substr(0, n.label.size() - 1);
      const int moved = find_param(model_info(c.material.model), name);
      for (std::size_t d = 0; d < grid.dimensions(); ++d) {
        const double before = c.material.params[d], after = n.material.params[d];
        if (moved >= 0 && d != static_cast<std::size_t>(moved)) {
          EXPECT_EQ(after, before) << n.label;
          continue;
        }
        EXPECT_TRUE(up ? after > before : after < before) << n.label << ": " << after;
        if (n.at_boundary && moved >= 0) {
          EXPECT_EQ(after, up ? grid.axis(d).back() : grid.axis(d).front()) << n.label;
        }
      }
      if (moved < 0) {  // Ward's alpha+ / alpha-: both slopes by one factor, the anisotropy kept
        EXPECT_EQ(c.material.model, ModelId::ward) << n.label;
        EXPECT_NEAR(n.material.params[0] / n.material.params[1],
                    c.material.params[0] / c.material.params[1], 1e-9);
      }
      EXPECT_TRUE((n.material.rho_d == c.material.rho_d).all());
      EXPECT_TRUE((n.material.rho_s == c.material.rho_s).all());
    }
  }
}

TEST(Navigator, AMaterialAtTheEndOfItsGridStaysThereTowardTheEnd) {
  Material m = default_material(ModelId::ward);
  m.params = {grid_of(ModelId::ward).axis(0).back(), 0.02};
  m.rho_s = Rgb::Constant(0.5);
  const std::vector<Neighbor> lobe = navigator().neighbors(m, 0.01, Tab::lobe);
  ASSERT_EQ(lobe[0].label, "alpha_x+");
  EXPECT_TRUE(lobe[0].at_boundary);
  EXPECT_EQ(lobe[0].distance, 0);
  EXPECT_EQ(lobe[0].material.params, m.params);
  EXPECT_FALSE(lobe[1].at_boundary);
}

TEST(Navigator, CielabOfReferenceColors) {
  const Vec3 white = lab_from_rec709(Rgb::Ones());
  EXPECT_NEAR(white.x(), 100, 1e-9);
  EXPECT_NEAR(white.y(), 0, 1e-9);
  EXPECT_NEAR(white.z(), 0, 1e-9);
  // sRGB red: L*a*b* (53.24, 80.09, 67.20) (Lindbloom's calculator, D65).
  const Vec3 red = lab_from_rec709(Rgb(1, 0, 0));
  EXPECT_NEAR(red.x(), 53.24, 0.01);
  EXPECT_NEAR(red.y(), 80.09, 0.01);
  EXPECT_NEAR(red.z(), 67.20, 0.01);
  const Rgb color(0.3, 0.02, 4.5);
  EXPECT_LT((rec709_from_lab(lab_from_rec709(color)) - color).abs().maxCoeff(), 1e-12);
}

// The colour tabs' hue words say what the picture shows: each of the eight directions is named
// by a colour whose CIELAB hue is within 30 degrees of it (the "ab+0" offer is pink, not red),
// and no two directions share their words.
TEST(Navigator, HueWordsNameAColourOfTheirDirection) {
  std::set<std::string> said;
  for (int degrees = 0; degrees < 360; degrees += 45) {
    const std::string words = nav::hue_word(degrees);
    said.insert(words);
    const auto word = std::find_if(nav::hue_words().begin(), nav::hue_words().end(),
                                   [&](const nav::HueWord& w) { return words == w.words; });
    ASSERT_NE(word, nav::hue_words().end()) << words;
    const double gap = std::abs(std::remainder(nav::hue_angle(*word) - degrees, 360.0));
    EXPECT_LE(gap, 30) << degrees << " degrees: " << words << " at " << nav::hue_angle(*word);
  }
  EXPECT_EQ(said.size(), 8u);
  EXPECT_EQ(nav::hue_word(0), "towards pink");
  EXPECT_EQ(nav::hue_word(45), "towards red");
  EXPECT_EQ(nav::hue_word(135), "towards green");
}

// Colour neighbours: at eps and valid, or clamped at the edge of the valid range (inside the
// sphere); L+ brighter, L- darker, the a-b ones at their hue and at the current L.
void expect_color_tab(const Case& c, Tab tab) {
  const bool diffuse = tab == Tab::diffuse;
  const double max = diffuse ? kRhoDMax : kRhoSMax;
  const Rgb& before = diffuse ? c.material.rho_d : c.material.rho_s;
  const Vec3 lab = lab_from_rec709(before);
  const std::vector<Neighbor> out = navigator().neighbors(c.material, c.radius, tab);
  ASSERT_EQ(out.size(), 10u);
  expect_ring(out);
  const std::map<std::string, Neighbor> found = by_label(out);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::string label =
        i < 2 ? (i == 0 ? "L+" : "L-") : "ab+" + std::to_string(45 * static_cast<int>(i - 2));
    ASSERT_TRUE(found.contains(label)) << label;
    const Neighbor& n = found.at(label);
    EXPECT_EQ(n.words, i < 2 ? (i == 0 ? "lighter" : "darker") : nav::hue_word(45.0 * (i - 2)));
    const Rgb& after = diffuse ? n.material.rho_d : n.material.rho_s;
    EXPECT_TRUE((after >= 0).all() && (after <= max).all()) << n.label;
    EXPECT_FALSE(n.at_boundary);
    expect_on_sphere(c, n, n.clamped);
    const Vec3 step = lab_from_rec709(after) - lab;
    if (step.norm() < 1e-6) continue;  // clamped at once: no direction to check
    if (i < 2) {
      EXPECT_GT(i == 0 ? step.x() : -step.x(), 0) << n.label;
    } else {
      const int degrees = 45 * static_cast<int>(i - 2);
      const double angle = degrees * std::numbers::pi / 180;
      EXPECT_NEAR(step.x(), 0, 1e-6 * step.norm()) << n.label;
      EXPECT_NEAR(step.y() * std::sin(angle) - step.z() * std::cos(angle), 0, 1e-6 * step.norm())
          << n.label;
    }
  }
}

TEST(Navigator, ColorNeighboursAreAtTheRadiusAndValid) {
  for (const Case& c : cases(2, 3)) {
    SCOPED_TRACE(describe(c));
    expect_color_tab(c, Tab::diffuse);
    expect_color_tab(c, Tab::specular);
  }
}

TEST(Navigator, ColorsAtTheEdgeOfTheirRangeAreClamped) {
  Material m = default_material(ModelId::blinn_phong);
  m.rho_d = Rgb(0.98, 0.98, 0.98), m.rho_s = Rgb::Constant(0.2);
  const Case white{m, 0.05};
  const auto diffuse = by_label(navigator().neighbors(m, white.radius, Tab::diffuse));
  EXPECT_TRUE(diffuse.at("L+").clamped) << "L+ of near-white";
  EXPECT_FALSE(diffuse.at("L-").clamped) << "L- of near-white";
  expect_color_tab(white, Tab::diffuse);
  // Black: no other L and no hue is valid, so every neighbour but L+ is black itself (to the
  // bisection's resolution).
  m.rho_d = Rgb::Zero();
  for (const Neighbor& n : navigator().neighbors(m, 0.01, Tab::diffuse)) {
    if (n.label == "L+") continue;
    EXPECT_TRUE(n.clamped) << n.label;
    EXPECT_LT(n.material.rho_d.maxCoeff(), 1e-6) << n.label;
    EXPECT_LT(n.distance, 1e-4) << n.label;
  }
}

// The page starts from start_material() at radius 0.03 (serve/src/serve_api.cpp), and the README's
// example asks for this Ward material at 0.03: every lobe and colour direction has room to move.
TEST(Navigator, TheStartAndTheReadmesMaterialHaveRoomInEveryDirection) {
  const Navigator& nav = navigator();
  // The smoke profile (the sanitized trees' database) has 2 to 4 nodes per axis: a step of 0.03
  // leaves its grids.
  if (nav.database().manifest().profile == "smoke")
    GTEST_SKIP() << "the smoke profile's grids are too coarse for a radius of 0.03";
  for (const Material& m :
       {nav.start_material(),
        parse_material_spec("ward:alpha_x=0.05,alpha_y=0.05,rho_d=0.2,rho_s=0.3")}) {
    SCOPED_TRACE(format_material_spec(m));
    for (Tab tab : {Tab::lobe, Tab::diffuse, Tab::specular})
      for (const Neighbor& n : nav.neighbors(m, 0.03, tab)) {
        EXPECT_FALSE(n.at_boundary) << n.label;
        EXPECT_FALSE(n.clamped) << n.label;
      }
  }
  EXPECT_EQ(nav.start_material().model, nav.database().manifest().grids.front().model);
}

TEST(Navigator, ModelsTabShowsWhatTheCurrentModelCannot) {
  const Navigator& nav = navigator();
  std::size_t shown = 0, beyond = 0;
  for (const Case& c : cases(2, 4)) {
    SCOPED_TRACE(describe(c));
    const std::vector<Neighbor> out = nav.neighbors(c.material, c.radius, Tab::models, 5);
    EXPECT_LE(out.size(), 5u);
    shown += out.size();
    expect_ring(out);
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Neighbor& n = out[i];
      EXPECT_NE(n.material.model, c.material.model);
      EXPECT_EQ(n.label, model_info(n.material.model).name);
      EXPECT_EQ(n.words, "as " + std::string(model_info(n.material.model).title));
      EXPECT_NEAR(nav.distance(c.material, n.material), n.distance, 1e-6 * c.radius);
      // At eps from the current material; a model that cannot come that close offers the
      // closest it comes, flagged, farther than eps and no farther than its best fit.
      if (n.beyond_radius) {
        EXPECT_GE(n.distance, c.radius) << n.label;
        const Material fit = nav.convert(c.material, n.material.model);
        EXPECT_LE(n.distance, nav.distance(c.material, fit) + 1e-9) << n.label;
        ++beyond;
      } else if (!n.at_boundary) {
        EXPECT_NEAR(n.distance, c.radius, 1e-3 * c.radius) << n.label;
        // Its best fit in the current model is at least delta = 0.3 eps away.
        const Material back = nav.convert(n.material, c.material.model);
        EXPECT_GE(nav.distance(n.material, back), 0.3 * c.radius) << n.label;
      }
      // No two offers look the same: at least delta apart.
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_GE(nav.distance(n.material, out[j].material), 0.3 * c.radius) << n.label;
    }
  }
  EXPECT_GT(shown, 0u) << "the filter dropped every neighbour of every case";
  EXPECT_GT(beyond, 0u) << "no case had a model beyond the radius";
}

// The search for a model's closest material: from a far start in the centre's own model it
// comes back to the centre (the embedding's distance vanishes there), and it is never farther
// than where it started.
TEST(ClosestInModel, FindsTheCentreFromAFarStart) {
  const Navigator& nav = navigator();
  const ModelEmbedding& ward = *nav.database().embedding(ModelId::ward);
  Material centre = default_material(ModelId::ward);
  centre.params = {0.1, 0.05};
  centre.rho_s = Rgb::Constant(0.5);
  Material start = centre;
  start.params = {0.3, 0.2};
  start.rho_s = Rgb::Constant(0.2);
  const Eigen::VectorXf point = ward.embed(centre);
  const double far = embedding_distance(ward.embed(start), point);
  const nav::Closest c = nav::closest_in_model(ward, point, start);
  EXPECT_LT(c.distance, 0.05 * far) << far;
  EXPECT_NEAR(std::log(c.material.params[0] / 0.1), 0, 0.1);
  EXPECT_NEAR(std::log(c.material.params[1] / 0.05), 0, 0.1);
  EXPECT_NEAR(std::log(c.material.rho_s[0] / 0.5), 0, 0.1);
  EXPECT_LE(c.evaluations, 200);
  // A start at the centre stays there.
  EXPECT_EQ(nav::closest_in_model(ward, point, centre).distance, 0.0);
}

TEST(Navigator, ConversionsInterpolateTheTables) {
  const Navigator& nav = navigator();
  const ConversionTable& table = *nav.database().conversion(ModelId::ward, ModelId::blinn_phong);
  const ParamGrid& grid = grid_of(ModelId::ward);
  Material m = default_material(ModelId::ward);
  m.rho_s = Rgb(0.5, 1, 2);
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    m.params = grid.node_values(node);
    const Material fit = nav.convert(m, ModelId::blinn_phong);
    // n is interpolated in its log scale: exp(log(n)) rounds by up to |log(n)| ulps (10 at
    // n = 20000), more than EXPECT_DOUBLE_EQ's 4.
    EXPECT_NEAR(fit.params[0], table.nodes[node].params[0], 1e-14 * table.nodes[node].params[0]);
    EXPECT_TRUE((fit.rho_d == m.rho_d).all());
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_DOUBLE_EQ(fit.rho_s[ch],
                       std::min(kRhoSMax, m.rho_s[ch] * table.nodes[node].scale[ch]));
  }
  // Half way between two nodes in log(alpha): the fit's log(n) half way too.
  m.params = {std::sqrt(grid.axis(0)[0] * grid.axis(0)[1]), grid.axis(1)[0]};
  const double n0 = table.nodes[0].params[0], n1 = table.nodes[1].params[0];
  EXPECT_NEAR(nav.convert(m, ModelId::blinn_phong).params[0], std::sqrt(n0 * n1), 1e-9 * n0);
  const std::vector<Equivalent> eq = nav.equivalents(m);
  ASSERT_EQ(eq.size(), static_cast<std::size_t>(kModelCount - 1));
  for (const Equivalent& e : eq) EXPECT_DOUBLE_EQ(e.residual, nav.distance(m, e.material));
}

// The one definition of a conversion row: what the builder writes reads back field by field, and
// a row of another model's width is refused.
TEST(DatabaseFormat, ConversionRowsReadBackAsWritten) {
  const Conversion c{{0.12, 0.34}, Rgb(0.5, 0.75, 1.25), 0.0625, 0.03125};
  std::vector<float> row(db::conversion_columns(ModelId::ward));
  ASSERT_EQ(row.size(), 7u);
  db::write_conversion_row(c, ModelId::ward, row);
  EXPECT_THAT(row, ::testing::ElementsAre(0.12f, 0.34f, 0.5f, 0.75f, 1.25f, 0.0625f, 0.03125f));
  const Conversion back = db::read_conversion_row(row, ModelId::ward);
  EXPECT_THAT(back.params, ::testing::ElementsAre(double(0.12f), double(0.34f)));
  EXPECT_TRUE((back.scale == Rgb(0.5, 0.75, 1.25)).all());
  EXPECT_EQ(back.relative_error, 0.0625);
  EXPECT_EQ(back.image_distance, 0.03125);
  EXPECT_THROW(db::read_conversion_row(row, ModelId::blinn_phong), std::invalid_argument);
  EXPECT_THROW(db::write_conversion_row(c, ModelId::blinn_phong, std::span<float>(row).first(6)),
               std::invalid_argument);
}

TEST(Navigator, ClusteringIsDeterministicAndIndependentOfThreads) {
  NavigatorOptions four;
  four.threads = 4;
  const Navigator parallel = Navigator::open(test::NavigationDatabase::get().dir(), four);
  for (const Case& c : cases(1, 5)) {
    SCOPED_TRACE(describe(c));
    const auto first = navigator().neighbors(c.material, c.radius, Tab::models, 3);
    expect_same(first, navigator().neighbors(c.material, c.radius, Tab::models, 3));
    expect_same(first, parallel.neighbors(c.material, c.radius, Tab::models, 3));
  }
  expect_same(navigator().gallery(8), parallel.gallery(8));
  expect_same(navigator().gallery(8), navigator().gallery(8));
}

TEST(Navigator, GalleryReturnsDistinctMaterialsAtOneDistanceFromMatte) {
  for (int k : {1, 3, 8, 12}) {
    const std::vector<Neighbor> gallery = navigator().gallery(k);
    ASSERT_EQ(gallery.size(), static_cast<std::size_t>(k));
    std::set<std::string> distinct;
    std::set<ModelId> models;
    for (const Neighbor& n : gallery) {
      EXPECT_EQ(n.tab, Tab::gallery);
      EXPECT_EQ(n.label, model_info(n.material.model).name);
      distinct.insert(format_material_spec(n.material));
      models.insert(n.material.model);
    }
    EXPECT_EQ(distinct.size(), gallery.size());
    if (k >= 8) {
      EXPECT_GE(models.size(), 3u) << "the gallery should span several models";
    }
  }
  // Through neighbors(), distances are from the current material.
  const Material m = default_material(ModelId::he);
  for (const Neighbor& n : navigator().neighbors(m, 0.01, Tab::gallery, 4))
    EXPECT_NEAR(n.distance, navigator().distance(m, n.material), 1e-6);
}

// 1000 queries a thread (the load test of `brdfnav bench load` in small; it runs 10^5), fewer
// under ThreadSanitizer, which slows every query down by an order of magnitude.
#ifdef __SANITIZE_THREAD__
constexpr std::size_t kQueriesPerThread = 250;
#else
constexpr std::size_t kQueriesPerThread = 1000;
#endif

TEST(Navigator, ConcurrentQueriesGiveTheSerialAnswers) {
  const std::vector<Case> all = cases(1, 6);
  const std::size_t calls = kQueriesPerThread / std::size(kTabs);  // each call queries every tab
  const auto query = [&](const Case& c) {
    std::vector<Neighbor> out;
    for (Tab tab : kTabs) {
      const auto some = navigator().neighbors(c.material, c.radius, tab, 4);
      out.insert(out.end(), some.begin(), some.end());
    }
    return out;
  };
  std::vector<std::vector<Neighbor>> serial;
  for (const Case& c : all) serial.push_back(query(c));
  std::vector<std::vector<std::vector<Neighbor>>> parallel(8);
  {
    std::vector<std::jthread> threads;
    for (int t = 0; t < 8; ++t)
      threads.emplace_back([&, t] {
        // Each thread walks the cases from another start, so different queries overlap.
        for (std::size_t i = 0; i < calls; ++i)
          parallel[t].push_back(query(all[(i + t) % all.size()]));
      });
  }
  for (int t = 0; t < 8; ++t)
    for (std::size_t i = 0; i < calls; ++i)
      expect_same(parallel[t][i], serial[(i + t) % all.size()]);
}

TEST(Navigator, RejectsQueriesItCannotAnswer) {
  const Material m = default_material(ModelId::ward);
  // Below kMinRadius, single-precision noise in the embedding is no longer small against it.
  for (double radius : {0.0, -0.1, double(NAN), double(INFINITY), 0.5 * kMinRadius, 1e-300}) {
    try {
      navigator().neighbors(m, radius, Tab::lobe);
      ADD_FAILURE() << "radius " << radius;
    } catch (const NavigatorError& e) {
      EXPECT_THAT(e.what(), HasSubstr("radius"));
    }
  }
  EXPECT_THROW(navigator().neighbors(m, 0.01, Tab::models, 0), NavigatorError);
  EXPECT_THROW(navigator().gallery(0), NavigatorError);
  Material acescg = m;
  acescg.colorspace = "acescg";
  // The database's images are lin_rec709: every tab, the fits and distances refuse another space.
  for (Tab tab : {Tab::lobe, Tab::diffuse, Tab::specular, Tab::models, Tab::gallery}) {
    try {
      navigator().neighbors(acescg, 0.01, tab);
      ADD_FAILURE() << "tab " << int(tab) << " of an acescg material";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr("colorspace 'acescg'"));
      EXPECT_EQ(e.code(), ErrorCode::invalid_argument);  // the caller's, as a bad radius is
    }
  }
  EXPECT_THROW(navigator().equivalents(acescg), MaterialError);
  EXPECT_THROW(navigator().distance(acescg, m), MaterialError);
  Material bad = m;
  bad.params[0] = 7;
  EXPECT_THROW(navigator().neighbors(bad, 0.01, Tab::lobe), MaterialError);
  EXPECT_THROW(Navigator::open("/nonexistent/brdfnav-db"), DatabaseError);
}

// A database of two models: the others cannot be queried, and the models tab offers only what
// is there.
TEST(Navigator, AnswersOnlyForTheModelsOfItsDatabase) {
  const std::filesystem::path dir = test::NavigationDatabase::get().scratch() / "two";
  Profile profile = make_profile("smoke");
  profile.grids.erase(profile.grids.begin() + 2, profile.grids.end());  // blinn_phong, ward
  const EnvMap env = EnvMap::load(kDefaultEnvPath, {}, [](const std::string&) {});
  precompute_database({profile, dir, false, 0, {}}, env, Scene::sphere());
  const Navigator two = Navigator::open(dir);
  try {
    two.neighbors(default_material(ModelId::he), 0.01, Tab::lobe);
    ADD_FAILURE() << "queried a model the database does not hold";
  } catch (const NavigatorError& e) {
    EXPECT_THAT(e.what(), HasSubstr("model 'he' is not in the database"));
  }
  Material m = default_material(ModelId::ward);
  m.rho_s = Rgb::Constant(0.5);
  for (const Neighbor& n : two.neighbors(m, 0.02, Tab::models))
    EXPECT_EQ(n.material.model, ModelId::blinn_phong);
  ASSERT_EQ(two.equivalents(m).size(), 1u);
  for (const Neighbor& n : two.gallery(4)) EXPECT_LE(static_cast<int>(n.material.model), 1);
}

TEST(NavigationYaml, NeighbourListsReadBackWithTheirStableKeys) {
  const Material m = parse_material_spec("lafortune:cz=0.57,n=300,rho_d=0.1/0.2/0.3,rho_s=0.5");
  std::vector<Neighbor> all;
  for (Tab tab : kTabs) {
    const auto some = navigator().neighbors(m, 0.3, tab, 3);
    all.insert(all.end(), some.begin(), some.end());
  }
  const YAML::Node doc = YAML::Load(neighbors_to_yaml(all));
  ASSERT_TRUE(doc.IsMap());
  EXPECT_EQ(doc.size(), 1u);
  const YAML::Node list = doc["neighbors"];
  ASSERT_TRUE(list.IsSequence());
  ASSERT_EQ(list.size(), all.size());
  bool some_flag = false;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const YAML::Node item = list[i];
    std::set<std::string> keys;
    for (const auto& kv : item) keys.insert(kv.first.as<std::string>());
    EXPECT_EQ(keys, (std::set<std::string>{"tab", "label", "words", "change", "opposite",
                                           "distance", "flags", "material"}));
    EXPECT_EQ(item["tab"].as<std::string>(), tab_name(all[i].tab));
    EXPECT_EQ(item["label"].as<std::string>(), all[i].label);
    EXPECT_EQ(item["words"].as<std::string>(), all[i].words);
    EXPECT_EQ(item["change"].as<std::string>(), all[i].change);
    EXPECT_EQ(item["opposite"].as<int>(), all[i].opposite);
    EXPECT_EQ(item["distance"].as<double>(), all[i].distance);
    ASSERT_TRUE(item["flags"].IsSequence());
    std::vector<std::string> flags;
    if (all[i].at_boundary) flags.push_back("at_boundary");
    if (all[i].clamped) flags.push_back("clamped");
    if (all[i].beyond_radius) flags.push_back("beyond_radius");
    some_flag |= !flags.empty();
    EXPECT_EQ(item["flags"].as<std::vector<std::string>>(), flags);
    EXPECT_FALSE(item["material"]["brdfnav_material"]);
    EXPECT_TRUE(same(material_from_node(item["material"], "list", false), all[i].material));
  }
  EXPECT_TRUE(some_flag) << "radius 0.3 should reach some boundary";
  EXPECT_EQ(neighbors_to_yaml({}), "neighbors: []\n");
}

// The JSON forms: a material reads back through the material reader (JSON is YAML's flow
// syntax), and a neighbour carries its fields and flags in their YAML names.
TEST(NavigationJson, AMaterialReadsBackAndANeighbourKeepsItsFields) {
  Material m = default_material(ModelId::he);
  m.params = {0.3, 7.5, 1.9};
  m.rho_d = Rgb(0.1, 0.2, 0.3);
  m.rho_s = Rgb(0.4, 0.5, 0.6);
  const nlohmann::ordered_json j = material_json(m);
  EXPECT_EQ(j.at("model"), "he");
  EXPECT_EQ(j.at("params").begin().key(), "sigma");  // the model's parameter order
  const Material back = material_from_node(YAML::Load(j.dump()), "json", false);
  EXPECT_TRUE(same(back, m));
  Neighbor n{.tab = Tab::models, .label = "ward", .material = m, .distance = 0.03};
  n.clamped = n.beyond_radius = true;
  n.words = "as Ward";
  const nlohmann::ordered_json nj = neighbor_json(n);
  EXPECT_EQ(nj.at("tab"), "models");
  EXPECT_EQ(nj.at("flags"), nlohmann::ordered_json::parse(R"(["clamped", "beyond_radius"])"));
  EXPECT_EQ(nj.at("opposite"), -1);
  EXPECT_EQ(nj.at("material"), j);
  EXPECT_THAT(neighbors_to_yaml({n}), HasSubstr("flags: [clamped, beyond_radius]"));
}

TEST(NavigationYaml, AnExportReadsBackAsItsMaterial) {
  const Navigator& nav = navigator();
  const Material m = parse_material_spec("he:sigma=0.3,tau=9,eta=2,rho_d=0.1/0.2/0.3,rho_s=0.7");
  const std::string text = export_to_yaml(nav, m);
  EXPECT_TRUE(same(parse_material_yaml(text, "chosen.yaml"), m));
  const YAML::Node doc = YAML::Load(text);
  EXPECT_EQ(doc["brdfnav_material"].as<int>(), 1);
  const YAML::Node p = doc["provenance"];
  EXPECT_EQ(p["manifest_sha1"].as<std::string>(),
            file_sha1(nav.database().dir() / "manifest.yaml"));
  EXPECT_EQ(p["environment"]["path"].as<std::string>(), nav.database().manifest().env_path);
  EXPECT_EQ(p["environment"]["pixel_sha1"].as<std::string>(),
            nav.database().manifest().env_pixel_sha1);
  EXPECT_THAT(p["metric"].as<std::string>(), HasSubstr("cube-root RMS"));
  const YAML::Node eq = doc["equivalents"];
  ASSERT_EQ(eq.size(), static_cast<std::size_t>(kModelCount - 1));
  for (const Equivalent& e : nav.equivalents(m)) {
    const YAML::Node item = eq[std::string(model_info(e.material.model).name)];
    ASSERT_TRUE(item) << model_info(e.material.model).name;
    EXPECT_EQ(item["residual"].as<double>(), e.residual);
    EXPECT_TRUE(same(material_from_node(item["material"], "chosen.yaml", false), e.material));
  }
  // The export keys are accepted at the top of a file only.
  EXPECT_THROW(material_from_node(doc, "chosen.yaml", true), MaterialError);
  YAML::Node nested = YAML::Clone(eq["ward"]["material"]);
  nested["provenance"] = "somewhere";
  EXPECT_THROW(material_from_node(nested, "chosen.yaml", false), MaterialError);
  EXPECT_THROW(parse_material_yaml(text + "extra: 1\n", "chosen.yaml"), MaterialError);
}

}  // namespace
}  // namespace brdfnav
