#include <brdfnav/studies/validation_report.h>

#include <brdfnav/studies/plot.h>

#include <cstdio>

namespace brdfnav {

namespace {

std::string fixed(double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

struct Writer {
  const std::filesystem::path& dir;
  std::vector<ReportFile> files;

  void plot(const std::string& figure, const std::string& file, const PlotSpec& spec,
            const std::vector<PlotSeries>& series) {
    write_line_plot(dir / file, spec, series);
    files.push_back({figure, file, spec.width, spec.height});
  }
  void strip(const std::string& figure, const std::string& file, const std::string& title,
             const std::vector<StripTile>& tiles) {
    const StripSize size = write_image_strip(dir / file, title, tiles);
    files.push_back({figure, file, size.width, size.height});
  }
};

// The straight line the subjects' ratings follow, 0 at d = 0.8 and 1 at d = 0.99.
std::vector<double> pellacini_line(const std::vector<double>& d) {
  std::vector<double> line;
  for (double v : d) line.push_back((v - d.front()) / (d.back() - d.front()));
  return line;
}

// A cumulative curve scaled onto that line (least squares), so that only its shape shows.
PlotSeries scaled_curve(const std::string& label, const std::vector<double>& d,
                        const CumulativeCurve& c, std::size_t color) {
  PlotSeries p{label + " (R^2 " + fixed(c.fit.r2, 3) + ")", d, {}, plot_color(color), true};
  const double scale = least_squares_scale(c.values, pellacini_line(d));
  for (double v : c.values) p.y.push_back(scale * v);
  return p;
}

// Figure 2: every metric's curve under the reference map; then the cube root under every map.
void plot_fig2(Writer& w, const PellaciniStudy& s, const std::string& reference,
               const std::vector<NamedPellacini>& others) {
  const PlotSeries line{"linear in d (Pellacini)", s.d, pellacini_line(s.d), {0.f, 0.f, 0.f}};
  const char* x_label = "d = 1 - alpha (distinctness of image)";
  const char* y_label = "cumulative distance, least-squares scaled";
  std::vector<PlotSeries> series;
  for (std::size_t k = 0; k < s.curves.size(); ++k)
    series.push_back(scaled_curve(s.curves[k].metric, s.d, s.curves[k], k));
  series.push_back(line);
  w.plot("figure2", "fig2_cumulative.png",
         {"Fig. 2: cumulative distance along Pellacini's 11 Ward stimuli", x_label, y_label},
         series);
  if (others.empty()) return;
  series = {scaled_curve(reference, s.d, s.curves[0], 0)};
  for (const NamedPellacini& o : others)
    series.push_back(scaled_curve(o.env, s.d, o.study.curves[0], series.size()));
  series.push_back(line);
  w.plot("figure2", "fig2_environments.png",
         {"Fig. 2 under each map: the cube-root metric's cumulative distance", x_label, y_label},
         series);
}

// Figure 3: the distances from the sample nearest alpha = 0.07 to all 25, each metric scaled
// onto the reference map's distances.
void plot_fig3(Writer& w, const SceneStudy& s) {
  std::vector<PlotSeries> series;
  for (std::size_t k = 0; k < s.entries.size(); ++k) {
    const SceneEntry& e = s.entries[k];
    PlotSeries p{e.name + " (" + fixed(100 * e.agreement.within, 0) + "% within 20%)",
                 s.alpha,
                 {},
                 plot_color(k),
                 true};
    for (std::size_t j = 0; j < s.alpha.size(); ++j)
      p.y.push_back(e.agreement.scale *
                    e.distances(Eigen::Index(s.reference_sample), Eigen::Index(j)));
    series.push_back(std::move(p));
  }
  w.plot("figure3", "fig3_distances.png",
         {"Fig. 3: distance from Ward alpha = " + fixed(s.alpha[s.reference_sample], 4) +
              " to 25 samples",
          "alpha", "distance (scaled to " + s.entries.front().name + ")"},
         series);
}

StripTile tile(const Image& image, const std::string& label, const ocio::ColorPipeline& color) {
  return {{image.width, image.height,
           color.apply(image.rgba.data(), image.width, image.height, ocio::kDisplaySRGB,
                       ocio::kViewStandard)},
          label};
}

// Figures 8 and 9: both cumulative curves (normalised) with the samples each spacing picks, and
// the two rows of images.
void plot_spacing(Writer& w, const std::string& figure, const std::string& model,
                  const char* parameter, int digits, const SpacingStudy& s,
                  const ocio::ColorPipeline& color) {
  const auto normalised = [](const std::vector<double>& c) {
    std::vector<double> out;
    for (double v : c) out.push_back(v / c.back());
    return out;
  };
  w.plot(figure, figure + "_cumulative.png",
         {figure + ": " + model + ", cumulative distance along " + parameter, parameter,
          "cumulative distance / total"},
         {{"image metric", s.fine, normalised(s.cumulative_image), plot_color(0), true},
          {s.baseline.spacing, s.fine, normalised(s.cumulative_baseline), plot_color(1), true}});
  for (const SpacedRow* row : {&s.baseline, &s.image}) {
    std::vector<StripTile> tiles;
    for (std::size_t i = 0; i < row->values.size(); ++i)
      tiles.push_back(
          tile(row->images[i], parameter + ("=" + fixed(row->values[i], digits)), color));
    w.strip(figure, figure + "_" + row->spacing + ".png",
            model + ", spaced by " + row->spacing + " (CV of image-metric steps " +
                fixed(row->cv, 2) + ")",
            tiles);
  }
}

void plot_embedding(Writer& w, const EmbeddingStudy& s) {
  std::vector<PlotSeries> series;
  for (const auto& [name, rows] : {std::pair{"anywhere", &s.anywhere}, {"on nodes", &s.on_nodes}})
    for (const bool p95 : {false, true}) {
      PlotSeries p{
          std::string(p95 ? "p95, " : "median, ") + name, {}, {}, plot_color(series.size()), true};
      for (const EmbeddingErrors& r : *rows)
        p.x.push_back(r.coefficients), p.y.push_back(p95 ? r.p95 : r.median);
      series.push_back(std::move(p));
    }
  w.plot("embedding", "embedding_error.png",
         {"Embedded vs exact distance, " + std::to_string(s.pairs) + " random pairs each",
          "coefficients per channel", "relative error", true},
         series);
}

}  // namespace

std::vector<ReportFile> write_report_plots(const std::filesystem::path& dir,
                                           const ValidationResults& r,
                                           const ocio::ColorPipeline& color) {
  Writer w{dir, {}};
  plot_fig2(w, r.fig2, r.fig3.entries.front().name, r.fig2_others);
  plot_fig3(w, r.fig3);
  plot_spacing(w, "figure8", "Ward", kFig8Parameter, 3, r.fig8, color);
  plot_spacing(w, "figure9", "Lafortune n=800", kFig9Parameter, 4, r.fig9, color);
  if (r.embedding) plot_embedding(w, *r.embedding);
  return w.files;
}

}  // namespace brdfnav
