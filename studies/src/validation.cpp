#include <brdfnav/studies/validation.h>

#include <brdfnav/core/cielab.h>
#include <brdfnav/core/statistics.h>
#include <brdfnav/precompute/fit.h>
#include <brdfnav/renderer/env_map.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>

namespace brdfnav {

namespace {

// sqrt(mean over covered pixels of squared(a_px, b_px)), after the metric's shape checks.
template <typename F>
double rms_over_covered(const Image& a, const Image& b, F squared) {
  check_same_shape(a, b);
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    if (a.rgba[i + 3] <= 0.5f) continue;
    sum += squared(&a.rgba[i], &b.rgba[i]);
    ++count;
  }
  if (count == 0) throw ImageError("the images cover no pixel");
  return std::sqrt(sum / double(count));
}

// sum_k w_k mean_c |f(k) - g(k)|^2 over the quadrature (g may be null: the norm of f).
double weighted_square(const FitQuadrature& q, const Closure& f, const Closure* g) {
  double sum = 0;
  for (std::size_t k = 0; k < q.weight.size(); ++k) {
    Rgb d = f.eval(q.wi[k], q.wo[k]);
    if (g) d -= g->eval(q.wi[k], q.wo[k]);
    sum += q.weight[k] * d.square().mean();
  }
  return sum;
}

// Dense enough that the Ward lobes of the figures (alpha >= 0.01) are resolved at every wo.
constexpr int kBrdfQuadratureWo = 32, kBrdfQuadratureWi = 256;

std::vector<Image> render_all(Renderer& renderer, const std::vector<Material>& samples) {
  std::vector<Image> images;
  images.reserve(samples.size());
  for (const Material& m : samples) images.push_back(renderer.render(m));
  return images;
}

// The symmetric matrix of distance(i, j) over n samples, zero on the diagonal.
template <typename F>
Eigen::MatrixXd pairwise(std::size_t n, F distance) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      d(Eigen::Index(i), Eigen::Index(j)) = d(Eigen::Index(j), Eigen::Index(i)) = distance(i, j);
  return d;
}

std::vector<double> successive(const std::vector<Image>& images,
                               double (*metric)(const Image&, const Image&)) {
  std::vector<double> steps;
  for (std::size_t i = 1; i < images.size(); ++i) steps.push_back(metric(images[i - 1], images[i]));
  return steps;
}

// The fine samples of a spacing study, their images and both curves' steps between them.
struct FineSweep {
  std::vector<double> x;
  std::vector<Image> images;
  std::vector<double> image_steps, base_steps;
};

void measure_steps(FineSweep& s, const MaterialFamily& family, Baseline baseline) {
  s.image_steps = successive(s.images, image_distance);
  s.base_steps.clear();
  for (std::size_t i = 1; i < s.x.size(); ++i)
    s.base_steps.push_back(baseline == Baseline::brdf_l2
                               ? brdf_distance(family(s.x[i - 1]), family(s.x[i]))
                               : s.x[i] - s.x[i - 1]);
}

// A segment whose step is a large part of a row's step (total / (count - 1)) would place a row
// sample by linear interpolation across a change it does not resolve (Lafortune's cz near
// 1/sqrt(3), Ward's BRDF-space metric near the mirror): such segments are bisected until every
// step is at most a quarter of a row's step, up to kMaxFine samples.
constexpr double kStepsPerRowStep = 4;
constexpr std::size_t kMaxFine = 128;

FineSweep measure_fine(Renderer& renderer, const MaterialFamily& family,
                       const std::vector<double>& fine, Baseline baseline, int count) {
  FineSweep s;
  s.x = fine;
  for (double x : fine) s.images.push_back(renderer.render(family(x)));
  for (;;) {
    measure_steps(s, family, baseline);
    const double limit = kStepsPerRowStep * (count - 1);
    const double image_max =
        std::accumulate(s.image_steps.begin(), s.image_steps.end(), 0.0) / limit;
    const double base_max = std::accumulate(s.base_steps.begin(), s.base_steps.end(), 0.0) / limit;
    std::vector<std::size_t> split;
    for (std::size_t i = 0; i + 1 < s.x.size() && s.x.size() + split.size() < kMaxFine; ++i)
      if (s.image_steps[i] > image_max || s.base_steps[i] > base_max) split.push_back(i);
    if (split.empty()) return s;
    // From the back, so that the indices still to come stay valid.
    for (auto i = split.rbegin(); i != split.rend(); ++i) {
      const double mid = 0.5 * (s.x[*i] + s.x[*i + 1]);
      s.x.insert(s.x.begin() + std::ptrdiff_t(*i + 1), mid);
      s.images.insert(s.images.begin() + std::ptrdiff_t(*i + 1), renderer.render(family(mid)));
    }
  }
}

