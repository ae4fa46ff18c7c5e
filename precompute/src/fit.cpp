#include <brdfnav/precompute/fit.h>

#include <brdfnav/core/grid.h>
#include <brdfnav/precompute/levenberg_marquardt.h>

#include <algorithm>
#include <numeric>

namespace brdfnav {

namespace {

// Rank-1 lattice point i of n (Fibonacci-like generator): well-spread and deterministic.
Vec2 lattice(int i, int n) {
  constexpr double kGolden = 0.6180339887498949;
  return {(i + 0.5) / n, std::fmod(0.5 + i * kGolden, 1.0)};
}

template <typename F>
decltype(auto) visit_lobe(const Lobe& lobe, F&& f) {
  return std::visit(std::forward<F>(f), lobe);
}

// Parameters of `model` in their interpolation scale, clamped to the grid's span.
struct ParamBox {
  std::span<const ParamSpec> specs;
  Eigen::VectorXd lo, hi;

  explicit ParamBox(ModelId model) : specs(model_info(model).params) {
    lo.resize(specs.size()), hi.resize(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i) {
      const auto nodes = grid_nodes(specs[i]);
      lo[i] = to_scale(specs[i], nodes.front());
      hi[i] = to_scale(specs[i], nodes.back());
    }
  }
  std::vector<double> values(const Eigen::VectorXd& x) const {
    std::vector<double> v(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i)
      v[i] = from_scale(specs[i], std::clamp(x[i], lo[i], hi[i]));
    return v;
  }
};

// The variable-projection residual: for parameters x, the RGB scale is solved in closed form and
// the weighted differences (3 per quadrature point) are returned.
class FitProblem {
 public:
  FitProblem(const FitQuadrature& q, const std::vector<Rgb>& target, ModelId model)
      : q_(q), target_(target), model_(model), box_(model) {}

  int residual_count() const { return 3 * static_cast<int>(q_.weight.size()); }
  const ParamBox& box() const { return box_; }
  int evaluations() const { return evaluations_; }

  // Fills `r` (when given) and returns the scale and the weighted squared error.
  std::pair<Rgb, double> evaluate(const Eigen::VectorXd& x, Eigen::VectorXd* r) const {
    ++evaluations_;
    const Lobe lobe = make_lobe(model_, box_.values(x));
    std::vector<Rgb> fb(q_.weight.size());
    Rgb ab = Rgb::Zero(), bb = Rgb::Zero();
    for (std::size_t k = 0; k < fb.size(); ++k) {
      fb[k] = visit_lobe(lobe, [&](const auto& l) { return l.eval(q_.wi[k], q_.wo[k]); });
      ab += q_.weight[k] * target_[k] * fb[k];
      bb += q_.weight[k] * fb[k] * fb[k];
    }
    const Rgb s = (bb > 0).select(ab / bb.max(1e-300), Rgb::Zero());
    double e = 0;
    for (std::size_t k = 0; k < fb.size(); ++k) {
      const Rgb d = std::sqrt(q_.weight[k]) * (target_[k] - s * fb[k]);
      if (r) r->segment<3>(3 * static_cast<Eigen::Index>(k)) = d.matrix();
      e += d.square().sum();
    }
    return {s, e};
  }

