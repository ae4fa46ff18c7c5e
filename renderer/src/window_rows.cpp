#include "window_rows.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace brdfnav {

namespace {

// Sorts `v` by row_of(element), then by `less` within each row, through `sorted`: by counting
// the rows (a window's pieces and crossings are many over few rows, and a comparison sort of them
// was a tenth of a sliver's time), then a sort within each row.
template <typename T, typename RowOf, typename Less>
void sort_rows(std::vector<T>& v, std::vector<T>& sorted, std::vector<int>& row_ends,
               RowOf&& row_of, Less&& less) {
  if (v.empty()) return;
  const auto [lo, hi] = std::minmax_element(
      v.begin(), v.end(), [&](const T& a, const T& b) { return row_of(a) < row_of(b); });
  const int first = row_of(*lo), rows = row_of(*hi) - first + 1;
  row_ends.assign(rows + 1, 0);
  for (const T& e : v) ++row_ends[row_of(e) - first + 1];
  for (int r = 0; r < rows; ++r) row_ends[r + 1] += row_ends[r];  // now where each row starts
  sorted.resize(v.size());
  for (const T& e : v) sorted[row_ends[row_of(e) - first]++] = e;  // ... ends
  for (int r = 0, begin = 0; r < rows; begin = row_ends[r++])
    std::sort(sorted.begin() + begin, sorted.begin() + row_ends[r], less);
  v.swap(sorted);
}

// Segments of a row in order of their first column. Pieces of a row with the same x0 may come in
// any order: merge_rows() then keeps the largest x1 whatever the order.
bool by_first_column(const RowSegment& a, const RowSegment& b) {
  return a.x0 < b.x0;
}

// Segments by row, then by first column.
void sort_rows(std::vector<RowSegment>& v, PolygonScratch& s) {
  sort_rows(
      v, s.sorted, s.row_ends, [](const RowSegment& a) { return a.row; }, by_first_column);
}

// Appends `pieces` (sorted) to `out` with the overlapping and adjacent ones of a row merged; a
// row whose segments reach across the grid's width (they would wrap onto each other) becomes
// one segment of the whole row.
void merge_rows(const std::vector<RowSegment>& pieces, int width, std::vector<RowSegment>& out) {
  const std::size_t first = out.size();
  for (const RowSegment& piece : pieces) {
    if (out.size() > first && out.back().row == piece.row && piece.x0 <= out.back().x1 + 1)
      out.back().x1 = std::max(out.back().x1, piece.x1);
    else
      out.push_back(piece);
  }
  // Rows reaching across the width, from the last backwards (erasing keeps earlier indices).
  for (std::size_t end = out.size(); end > first;) {
    std::size_t begin = end - 1;
    while (begin > first && out[begin - 1].row == out[end - 1].row) --begin;
    if (out[end - 1].x1 - out[begin].x0 + 1 >= width) {
      out[begin].x1 = out[begin].x0 + width - 1;
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(begin + 1),
                out.begin() + static_cast<std::ptrdiff_t>(end));
    }
    end = begin;
  }
}

// Calls row(y, a, b, crossing) for every grid row y in [0, height) that an edge of the closed
// polygon p[0..n] crosses: a and b are the edge's x where it enters and leaves the row, crossing
// its x on the row's centre line, or NaN where it does not cross that line (half open, so that a
// vertex on the line counts once).
template <typename Row>
void edge_rows(const Vec2* p, int n, int height, Row&& row) {
  for (int k = 0; k < n; ++k) {
    const Vec2 &e0 = p[k], &e1 = p[k + 1];
    const double lo_y = std::min(e0.y(), e1.y()), hi_y = std::max(e0.y(), e1.y());
    const double dy = e1.y() - e0.y();
    auto x_at = [&](double y) {
      return dy == 0 ? e0.x() : e0.x() + (y - e0.y()) / dy * (e1.x() - e0.x());
    };
    const int first = std::max(0, static_cast<int>(std::floor(lo_y)));
    const int last = std::min(height - 1, static_cast<int>(std::floor(hi_y)));
    for (int y = first; y <= last; ++y) {
      const double centre = y + 0.5;
      row(y, x_at(std::max<double>(y, lo_y)), x_at(std::min(y + 1.0, hi_y)),
          (e0.y() <= centre) != (e1.y() <= centre) ? x_at(centre) : std::nan(""));
    }
  }
}

int floor_int(double x) {
  return static_cast<int>(std::floor(x));
}

}  // namespace

