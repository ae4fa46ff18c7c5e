// Exact steps (ExactSteps, navigator.h): the navigator moves each offer along its path until a
// distance it is handed, a render's in the server, is at eps. Here that distance is a known
// function of the embedded one, so every answer can be checked without a renderer: a steeper
// metric, one with a sharp turn, and one whose whole path stays inside the sphere.
#include "navigator/navigator_fixture.h"

#include <brdfnav/navigator/navigator.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <set>

namespace brdfnav {
namespace {

using test::random_material;

using test::navigator;

struct Probe {
  ExactSteps steps;
  int calls = 0;
};

// ExactSteps whose distance is `shape` of the embedded distance from `current`, counting calls.
std::unique_ptr<Probe> probe(const Material& current, std::function<double(double)> shape) {
  auto p = std::make_unique<Probe>();
  p->steps.distance = [current, shape, calls = &p->calls](const Material& m) {
    ++*calls;
    return shape(navigator().distance(current, m));
  };
  return p;
}

bool flagged(const Neighbor& n) {
  return n.at_boundary || n.clamped || n.beyond_radius;
}

std::vector<Material> materials(int per_model) {
  std::mt19937_64 rng(11);
  std::vector<Material> out;
  for (const ModelInfo& info : models())
    for (int i = 0; i < per_model; ++i)
      out.push_back(
          random_material(info.id, navigator().database().embedding(info.id)->grid(), rng));
  return out;
}

constexpr Tab kTabs[] = {Tab::lobe, Tab::diffuse, Tab::specular, Tab::models};

// A metric 25% steeper than the embedding's: without exact steps every offer is 25% beyond eps;
// with them every unflagged offer is within the tolerance, reports the distance the probe gives
// its material, and cost at most `renders` probes (the models tab one more: its fit's). A model
// whose fit the steeper metric puts beyond eps offers that fit, flagged, once.
TEST(ExactSteps, EveryOfferMovesToTheExactRadius) {
  const double radius = 0.02;
  int moved = 0;
  for (const Material& m : materials(2)) {
    SCOPED_TRACE(format_material_spec(m));
    for (Tab tab : kTabs) {
      const auto p = probe(m, [](double d) { return 1.25 * d; });
      const std::vector<Neighbor> plain = navigator().neighbors(m, radius, tab);
      const std::vector<Neighbor> exact = navigator().neighbors(m, radius, tab, 8, &p->steps);
      EXPECT_LE(p->calls, static_cast<int>(plain.size()) * (p->steps.renders + 1));
      if (tab != Tab::models) ASSERT_EQ(exact.size(), plain.size()) << tab_name(tab);
      std::set<std::string> beyond;  // models whose fit is offered: once each
      for (std::size_t i = 0; i < exact.size(); ++i) {
        const Neighbor& n = exact[i];
        if (tab != Tab::models) EXPECT_EQ(n.label, plain[i].label);
        if (n.beyond_radius) {
          EXPECT_TRUE(beyond.insert(n.label).second) << n.label;
          EXPECT_GE(n.distance, radius) << n.label;
        }
        if (flagged(n)) continue;
        EXPECT_NEAR(n.distance, 1.25 * navigator().distance(m, n.material), 1e-6) << n.label;
        EXPECT_NEAR(n.distance / radius, 1, p->steps.tolerance) << tab_name(tab) << n.label;
        ++moved;
      }
    }
  }
  EXPECT_GT(moved, 100);
}

// A metric that is flat, then turns sharply (as a Lafortune lobe across cz = 1/sqrt(3)): the
// embedding's hit lands far beyond eps, and the bracket still closes on eps.
TEST(ExactSteps, ASharpTurnIsBracketed) {
  const double radius = 0.02;
  const auto shape = [radius](double d) {
    return d < 0.7 * radius ? 0.3 * d : 0.21 * radius + 10 * (d - 0.7 * radius);
  };
  int moved = 0;
  for (const Material& m : materials(2)) {
    SCOPED_TRACE(format_material_spec(m));
    const auto p = probe(m, shape);
    for (const Neighbor& n : navigator().neighbors(m, radius, Tab::lobe, 8, &p->steps)) {
      if (flagged(n)) continue;
      EXPECT_NEAR(n.distance / radius, 1, p->steps.tolerance) << n.label;
      ++moved;
    }
  }
  EXPECT_GT(moved, 20);
}

// A metric under which no path leaves the sphere: every offer ends at its grid end, flagged,
// with the distance the probe gives there; a probe of nothing is refused.
TEST(ExactSteps, APathThatStaysInsideEndsAtItsEndFlagged) {
  const double radius = 0.02;
  // Rising, and rising then falling beyond the embedding's hit (a path whose distance is not
  // monotonic, as across Lafortune's kink): either way the search goes on to the path's end.
  const std::function<double(double)> shapes[] = {
      [](double d) { return 1e-3 * d; },
      [radius](double d) { return 1e-3 * (d <= radius ? d : std::max(0.0, 2 * radius - d)); }};
  for (const auto& shape : shapes)
    for (const Material& m : materials(1)) {
      SCOPED_TRACE(format_material_spec(m));
      const auto p = probe(m, shape);
      for (const Neighbor& n : navigator().neighbors(m, radius, Tab::lobe, 8, &p->steps)) {
        EXPECT_TRUE(n.at_boundary) << n.label;
        EXPECT_LT(n.distance, radius) << n.label;
      }
    }
  const ExactSteps nothing;
  const Material m = navigator().start_material();
  EXPECT_THROW(navigator().neighbors(m, radius, Tab::lobe, 8, &nothing), NavigatorError);
}

}  // namespace
}  // namespace brdfnav