// A material of `e`'s model with random parameters and colours (see embedding_study).
Material random_material(const ModelEmbedding& e, bool on_nodes, std::mt19937& rng) {
  const auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * (double(rng()) + 0.5) / 4294967296.0;
  };
  const auto pick = [&](const std::vector<double>& nodes) { return nodes[rng() % nodes.size()]; };
  Material m = default_material(e.model());
  for (std::size_t d = 0; d < e.grid().dimensions(); ++d)
    m.params[d] = on_nodes ? pick(e.grid().axis(d))
                           : e.grid().value_at(d, uniform(0, double(e.grid().axis(d).size() - 1)));
  for (int c = 0; c < 3; ++c) {
    if (on_nodes) {
      const double sum = uniform(0, 1), q = pick(e.q_nodes());
      m.rho_d[c] = q * sum, m.rho_s[c] = (1 - q) * sum;
    } else {
      m.rho_d[c] = uniform(0, 0.5), m.rho_s[c] = uniform(0, 1);
    }
  }
  return m;
}

// Median and p95 of the relative error at every k, over `pairs` random pairs.
std::vector<EmbeddingErrors> embedding_errors(const std::vector<const ModelEmbedding*>& models,
                                              Renderer& renderer, int pairs, bool on_nodes,
                                              const std::vector<int>& ks, std::mt19937& rng) {
  std::vector<std::vector<double>> errors(ks.size());
  for (int p = 0; p < pairs; ++p) {
    const ModelEmbedding& ea = *models[rng() % models.size()];
    const ModelEmbedding& eb = *models[rng() % models.size()];
    const Material a = random_material(ea, on_nodes, rng);
    const Material b = random_material(eb, on_nodes, rng);
    const double exact = image_distance(renderer.render(a), renderer.render(b));
    const Eigen::VectorXf va = ea.embed(a), vb = eb.embed(b);
    for (std::size_t i = 0; i < ks.size(); ++i)
      errors[i].push_back(std::abs(truncated_distance(va, vb, ks[i]) - exact) / exact);
  }
  std::vector<EmbeddingErrors> rows;
  for (std::size_t i = 0; i < ks.size(); ++i)
    rows.push_back({ks[i], quantile(errors[i], 0.5), quantile(errors[i], 0.95)});
  return rows;
}

}  // namespace

double rgb_distance(const Image& a, const Image& b) {
  return rms_over_covered(a, b, [](const float* p, const float* q) {
    double s = 0;
    for (int c = 0; c < 3; ++c) s += (double(p[c]) - q[c]) * (double(p[c]) - q[c]);
    return s / 3;
  });
}

double lab_distance(const Image& a, const Image& b, double white_y) {
  if (!(white_y > 0)) throw ImageError("lab_distance: the white's luminance must be positive");
  return rms_over_covered(a, b, [&](const float* p, const float* q) {
    const Rgb a(p[0], p[1], p[2]), b(q[0], q[1], q[2]);
    return (lab_from_rec709(a / white_y) - lab_from_rec709(b / white_y)).squaredNorm();
  });
}

double mean_luminance(const Image& image) {
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    if (image.rgba[i + 3] <= 0.5f) continue;
    sum += luminance(Rgb(image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]));
    ++count;
  }
  if (count == 0) throw ImageError("the image covers no pixel");
  return sum / double(count);
}

EnvLuminance env_luminance(const EnvMap& env) {
  EnvLuminance l{0, luminance_power(env) / (4 * kPi)};
  for (int y = 0; y < env.height(); ++y)
    for (int x = 0; x < env.width(); ++x) l.peak = std::max(l.peak, luminance(env.texel(x, y)));
  return l;
}

double brdf_distance(const Material& a, const Material& b) {
  const Closure fa = make_closure(a), fb = make_closure(b);
  const FitQuadrature qa = make_fit_quadrature(fa.lobe(), kBrdfQuadratureWo, kBrdfQuadratureWi);
  const FitQuadrature qb = make_fit_quadrature(fb.lobe(), kBrdfQuadratureWo, kBrdfQuadratureWi);
  const bool a_sharper = weighted_square(qa, fa, nullptr) >= weighted_square(qb, fb, nullptr);
  return std::sqrt(weighted_square(a_sharper ? qa : qb, fa, &fb));
}

LineFit fit_line(std::span<const double> x, std::span<const double> y) {
  const double n = double(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0)) throw std::invalid_argument("fit_line: needs two distinct x");
  LineFit fit;
  fit.slope = sxy / sxx;
  fit.intercept = my - fit.slope * mx;
  // R^2 = 1 - SS_res / SS_tot; with SS_res = syy - slope * sxy for a least-squares line.
  fit.r2 = syy > 0 ? 1 - (syy - fit.slope * sxy) / syy : 1;
  return fit;
}