 private:
  const FitQuadrature& q_;
  const std::vector<Rgb>& target_;
  ModelId model_;
  ParamBox box_;
  mutable int evaluations_ = 0;
};

// Every other grid node of `model` along each axis (the last one kept), in scale coordinates: a
// quarter (two parameters) to an eighth (three) of the grid, fine enough to rank the starts of
// Levenberg-Marquardt, which then moves by less than a grid cell.
std::vector<Eigen::VectorXd> grid_starts(ModelId model) {
  const ParamGrid grid(model_info(model).params);
  std::vector<Eigen::VectorXd> starts;
  for (std::size_t node = 0; node < grid.node_count(); ++node) {
    const std::vector<std::size_t> multi = grid.multi_index(node);
    bool coarse = true;
    for (std::size_t d = 0; d < multi.size(); ++d)
      coarse = coarse && (multi[d] % 2 == 0 || multi[d] + 1 == grid.axis(d).size());
    if (!coarse) continue;
    const std::vector<double> values = grid.node_values(node);
    Eigen::VectorXd x(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) x[i] = to_scale(grid.specs()[i], values[i]);
    starts.push_back(x);
  }
  return starts;
}

}  // namespace

FitQuadrature make_fit_quadrature(const Lobe& target, int n_wo, int n_wi) {
  FitQuadrature q;
  for (int j = 0; j < n_wo; ++j) {
    const Vec2 uo = lattice(j, n_wo);
    const double cos_o = uo[0];
    const Vec3 wo = spherical_direction(safe_sqrt(1 - cos_o * cos_o), cos_o, 2 * kPi * uo[1]);
    for (int i = 0; i < n_wi; ++i) {
      // Half the directions from the lobe's sampler, half cosine-weighted; the balance-heuristic
      // weight 1 / (n q) with the mixture density q keeps the estimate unbiased.
      const Vec2 u = lattice(i / 2, (n_wi + 1) / 2);
      const std::optional<Vec3> wi =
          i % 2 == 0 ? visit_lobe(target, [&](const auto& l) { return l.sample(wo, u); })
                     : std::optional<Vec3>(sample_cosine_hemisphere(u));
      if (!wi || wi->z() <= 0) continue;
      const double lobe_pdf = visit_lobe(target, [&](const auto& l) { return l.pdf(*wi, wo); });
      const double mix = 0.5 * lobe_pdf + 0.5 * cosine_hemisphere_pdf(wi->z());
      if (!(mix > 0)) continue;
      q.wi.push_back(*wi);
      q.wo.push_back(wo);
      q.weight.push_back(2 * kPi / n_wo * cos_o * wi->z() / (n_wi * mix));
    }
  }
  return q;
}

LobeFit fit_lobe(const Lobe& target, ModelId model, const FitOptions& options) {
  const FitQuadrature q = make_fit_quadrature(target, options.n_wo, options.n_wi);
  std::vector<Rgb> fa(q.weight.size());
  double norm = 0;
  for (std::size_t k = 0; k < fa.size(); ++k) {
    fa[k] = visit_lobe(target, [&](const auto& l) { return l.eval(q.wi[k], q.wo[k]); });
    norm += q.weight[k] * fa[k].square().sum();
  }
  const FitProblem problem(q, fa, model);
  // Ranking the starts needs only a rough error: every kRankStride-th point of the quadrature.
  constexpr std::size_t kRankStride = 4;
  FitQuadrature coarse_q;
  std::vector<Rgb> coarse_fa;
  for (std::size_t k = 0; k < fa.size(); k += kRankStride) {
    coarse_q.wi.push_back(q.wi[k]), coarse_q.wo.push_back(q.wo[k]);
    coarse_q.weight.push_back(q.weight[k] * kRankStride);
    coarse_fa.push_back(fa[k]);
  }
  const FitProblem ranking(coarse_q, coarse_fa, model);

  // Rank a coarse grid, then refine the best few with Levenberg-Marquardt.
  std::vector<Eigen::VectorXd> starts = grid_starts(model);
  std::vector<double> cost(starts.size());
  for (std::size_t i = 0; i < starts.size(); ++i)
    cost[i] = ranking.evaluate(starts[i], nullptr).second;
  std::vector<std::size_t> order(starts.size());
  std::iota(order.begin(), order.end(), 0);
  const std::size_t keep = std::min<std::size_t>(options.starts, order.size());
  std::partial_sort(order.begin(), order.begin() + keep, order.end(),
                    [&](std::size_t a, std::size_t b) { return cost[a] < cost[b]; });

  // Each start is refined on the coarse quadrature; the best result is polished on the full one.
  const int n = static_cast<int>(starts[order[0]].size());
  auto refine = [&](const FitProblem& p, Eigen::VectorXd x) {
    x = levenberg_marquardt(
        [&p](const Eigen::VectorXd& in, Eigen::VectorXd& r) { p.evaluate(in, &r); },
        p.residual_count(), std::move(x), options.max_iterations * (n + 1));
    return Eigen::VectorXd(x.cwiseMax(p.box().lo).cwiseMin(p.box().hi));
  };
  Eigen::VectorXd best = starts[order[0]];
  double best_cost = problem.evaluate(best, nullptr).second;
  for (std::size_t s = 0; s < keep; ++s) {
    const Eigen::VectorXd x = refine(ranking, starts[order[s]]);
    const double c = problem.evaluate(x, nullptr).second;
    if (c < best_cost) best_cost = c, best = x;
  }
  const Eigen::VectorXd polished = refine(problem, best);
  if (problem.evaluate(polished, nullptr).second < best_cost) best = polished;
  const auto [scale, err] = problem.evaluate(best, nullptr);
  return {model, problem.box().values(best), scale, norm > 0 ? std::sqrt(err / norm) : 0.0,
          problem.evaluations() + ranking.evaluations()};
}

}  // namespace brdfnav
