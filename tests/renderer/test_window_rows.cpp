// The quadrature window's rows (renderer/src/window_rows.h): every node whose cell meets the
// polygon is in a segment, the convex scan agrees on convex polygons, a curved sliver is not
// filled between its ends, padding (exactly the dilation of the unpadded cells) and rows wider
// than the grid.
#include "window_rows.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

namespace brdfnav {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Cells = std::set<std::pair<int, int>>;  // (row, unwrapped column)

Cells cells_of(const std::vector<RowSegment>& segments) {
  Cells cells;
  for (const RowSegment& s : segments)
    for (int x = s.x0; x <= s.x1; ++x) cells.insert({s.row, x});
  return cells;
}

// Segments sorted by row then column, disjoint and not adjacent (adjacent ones are merged).
void expect_ordered_and_disjoint(const std::vector<RowSegment>& segments) {
  for (std::size_t i = 1; i < segments.size(); ++i) {
    const RowSegment &a = segments[i - 1], &b = segments[i];
    ASSERT_LE(a.row, b.row);
    if (a.row == b.row) {
      EXPECT_GT(b.x0, a.x1 + 1) << "row " << a.row;
    }
  }
}

bool inside(const std::vector<Vec2>& p, const Vec2& q) {  // even-odd rule, p closed
  bool in = false;
  for (std::size_t k = 0; k + 1 < p.size(); ++k) {
    const Vec2 &a = p[k], &b = p[k + 1];
    if ((a.y() > q.y()) != (b.y() > q.y()) &&
        q.x() < a.x() + (q.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x()))
      in = !in;
  }
  return in;
}

// Cells of points inside the polygon and on its edges, sampled densely.
Cells sampled_cells(const std::vector<Vec2>& p, std::mt19937_64& rng) {
  Vec2 lo = p[0], hi = p[0];
  for (const Vec2& v : p) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  std::uniform_real_distribution<double> u(0, 1);
  Cells cells;
  auto add = [&](const Vec2& q) {
    cells.insert({static_cast<int>(std::floor(q.y())), static_cast<int>(std::floor(q.x()))});
  };
  for (int i = 0; i < 200000; ++i) {
    const double ux = u(rng), uy = u(rng);  // in this order under every compiler
    const Vec2 q(lo.x() + ux * (hi.x() - lo.x()), lo.y() + uy * (hi.y() - lo.y()));
    if (inside(p, q)) add(q);
  }
  for (std::size_t k = 0; k + 1 < p.size(); ++k)
    for (int i = 0; i <= 400; ++i) add(p[k] + (p[k + 1] - p[k]) * (i / 400.0));
  return cells;
}

// A closed arc of `width` around a circle of `radius` centred at c from angle a0 to a1.
std::vector<Vec2> arc(const Vec2& c, double radius, double width, double a0, double a1, int n) {
  std::vector<Vec2> p;
  for (int i = 0; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    p.push_back(c + (radius + width / 2) * Vec2(std::cos(a), std::sin(a)));
  }
  for (int i = n; i >= 0; --i) {
    const double a = a0 + (a1 - a0) * i / n;
    p.push_back(c + (radius - width / 2) * Vec2(std::cos(a), std::sin(a)));
  }
  p.push_back(p.front());
  return p;
}

const RowGrid kGrid{256, 128, kPi / 128};

TEST(WindowRows, EveryCellMeetingARandomPolygonIsCovered) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    // Star-shaped around a centre, hence simple; columns past the width on purpose.
    const double ux = u(rng), uy = u(rng);
    const Vec2 centre(240 + 20 * ux, 30 + 60 * uy);
    std::vector<Vec2> p;
    const int n = 5 + trial;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * kPi * (k + 0.8 * u(rng)) / n, r = 3 + 25 * u(rng);
      p.push_back(centre + r * Vec2(std::cos(a), 0.7 * std::sin(a)));
    }
    p.push_back(p.front());
    std::vector<RowSegment> segments;
    PolygonScratch scratch;
    polygon_segments(p.data(), n, 0, 1, kGrid, segments, scratch);
    expect_ordered_and_disjoint(segments);
    const Cells covered = cells_of(segments);
    for (const auto& cell : sampled_cells(p, rng))
      ASSERT_TRUE(covered.count(cell)) << "trial " << trial << ": row " << cell.first << ", column "
                                       << cell.second << " left out";
  }
}