double least_squares_scale(std::span<const double> values, std::span<const double> reference) {
  double vv = 0, vr = 0;
  for (std::size_t i = 0; i < values.size(); ++i)
    vv += values[i] * values[i], vr += values[i] * reference[i];
  return vv > 0 ? vr / vv : 0;
}

std::vector<double> cumulative(std::span<const double> steps) {
  std::vector<double> out{0};
  for (double s : steps) out.push_back(out.back() + s);
  return out;
}

double coefficient_of_variation(std::span<const double> values) {
  if (values.empty()) return 0;
  const double n = double(values.size());
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  double var = 0;
  for (double v : values) var += (v - mean) * (v - mean);
  return mean != 0 ? std::sqrt(var / n) / mean : 0;
}

std::vector<double> equal_steps(std::span<const double> x, std::span<const double> curve,
                                int count) {
  std::vector<double> out;
  std::size_t i = 0;
  for (int j = 0; j < count; ++j) {
    const double t = curve.front() + (curve.back() - curve.front()) * j / (count - 1);
    while (i + 2 < curve.size() && curve[i + 1] < t) ++i;
    const double span = curve[i + 1] - curve[i];
    const double frac = span > 0 ? std::clamp((t - curve[i]) / span, 0.0, 1.0) : 0.0;
    out.push_back(x[i] + frac * (x[i + 1] - x[i]));
  }
  out.front() = x.front(), out.back() = x.back();
  return out;
}

Material ward_sample(double alpha) {
  Material m = default_material(ModelId::ward);
  m.params = {alpha, alpha};
  m.rho_d = Rgb::Constant(0.1), m.rho_s = Rgb::Constant(0.1);
  return m;
}

PellaciniStudy pellacini_study(Renderer& renderer) {
  constexpr int kStimuli = 11;
  PellaciniStudy study;
  std::vector<Material> samples;
  for (int i = 0; i < kStimuli; ++i) {
    study.d.push_back(0.8 + 0.19 * i / (kStimuli - 1));
    samples.push_back(ward_sample(1 - study.d.back()));
  }
  const std::vector<Image> images = render_all(renderer, samples);
  study.white_y = mean_luminance(renderer.diffuse());
  study.env = env_luminance(renderer.env());

  std::vector<double> lab, brdf;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    lab.push_back(lab_distance(images[i - 1], images[i], study.white_y));
    brdf.push_back(brdf_distance(samples[i - 1], samples[i]));
  }
  const std::pair<const char*, std::vector<double>> steps[] = {
      {"cube_root", successive(images, image_distance)},
      {"cielab", lab},
      {"rgb", successive(images, rgb_distance)},
      {"brdf_l2", brdf}};
  for (const auto& [name, s] : steps) {
    CumulativeCurve curve{name, cumulative(s), {}};
    curve.fit = fit_line(study.d, curve.values);
    study.curves.push_back(std::move(curve));
  }
  return study;
}

Eigen::MatrixXd image_distances(Renderer& renderer, const std::vector<Material>& samples) {
  const std::vector<Image> images = render_all(renderer, samples);
  return pairwise(samples.size(), [&](std::size_t i, std::size_t j) {
    return image_distance(images[i], images[j]);
  });
}

Eigen::MatrixXd brdf_distances(const std::vector<Material>& samples) {
  return pairwise(samples.size(), [&](std::size_t i, std::size_t j) {
    return brdf_distance(samples[i], samples[j]);
  });
}

Agreement compare_distances(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& other,
                            double tolerance) {
  std::vector<double> r, o;
  for (Eigen::Index i = 0; i < reference.rows(); ++i)
    for (Eigen::Index j = 0; j < reference.cols(); ++j)
      if (i != j) r.push_back(reference(i, j)), o.push_back(other(i, j));
  Agreement a;
  a.scale = least_squares_scale(o, r);
  std::size_t within = 0;
  for (std::size_t k = 0; k < r.size(); ++k)
    if (std::abs(a.scale * o[k] - r[k]) <= tolerance * r[k]) ++within;
  a.within = r.empty() ? 0 : double(within) / double(r.size());
  return a;
}

SceneSamples scene_samples() {
  constexpr int kSamples = 25;
  SceneSamples s;
  for (int i = 0; i < kSamples; ++i) {
    s.alpha.push_back(0.01 + 0.35 * i / (kSamples - 1));
    s.materials.push_back(ward_sample(s.alpha.back()));
    if (std::abs(s.alpha.back() - 0.07) < std::abs(s.alpha[s.reference_sample] - 0.07))
      s.reference_sample = s.alpha.size() - 1;
  }
  return s;
}

