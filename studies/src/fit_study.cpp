#include <brdfnav/studies/fit_study.h>

#include <brdfnav/core/statistics.h>
#include <brdfnav/precompute/levenberg_marquardt.h>

#include <algorithm>
#include <limits>
#include <random>

namespace brdfnav {

namespace {

constexpr int kMaxIterations = 60;
// Levenberg-Marquardt runs from the best ranked starts: the distance with its best rho_s is the
// angle between two embeddings, which has local minima on the grid's boundary.
constexpr std::size_t kStarts = 3;

// The embedded distance to `target` of `model`'s materials with rho_d = 0, as a function of the
// parameters in their grid scale (clamped to the grid). Per channel, the embedding of rho_s_c is
// cbrt(rho_s_c) u_c(p), so the best cbrt(rho_s_c) is the projection of the target on u_c.
class EmbeddedFit {
 public:
  EmbeddedFit(const ModelEmbedding& model, const Eigen::VectorXf& target)
      : model_(model), target_(target), k_(model.components()) {
    for (std::size_t d = 0; d < model.grid().dimensions(); ++d) {
      const ParamSpec& spec = model.grid().specs()[d];
      lo_.push_back(to_scale(spec, model.grid().axis(d).front()));
      hi_.push_back(to_scale(spec, model.grid().axis(d).back()));
    }
  }

  // The embedding's 3 k differences, then one per parameter for how far x lies outside the grid:
  // the embedding is flat out there, so without it a forward-difference Jacobian taken at a grid
  // end sees no way back and Levenberg-Marquardt stops on the boundary.
  int residual_count() const { return 3 * static_cast<int>(k_) + static_cast<int>(lo_.size()); }

  // The material at `x` with its best rho_s; fills `r` (when given) with the residual.
  Material material(const Eigen::VectorXd& x, Eigen::VectorXd* r) const {
    Material m = default_material(model_.model());
    for (std::size_t d = 0; d < lo_.size(); ++d) {
      const double inside = std::clamp(x[d], lo_[d], hi_[d]);
      m.params[d] = from_scale(model_.grid().specs()[d], inside);
      if (r) (*r)[3 * k_ + static_cast<Eigen::Index>(d)] = x[d] - inside;
    }
    m.rho_d = Rgb::Zero();
    m.rho_s = Rgb::Ones();
    const Eigen::VectorXf u = model_.embed(m);
    for (Eigen::Index c = 0; c < 3; ++c) {
      const auto uc = u.segment(c * k_, k_), vc = target_.segment(c * k_, k_);
      const double uu = uc.squaredNorm();
      const double a = uu > 0 ? std::max(0.0, double(uc.dot(vc)) / uu) : 0.0;
      m.rho_s[c] = a * a * a;
      if (r) r->segment(c * k_, k_) = (vc - float(a) * uc).cast<double>();
    }
    return m;
  }
  double distance(const Eigen::VectorXd& x) const {
    Eigen::VectorXd r(residual_count());
    material(x, &r);
    return r.head(3 * k_).norm();
  }
  Eigen::VectorXd scaled(const std::vector<double>& values) const {
    Eigen::VectorXd x(static_cast<Eigen::Index>(values.size()));
    for (std::size_t d = 0; d < values.size(); ++d)
      x[d] = std::clamp(to_scale(model_.grid().specs()[d], values[d]), lo_[d], hi_[d]);
    return x;
  }

