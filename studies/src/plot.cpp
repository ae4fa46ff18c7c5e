#include <brdfnav/studies/plot.h>

#include <brdfnav/core/atomic_file.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace brdfnav {

namespace {

namespace IBA = OIIO::ImageBufAlgo;

constexpr const char* kFont = "DejaVuSans";
constexpr std::array<float, 3> kInk{0.1f, 0.1f, 0.1f};

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
  void pad() {
    if (!(hi > lo)) lo -= 0.5, hi += 0.5;
  }
};

// "Nice" tick step: 1, 2 or 5 times a power of ten, giving about `target` ticks.
double tick_step(const Range& r, int target) {
  const double raw = (r.hi - r.lo) / target;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

std::string tick_text(double v, bool log_axis) {
  char buf[32];
  if (log_axis)
    std::snprintf(buf, sizeof buf, "1e%d", int(std::lround(v)));
  else
    std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

void text(OIIO::ImageBuf& img, int x, int y, const std::string& s, int size,
          IBA::TextAlignX ax = IBA::TextAlignX::Left,
          IBA::TextAlignY ay = IBA::TextAlignY::Baseline, std::array<float, 3> ink = kInk) {
  IBA::render_text(img, x, y, s, size, kFont, ink, ax, ay);
}

void write_png(OIIO::ImageBuf& img, const std::filesystem::path& png) {
  img.set_write_format(OIIO::TypeDesc::UINT8);
  AtomicOutput out(png);
  if (!img.write(out.temp_path().string()))
    throw std::runtime_error(png.string() + ": cannot write image: " + img.geterror());
  out.commit();
}

}  // namespace

std::array<float, 3> plot_color(std::size_t index) {
  // Tableau 10, then black and a sea green (the demo plots 12 settings).
  static constexpr std::array<std::array<float, 3>, 12> kColors{{{0.12f, 0.47f, 0.71f},
                                                                 {1.00f, 0.50f, 0.05f},
                                                                 {0.17f, 0.63f, 0.17f},
                                                                 {0.84f, 0.15f, 0.16f},
                                                                 {0.58f, 0.40f, 0.74f},
                                                                 {0.55f, 0.34f, 0.29f},
                                                                 {0.89f, 0.47f, 0.76f},
                                                                 {0.50f, 0.50f, 0.50f},
                                                                 {0.74f, 0.74f, 0.13f},
                                                                 {0.09f, 0.75f, 0.81f},
                                                                 {0.00f, 0.00f, 0.00f},
                                                                 {0.40f, 0.76f, 0.65f}}};
  return kColors[index % kColors.size()];
}

void write_line_plot(const std::filesystem::path& png, const PlotSpec& spec,
                     const std::vector<PlotSeries>& series) {
  const auto ty = [&](double y) { return spec.log_y ? std::log10(y) : y; };
  const auto usable = [&](double y) { return std::isfinite(y) && (!spec.log_y || y > 0); };
  Range xr, yr;
  for (const PlotSeries& s : series)
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (usable(s.y[i])) xr.add(s.x[i]), yr.add(ty(s.y[i]));
  // A log axis shows at most kLogDecades decades below the maximum; lower values sit on the floor.
  constexpr double kLogDecades = 6;
  if (spec.log_y) yr.lo = std::max(yr.lo, yr.hi - kLogDecades);
  xr.pad(), yr.pad();

  OIIO::ImageBuf img(OIIO::ImageSpec(spec.width, spec.height, 3, OIIO::TypeDesc::FLOAT));
  IBA::fill(img, {1.0f, 1.0f, 1.0f});
  const int left = 90, right = spec.width - 280, top = 64, bottom = spec.height - 70;
  const auto px = [&](double x) {
    return int(left + (x - xr.lo) / (xr.hi - xr.lo) * (right - left));
  };
  const auto py = [&](double y) {
    return int(bottom - (std::max(y, yr.lo) - yr.lo) / (yr.hi - yr.lo) * (bottom - top));
  };

  IBA::render_box(img, left, top, right, bottom, kInk);
  const double xs = tick_step(xr, 8);
  const double ys = spec.log_y ? std::max(1.0, std::ceil((yr.hi - yr.lo) / 6)) : tick_step(yr, 6);
  for (double x = std::ceil(xr.lo / xs) * xs; x <= xr.hi + 1e-9 * xs; x += xs) {
    IBA::render_line(img, px(x), bottom, px(x), bottom + 6, kInk);
    text(img, px(x), bottom + 24, tick_text(x, false), 15, IBA::TextAlignX::Center);
  }
  for (double y = std::ceil(yr.lo / ys) * ys; y <= yr.hi + 1e-9 * ys; y += ys) {
    IBA::render_line(img, left - 6, py(y), left, py(y), kInk);
    text(img, left - 10, py(y), tick_text(y, spec.log_y), 15, IBA::TextAlignX::Right,
         IBA::TextAlignY::Center);
  }
  text(img, (left + right) / 2, 26, spec.title, 20, IBA::TextAlignX::Center);
  text(img, (left + right) / 2, spec.height - 22, spec.x_label, 17, IBA::TextAlignX::Center);
  text(img, 10, top - 10, spec.y_label + (spec.log_y ? " (log scale)" : ""), 17);

  for (std::size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    for (std::size_t i = 1; i < s.x.size(); ++i) {
      if (!usable(s.y[i - 1]) || !usable(s.y[i])) continue;
      // Two pixels wide, so that thin series stay readable next to each other.
      for (int d = 0; d < 2; ++d)
        IBA::render_line(img, px(s.x[i - 1]), py(ty(s.y[i - 1])) + d, px(s.x[i]),
                         py(ty(s.y[i])) + d, s.color);
    }
    for (std::size_t i = 0; s.markers && i < s.x.size(); ++i)
      if (usable(s.y[i]))
        IBA::render_box(img, px(s.x[i]) - 3, py(ty(s.y[i])) - 3, px(s.x[i]) + 3, py(ty(s.y[i])) + 3,
                        s.color, true);
    const int ly = top + 20 + int(k) * 24;
    IBA::render_box(img, right + 15, ly - 8, right + 40, ly - 4, s.color, true);
    text(img, right + 48, ly, s.label, 15);
  }

  write_png(img, png);
}

StripSize write_image_strip(const std::filesystem::path& png, const std::string& title,
                            const std::vector<StripTile>& tiles) {
  constexpr int kGap = 10, kTitle = 34, kLabel = 26, kTextSize = 15;
  constexpr std::array<float, 3> kSheet{0.16f, 0.16f, 0.16f}, kLight{0.9f, 0.9f, 0.9f};
  int cell = 0, tile_h = 0;
  for (const StripTile& t : tiles) {
    const OIIO::ROI box = IBA::text_size(t.label, kTextSize, kFont);
    cell = std::max({cell, t.image.width, box.defined() ? box.width() : 0});
    tile_h = std::max(tile_h, t.image.height);
  }
  const int n = int(tiles.size());
  const StripSize size{n * cell + (n + 1) * kGap, kTitle + tile_h + kLabel + kGap};
  OIIO::ImageBuf img(OIIO::ImageSpec(size.width, size.height, 3, OIIO::TypeDesc::FLOAT));
  IBA::fill(img, kSheet);
  text(img, kGap, kTitle - 12, title, 17, IBA::TextAlignX::Left, IBA::TextAlignY::Baseline, kLight);
  for (int i = 0; i < n; ++i) {
    const ocio::Thumbnail& t = tiles[i].image;
    OIIO::ImageBuf tile(OIIO::ImageSpec(t.width, t.height, 4, OIIO::TypeDesc::UINT8));
    tile.set_pixels(tile.roi(), OIIO::TypeDesc::UINT8, t.rgba.data());
    const int x = kGap + i * (cell + kGap);
    IBA::paste(img, x + (cell - t.width) / 2, kTitle, 0, 0, tile,
               OIIO::ROI(0, t.width, 0, t.height, 0, 1, 0, 3));
    text(img, x + cell / 2, kTitle + tile_h + kLabel - 8, tiles[i].label, kTextSize,
         IBA::TextAlignX::Center, IBA::TextAlignY::Baseline, kLight);
  }
  write_png(img, png);
  return size;
}

}  // namespace brdfnav
