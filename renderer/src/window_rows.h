// The nodes of the quadrature's window (quadrature.h) as segments of lat-long grid rows, from a
// polygon around the window in grid coordinates.
#pragma once

#include <brdfnav/core/math.h>

#include <vector>

namespace brdfnav {

// Nodes x0..x1 of grid row `row`, columns unwrapped (x0 may be negative or past the width; the
// quadrature wraps them).
struct RowSegment {
  int row, x0, x1;
};

// Per-thread scratch space of polygon_segments().
struct PolygonScratch {
  std::vector<RowSegment> pieces, merged, padded, sorted;
  std::vector<std::pair<int, double>> crossings;  // (row, x) of the edges at rows' centre lines
  std::vector<std::pair<int, double>> sorted_crossings;
  std::vector<int> row_ends;     // per row: where its segments end, sorted
  std::vector<double> edge_sin;  // sin(theta) at the rows' edges
};

// The grid the segments index: `width` x `height` nodes of `node_angle` radians.
struct RowGrid {
  int width, height;
  double node_angle;
};

// Appends to `out`, row by row and left to right, disjoint segments that hold every node whose
// cell [x, x + 1) x [y, y + 1) meets the closed polygon p[0..n] (p[n] = p[0]; grid coordinates,
// columns unwrapped, no self-intersections), then `pad` rows either side and `pad` nodes' angle
// wider (pad / sin(theta) columns, with sin(theta) at least `min_sin`). A row that the polygon
// crosses more than once gets a segment per crossing: a curved sliver does not fill the rows
// between its ends.
void polygon_segments(const Vec2* p, int n, int pad, double min_sin, const RowGrid& grid,
                      std::vector<RowSegment>& out, PolygonScratch& scratch);

// The same for a convex polygon without padding (one segment per row, from the leftmost to the
// rightmost point of the edges crossing it), in a single pass.
void convex_polygon_rows(const Vec2* p, int n, const RowGrid& grid, std::vector<RowSegment>& out,
                         PolygonScratch& scratch);

}  // namespace brdfnav