 private:
  const ModelEmbedding& model_;
  const Eigen::VectorXf& target_;
  Eigen::Index k_;
  std::vector<double> lo_, hi_;
};

Eigen::VectorXd refine(const EmbeddedFit& fit, const Eigen::VectorXd& x) {
  // Steps of 1e-3 of x: the embedding is single precision, so the default steps (1e-8 of x)
  // would see no change at all.
  constexpr double kStepSquared = 1e-6;
  return levenberg_marquardt(
      [&fit](const Eigen::VectorXd& in, Eigen::VectorXd& r) { fit.material(in, &r); },
      fit.residual_count(), x, kMaxIterations * static_cast<int>(x.size() + 1), kStepSquared);
}

// Every grid node and every cell centre, in scale units, nearest to `target` first.
std::vector<Eigen::VectorXd> ranked_starts(const EmbeddedFit& fit, const ParamGrid& grid) {
  std::vector<std::vector<double>> coordinates{{}};
  for (std::size_t d = 0; d < grid.dimensions(); ++d) {
    std::vector<std::vector<double>> next;
    for (const std::vector<double>& c : coordinates)
      for (double half = 0; half <= 2.0 * double(grid.axis(d).size() - 1); ++half) {
        next.push_back(c);
        next.back().push_back(grid.value_at(d, half / 2));
      }
    coordinates = std::move(next);
  }
  std::vector<std::pair<double, Eigen::VectorXd>> ranked;
  for (const std::vector<double>& values : coordinates) {
    const Eigen::VectorXd x = fit.scaled(values);
    ranked.emplace_back(fit.distance(x), x);
  }
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Eigen::VectorXd> starts;
  for (const auto& r : ranked) starts.push_back(r.second);
  return starts;
}

}  // namespace

ImageFit fit_in_embedding(const ModelEmbedding& model, const Eigen::VectorXf& target,
                          const std::vector<double>& start) {
  const EmbeddedFit fit(model, target);
  Eigen::VectorXd best;
  double best_distance = std::numeric_limits<double>::infinity();
  std::vector<Eigen::VectorXd> starts = ranked_starts(fit, model.grid());
  starts.resize(std::min(starts.size(), kStarts));
  starts.push_back(fit.scaled(start));
  for (const Eigen::VectorXd& x0 : starts) {
    for (const Eigen::VectorXd& x : {x0, refine(fit, x0)}) {
      const double d = fit.distance(x);
      if (d < best_distance) best_distance = d, best = x;
    }
  }
  return {fit.material(best, nullptr), best_distance};
}

FitStudy fit_study(const Database& db, int per_pair, std::uint32_t seed) {
  FitStudy study{per_pair, {}, 0, 0};
  std::vector<double> ratios;
  std::mt19937 rng(seed);
  for (const ModelInfo& from : models()) {
    const ModelEmbedding* a = db.embedding(from.id);
    if (!a) continue;
    std::vector<std::size_t> nodes;
    for (int i = 0; i < per_pair; ++i) nodes.push_back(rng() % a->grid().node_count());
    for (const ModelInfo& to : models()) {
      const ConversionTable* table = db.conversion(from.id, to.id);
      const ModelEmbedding* b = db.embedding(to.id);
      if (!table || !b) continue;
      std::vector<double> brdf, image, between;
      for (std::size_t node : nodes) {
        Material m = default_material(from.id);
        m.params = a->grid().node_values(node);
        m.rho_d = Rgb::Zero();
        m.rho_s = Rgb::Ones();
        const Eigen::VectorXf target = a->embed(m);
        const Conversion& c = table->nodes[node];
        Material converted = default_material(to.id);
        converted.params = c.params;
        converted.rho_d = Rgb::Zero();
        converted.rho_s = c.scale;
        const Eigen::VectorXf by_brdf = b->embed(converted);
        const ImageFit fit = fit_in_embedding(*b, target, c.params);
        brdf.push_back(embedding_distance(target, by_brdf));
        image.push_back(fit.distance);
        between.push_back(embedding_distance(by_brdf, b->embed(fit.material)));
        if (image.back() > 0) ratios.push_back(brdf.back() / image.back());
      }
      study.pairs.push_back({from.id, to.id, per_pair, quantile(brdf, 0.5), quantile(image, 0.5),
                             quantile(between, 0.5)});
    }
  }
  if (!ratios.empty()) {
    study.ratio_median = quantile(ratios, 0.5);
    study.ratio_p90 = quantile(ratios, 0.9);
  }
  return study;
}

}  // namespace brdfnav
