// What the per-pixel quadrature (quadrature.h) keeps from pixel to pixel: each thread's scratch
// space, with the sines and cosines of its grid's rows and columns, and the angles of the
// windows' outlines, shared by all.
#pragma once

#include "window_rows.h"

#include <brdfnav/core/math.h>

#include <cmath>
#include <vector>

namespace brdfnav {

// (sin, cos) of the polar angle of each row's centre and of the azimuth of each column's centre of
// one grid of pieces, each computed on first use: a thread's successive pixels mostly share their
// grid, and the sincos of every segment's row and first column were 4% of a Ward sliver's time.
class GridAngles {
 public:
  // Forgets the angles if the grid is not that of the last call.
  void use(int width, int height) {
    if (width == width_ && height == height_) return;
    width_ = width, height_ = height;
    rows_.assign(height, Vec2::Constant(std::nan("")));
    columns_.assign(width, Vec2::Constant(std::nan("")));
  }
  const Vec2& row(int y) { return known(rows_[y], (y + 0.5) * (kPi / height_)); }
  const Vec2& column(int x) { return known(columns_[x], 2 * kPi * ((x + 0.5) / width_ - 0.5)); }

 private:
  static const Vec2& known(Vec2& v, double angle) {
    if (std::isnan(v.x())) v = Vec2(std::sin(angle), std::cos(angle));
    return v;
  }
  int width_ = 0, height_ = 0;
  std::vector<Vec2> rows_, columns_;
};

// Per-thread scratch space of the quadrature, reused from pixel to pixel.
struct QuadratureScratch {
  std::vector<RowSegment> segments;  // the window's nodes, row by row, left to right
  // For kernels that evaluate a window's nodes at once (Ward's), a chunk of them at a time: per
  // node K, weight and the centroid, x then y then z, world and local.
  std::vector<double> kernel;
  std::vector<Rgb> weight;
  std::vector<double> directions;
  PolygonScratch polygon;
  GridAngles angles;  // of the grid of pieces (level 0 split)
};

// (cos t, sin t) at t = 2 pi j / n for j = 0..n, for the n of the windows' outlines (multiples of
// 4 up to kMaxOutlineAngles): computed once, as std::cos and std::sin of the same t, rather than
// per pixel.
inline constexpr int kMaxOutlineAngles = 256;
inline const Vec2* outline_angles(int n) {
  static const std::vector<std::vector<Vec2>> tables = [] {
    std::vector<std::vector<Vec2>> t(kMaxOutlineAngles / 4 + 1);
    for (int m = 4; m <= kMaxOutlineAngles; m += 4)
      for (int j = 0; j <= m; ++j) {
        const double angle = 2 * kPi * j / m;
        t[m / 4].push_back(Vec2(std::cos(angle), std::sin(angle)));
      }
    return t;
  }();
  return tables[n / 4].data();
}

}  // namespace brdfnav