void convex_polygon_rows(const Vec2* p, int n, const RowGrid& grid, std::vector<RowSegment>& out,
                         PolygonScratch& s) {
  double y_min = p[0].y(), y_max = p[0].y();
  for (int k = 1; k < n; ++k) y_min = std::min(y_min, p[k].y()), y_max = std::max(y_max, p[k].y());
  const int y0 = std::max(0, floor_int(y_min)), y1 = std::min(grid.height - 1, floor_int(y_max));
  s.pieces.assign(std::max(0, y1 - y0 + 1), {0, INT_MAX, INT_MIN});
  edge_rows(p, n, grid.height, [&](int y, double a, double b, double) {
    RowSegment& row = s.pieces[y - y0];
    row.x0 = std::min(row.x0, floor_int(std::min(a, b)));
    row.x1 = std::max(row.x1, floor_int(std::max(a, b)));
  });
  for (int y = y0; y <= y1; ++y) {
    const RowSegment& row = s.pieces[y - y0];
    if (row.x0 <= row.x1) out.push_back({y, row.x0, std::min(row.x1, row.x0 + grid.width - 1)});
  }
}

void polygon_segments(const Vec2* p, int n, int pad, double min_sin, const RowGrid& grid,
                      std::vector<RowSegment>& out, PolygonScratch& s) {
  s.pieces.clear();
  s.crossings.clear();
  edge_rows(p, n, grid.height, [&](int y, double a, double b, double crossing) {
    s.pieces.push_back({y, floor_int(std::min(a, b)), floor_int(std::max(a, b))});
    if (!std::isnan(crossing)) s.crossings.emplace_back(y, crossing);
  });
  // Inside the polygon on a centre line: between the 1st and 2nd crossing, the 3rd and 4th...
  // Every node whose cell meets the polygon is on an edge's part or on such a span.
  using Crossing = std::pair<int, double>;
  sort_rows(
      s.crossings, s.sorted_crossings, s.row_ends, [](const Crossing& c) { return c.first; },
      [](const Crossing& a, const Crossing& b) { return a.second < b.second; });
  for (std::size_t i = 0; i + 1 < s.crossings.size();) {
    const auto [row, x0] = s.crossings[i];
    const auto [next_row, x1] = s.crossings[i + 1];
    if (next_row != row) {  // rounding left a row with an odd count
      ++i;
      continue;
    }
    s.pieces.push_back({row, floor_int(x0), floor_int(x1)});
    i += 2;
  }
  sort_rows(s.pieces, s);
  if (pad == 0) {
    merge_rows(s.pieces, grid.width, out);
    return;
  }
  s.merged.clear();
  merge_rows(s.pieces, grid.width, s.merged);
  s.padded.clear();
  if (s.merged.empty()) return;
  // Columns are narrower by sin(theta): per row, the smallest over the rows the padding spans.
  const int y_lo = std::max(0, s.merged.front().row - pad);
  const int y_hi = std::min(grid.height - 1, s.merged.back().row + pad);
  // sin(theta) at the rows' edges from y_lo - pad to y_hi + 1 + pad, once each.
  const int edge_lo = std::max(y_lo - pad, 0), edge_hi = std::min(y_hi + 1 + pad, grid.height);
  s.edge_sin.resize(edge_hi - edge_lo + 1);
  for (int e = edge_lo; e <= edge_hi; ++e) s.edge_sin[e - edge_lo] = std::sin(e * grid.node_angle);
  // Row by row, the merged segments of the rows within `pad` of it, widened: `merged` is sorted
  // by row, so they are a sliding range of it; only the few of one row need sorting.
  std::size_t begin = 0, end = 0;
  for (int y = y_lo; y <= y_hi; ++y) {
    while (begin < s.merged.size() && s.merged[begin].row < y - pad) ++begin;
    while (end < s.merged.size() && s.merged[end].row <= y + pad) ++end;
    const double sin_theta = std::min(s.edge_sin[std::max(y - pad, 0) - edge_lo],
                                      s.edge_sin[std::min(y + 1 + pad, grid.height) - edge_lo]);
    const int columns = static_cast<int>(std::ceil(pad / std::max(sin_theta, min_sin)));
    const std::size_t first = s.padded.size();
    for (std::size_t i = begin; i < end; ++i)
      s.padded.push_back({y, s.merged[i].x0 - columns, s.merged[i].x1 + columns});
    std::sort(s.padded.begin() + static_cast<std::ptrdiff_t>(first), s.padded.end(),
              by_first_column);
  }
  merge_rows(s.padded, grid.width, out);
}

}  // namespace brdfnav