TEST(WindowRows, TheConvexScanGivesTheSameRowsOnConvexPolygons) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    // Ellipses as the quadrature outlines them, columns past the width on some.
    const double ux = u(rng), uy = u(rng);
    const Vec2 centre(200 + 100 * ux, 20 + 80 * uy);
    const double a = 0.5 + 30 * u(rng), b = 0.5 + 10 * u(rng), turn = kPi * u(rng);
    std::vector<Vec2> p;
    for (int k = 0; k < 32; ++k) {
      const double t = 2 * kPi * k / 32;
      const Vec2 e(a * std::cos(t), b * std::sin(t));
      p.push_back(centre + Vec2(std::cos(turn) * e.x() - std::sin(turn) * e.y(),
                                std::sin(turn) * e.x() + std::cos(turn) * e.y()));
    }
    p.push_back(p.front());
    std::vector<RowSegment> convex, general;
    PolygonScratch scratch;
    convex_polygon_rows(p.data(), 32, kGrid, convex, scratch);
    polygon_segments(p.data(), 32, 0, 1, kGrid, general, scratch);
    ASSERT_EQ(convex.size(), general.size()) << "trial " << trial;
    for (std::size_t i = 0; i < convex.size(); ++i) {
      EXPECT_EQ(convex[i].row, general[i].row);
      EXPECT_EQ(convex[i].x0, general[i].x0);
      EXPECT_EQ(convex[i].x1, general[i].x1);
    }
  }
}

TEST(WindowRows, ACurvedSliverIsNotFilledBetweenItsEnds) {
  // Half a ring, 2 nodes thick and 120 across: the rows near its middle cross it twice.
  const std::vector<Vec2> p = arc(Vec2(128, 64), 60, 2, 0, kPi, 200);
  std::vector<RowSegment> segments;
  PolygonScratch scratch;
  polygon_segments(p.data(), static_cast<int>(p.size()) - 1, 0, 1, kGrid, segments, scratch);
  expect_ordered_and_disjoint(segments);
  std::mt19937_64 rng(1);
  const Cells covered = cells_of(segments), met = sampled_cells(p, rng);
  for (const auto& cell : met) ASSERT_TRUE(covered.count(cell));
  int twice = 0;
  for (std::size_t i = 1; i < segments.size(); ++i) twice += segments[i].row == segments[i - 1].row;
  EXPECT_GT(twice, 40);
  // One hull per row would hold about 60 x 120 / 2 nodes; the ring's cells are about 400.
  EXPECT_LT(covered.size(), 2 * met.size());
}

TEST(WindowRows, PaddingAddsRowsAndColumnsAround) {
  const std::vector<Vec2> p{
      {100.2, 64.2}, {100.8, 64.2}, {100.8, 64.8}, {100.2, 64.8}, {100.2, 64.2}};
  std::vector<RowSegment> segments;
  PolygonScratch scratch;
  polygon_segments(p.data(), 4, 2, 0.1, kGrid, segments, scratch);
  ASSERT_EQ(segments.size(), 5u);  // rows 62..66
  for (const RowSegment& s : segments) {
    // At least 2 columns either side (more toward the poles, where columns are narrower).
    EXPECT_LE(s.x0, 98);
    EXPECT_GE(s.x1, 102);
  }
  EXPECT_EQ(segments.front().row, 62);
  EXPECT_EQ(segments.back().row, 66);
}

// The padded segments cover exactly the cells within `pad` rows and pad / sin(theta) columns of a
// cell of the unpadded ones, sin(theta) the smallest over the rows the padding spans: curved
// slivers, whose rows hold several segments and whose padding merges some of them.
TEST(WindowRows, PaddingIsTheDilationOfTheUnpaddedCells) {
  constexpr int kPad = 2;
  constexpr double kMinSin = 0.05;
  for (int trial = 0; trial < 12; ++trial) {
    const std::vector<Vec2> p =
        arc({128, 64}, 20 + 4 * trial, 1.5 + 0.5 * trial, 0.3 * trial, 0.3 * trial + 4.5, 64);
    const int n = static_cast<int>(p.size()) - 1;
    std::vector<RowSegment> unpadded, padded;
    PolygonScratch scratch;
    polygon_segments(p.data(), n, 0, kMinSin, kGrid, unpadded, scratch);
    polygon_segments(p.data(), n, kPad, kMinSin, kGrid, padded, scratch);
    expect_ordered_and_disjoint(padded);
    auto columns = [&](int y) {
      auto sin_at = [&](int edge) { return std::sin(edge * kGrid.node_angle); };
      const double s =
          std::min(sin_at(std::max(y - kPad, 0)), sin_at(std::min(y + 1 + kPad, kGrid.height)));
      return static_cast<int>(std::ceil(kPad / std::max(s, kMinSin)));
    };
    Cells expected;
    for (const auto& [row, x] : cells_of(unpadded))
      for (int y = std::max(0, row - kPad); y <= std::min(kGrid.height - 1, row + kPad); ++y)
        for (int dx = -columns(y); dx <= columns(y); ++dx) expected.insert({y, x + dx});
    EXPECT_EQ(cells_of(padded), expected) << "trial " << trial;
  }
}

TEST(WindowRows, ARowWiderThanTheGridIsOneWholeRow) {
  const std::vector<Vec2> p{{-10, 10.5}, {300, 10.5}, {300, 11.5}, {-10, 11.5}, {-10, 10.5}};
  std::vector<RowSegment> segments;
  PolygonScratch scratch;
  polygon_segments(p.data(), 4, 0, 1, kGrid, segments, scratch);
  ASSERT_EQ(segments.size(), 2u);
  for (const RowSegment& s : segments) EXPECT_EQ(s.x1 - s.x0 + 1, kGrid.width);
}

}  // namespace
}  // namespace brdfnav