SceneStudy scene_study(const SceneSamples& samples, std::vector<SceneEntry> maps) {
  SceneStudy study;
  study.alpha = samples.alpha;
  study.reference_sample = samples.reference_sample;
  study.entries = std::move(maps);
  study.entries.push_back({kBrdfL2Entry, brdf_distances(samples.materials), {}});
  for (SceneEntry& e : study.entries)
    e.agreement = compare_distances(study.entries.front().distances, e.distances, study.tolerance);
  const auto n = Eigen::Index(study.entries.size());
  study.within.resize(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      study.within(i, j) =
          compare_distances(study.entries[i].distances, study.entries[j].distances, study.tolerance)
              .within;
  return study;
}

std::vector<MapAgreement> map_agreements(const Eigen::MatrixXd& within, std::size_t maps) {
  if (Eigen::Index(maps) > within.rows() || within.rows() != within.cols())
    throw std::invalid_argument("map_agreements: more maps than the agreement matrix has");
  std::vector<MapAgreement> result(maps);
  for (std::size_t i = 0; i < maps; ++i) {
    for (std::size_t j = 0; j < maps; ++j) {
      if (i == j) continue;
      const double a = std::min(within(Eigen::Index(i), Eigen::Index(j)),
                                within(Eigen::Index(j), Eigen::Index(i)));
      if (a >= kAgreeingWithin) ++result[i].agreeing;
      result[i].mean += a / double(maps - 1);
    }
  }
  return result;
}

std::size_t most_representative(const std::vector<MapAgreement>& maps,
                                const std::vector<double>& r2) {
  if (maps.empty() || r2.size() != maps.size())
    throw std::invalid_argument("most_representative: one R^2 per map, at least one map");
  std::size_t most = 0;
  for (const MapAgreement& m : maps) most = std::max(most, m.agreeing);
  double best_mean = -1;
  for (const MapAgreement& m : maps)
    if (m.agreeing == most) best_mean = std::max(best_mean, m.mean);
  std::size_t best = maps.size();
  for (std::size_t i = 0; i < maps.size(); ++i)
    if (maps[i].agreeing == most && maps[i].mean >= best_mean - kMeanAgreementTie &&
        (best == maps.size() || r2[i] > r2[best]))
      best = i;
  return best;
}

SpacingStudy spacing_study(Renderer& renderer, const MaterialFamily& family,
                           const std::vector<double>& fine, Baseline baseline, int count) {
  const FineSweep sweep = measure_fine(renderer, family, fine, baseline, count);
  SpacingStudy study{sweep.x, cumulative(sweep.image_steps), cumulative(sweep.base_steps), {}, {}};
  const auto row = [&](std::string name, const std::vector<double>& curve) {
    SpacedRow r{std::move(name), equal_steps(sweep.x, curve, count), {}, {}, 0};
    std::vector<Material> materials;
    for (double x : r.values) materials.push_back(family(x));
    r.images = render_all(renderer, materials);
    r.steps = successive(r.images, image_distance);
    r.cv = coefficient_of_variation(r.steps);
    return r;
  };
  study.baseline =
      row(baseline == Baseline::brdf_l2 ? "brdf_l2" : "linear", study.cumulative_baseline);
  study.image = row("image", study.cumulative_image);
  return study;
}

double truncated_distance(const Eigen::VectorXf& a, const Eigen::VectorXf& b, int k) {
  const Eigen::Index full = a.size() / 3;
  double sum = 0;
  for (Eigen::Index c = 0; c < 3; ++c)
    sum += (a.segment(c * full, k) - b.segment(c * full, k)).squaredNorm();
  return std::sqrt(sum);
}

EmbeddingStudy embedding_study(const Database& db, Renderer& renderer, int pairs,
                               std::uint32_t seed) {
  std::vector<const ModelEmbedding*> models;
  for (const ModelInfo& info : brdfnav::models())
    if (const ModelEmbedding* e = db.embedding(info.id)) models.push_back(e);
  if (models.empty()) throw DatabaseError(db.dir().string() + ": holds no model");
  const int full = models.front()->components();
  std::vector<int> ks;
  for (int k = 4; k < full; k *= 2) ks.push_back(k);
  ks.push_back(full);

  std::mt19937 rng(seed);
  EmbeddingStudy study{pairs, {}, {}};
  study.anywhere = embedding_errors(models, renderer, pairs, false, ks, rng);
  study.on_nodes = embedding_errors(models, renderer, pairs, true, ks, rng);
  return study;
}

}  // namespace brdfnav
