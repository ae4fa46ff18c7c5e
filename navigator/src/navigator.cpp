#include <brdfnav/navigator/navigator.h>

#include "closest.h"
#include "color.h"
#include "kmeans.h"
#include "ring.h"
#include "walk.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace brdfnav {

namespace {

// The start gallery's materials: grey rho_d, and the rho_s that puts each node at the median
// distance from matte grey that the nodes have at rho_s = kGalleryReferenceRhoS. A common
// distance keeps a dim lobe (Cook-Torrance at f0 = 0.01) from looking like matte grey and a
// bright one from standing out by brightness alone: the clusters then differ by lobe shape.
constexpr double kGalleryRhoD = 0.1;
constexpr double kGalleryReferenceRhoS = 0.1;

std::string model_name(ModelId id) {
  return std::string(model_info(id).name);
}

Neighbor neighbor_of(Tab tab, std::string label, const nav::Hit& hit, double distance) {
  Neighbor n{.tab = tab, .label = std::move(label), .material = hit.material, .distance = distance};
  (tab == Tab::diffuse || tab == Tab::specular ? n.clamped : n.at_boundary) = !hit.reached;
  return n;
}

// Every path of one tab walked to the sphere around the current material (the paths' origin).
// A models-tab candidate's path from its model's best fit, and where the walk met the sphere.
struct Walked {
  nav::Path path;
  Material fit;
  nav::Hit hit;
};

std::vector<Neighbor> walk_all(Tab tab, const std::vector<nav::Path>& paths,
                               const ModelEmbedding& embedding, const Material& current,
                               double radius, const ExactSteps* exact) {
  const Eigen::VectorXf centre = embedding.embed(current);
  std::vector<Neighbor> out;
  for (const nav::Path& path : paths) {
    nav::Hit hit = nav::walk_to_sphere(embedding, centre, radius, path);
    if (exact) hit = nav::refine_exactly(path, hit, radius, 0, *exact);
    out.push_back(neighbor_of(tab, path.label, hit, hit.distance));
  }
  return out;
}

void check_query(double radius, int clusters) {
  if (!valid_radius(radius)) {
    char got[32];
    std::snprintf(got, sizeof got, "%g", radius);
    throw NavigatorError("radius: " + radius_requirement() + ", got " + got);
  }
  if (clusters < 1)
    throw NavigatorError("clusters: must be at least 1, got " + std::to_string(clusters));
}

// A material of `model` at the gallery's grey with rho_s = `rho_s`.
Material grey(Material m, double rho_s) {
  m.rho_d = Rgb::Constant(kGalleryRhoD);
  m.rho_s = Rgb::Constant(rho_s);
  return m;
}

}  // namespace

std::string_view tab_name(Tab tab) {
  switch (tab) {
    case Tab::lobe:
      return "lobe";
    case Tab::diffuse:
      return "diffuse";
    case Tab::specular:
      return "specular";
    case Tab::models:
      return "models";
    case Tab::gallery:
      return "gallery";
  }
  return "?";
}

std::optional<Tab> find_tab(std::string_view name) {
  for (Tab tab : kTabs)
    if (tab_name(tab) == name) return tab;
  return std::nullopt;
}

std::vector<std::string_view> flag_names(const Neighbor& n) {
  std::vector<std::string_view> names;
  if (n.at_boundary) names.emplace_back("at_boundary");
  if (n.clamped) names.emplace_back("clamped");
  if (n.beyond_radius) names.emplace_back("beyond_radius");
  return names;
}

Navigator Navigator::open(const std::filesystem::path& dir, const NavigatorOptions& options) {
  return Navigator(Database::open(dir), options);
}

Navigator::Navigator(Database database, const NavigatorOptions& options)
    : database_(std::move(database)), options_(options) {
  if (options_.threads < 1)
    throw NavigatorError("threads: must be at least 1, got " + std::to_string(options_.threads));
  if (!(options_.delta_factor >= 0)) throw NavigatorError("delta_factor: must be non-negative");
  if (database_.manifest().grids.empty())
    throw NavigatorError(database_.dir().string() + ": the database holds no model");
  build_gallery();
}

const ModelEmbedding& Navigator::embedding_of(ModelId id) const {
  if (const ModelEmbedding* e = database_.embedding(id)) return *e;
  throw NavigatorError("material: model '" + model_name(id) + "' is not in the database " +
                       database_.dir().string());
}

std::string radius_requirement() {
  char min[32];
  std::snprintf(min, sizeof min, "%g", kMinRadius);
  return std::string("must be a finite distance of at least ") + min;
}

Material Navigator::start_material() const {
  const ProfileGrid& g = database_.manifest().grids.front();
  Material m = default_material(g.model);
  for (std::size_t d = 0; d < g.grid.dimensions(); ++d) {
    const ParamSpec& spec = g.grid.specs()[d];
    const std::vector<double>& axis = g.grid.axis(d);
    m.params[d] =
        from_scale(spec, (to_scale(spec, axis.front()) + to_scale(spec, axis.back())) / 2);
  }
  m.rho_d = Rgb::Constant(0.2);
  m.rho_s = Rgb::Constant(0.3);
  return m;
}

Eigen::VectorXf Navigator::embed(const Material& m) const {
  require_render_colorspace(m);
  return embedding_of(m.model).embed(m);
}

double Navigator::distance(const Material& a, const Material& b) const {
  return embedding_distance(embed(a), embed(b));
}

Material Navigator::convert(const Material& m, ModelId to) const {
  if (to == m.model) return m;
  const ConversionTable* table = database_.conversion(m.model, to);
  if (!table)
    throw NavigatorError("no conversion from '" + model_name(m.model) + "' to '" + model_name(to) +
                         "' in the database " + database_.dir().string());
  const std::span<const ParamSpec> specs = model_info(to).params;
  std::vector<double> scaled(specs.size(), 0.0);
  Rgb scale = Rgb::Zero();
  for (const ParamGrid::Corner& k : embedding_of(m.model).grid().corners(m.params)) {
    const Conversion& fit = table->nodes[k.node];
    for (std::size_t j = 0; j < specs.size(); ++j)
      scaled[j] += k.weight * to_scale(specs[j], fit.params[j]);
    scale += k.weight * fit.scale;
  }
  // Kept inside the database's grid of `to`: the fits may range wider (the parameter tables'
  // grids), but beyond the grid the embedding cannot tell images apart.
  const ParamGrid& grid = embedding_of(to).grid();
  Material out = default_material(to);
  for (std::size_t j = 0; j < specs.size(); ++j)
    out.params[j] =
        std::clamp(from_scale(specs[j], scaled[j]), grid.axis(j).front(), grid.axis(j).back());
  out.rho_d = m.rho_d;
  out.rho_s = (m.rho_s * scale).max(0.0).min(kRhoSMax);
  out.colorspace = m.colorspace;
  validate(out);
  return out;
}

std::vector<Equivalent> Navigator::equivalents(const Material& m) const {
  validate(m);
  require_render_colorspace(m);
  std::vector<Equivalent> out;
  for (const ProfileGrid& g : database_.manifest().grids) {
    if (g.model == m.model || !database_.conversion(m.model, g.model)) continue;
    Material fit = convert(m, g.model);
    const double residual = distance(m, fit);
    out.push_back({std::move(fit), residual});
  }
  return out;
}

std::vector<Neighbor> Navigator::neighbors(const Material& current, double radius, Tab tab,
                                           int clusters, const ExactSteps* exact) const {
  validate(current);
  require_render_colorspace(current);
  check_query(radius, clusters);
  if (exact && !exact->distance) throw NavigatorError("exact steps: no distance given");
  std::vector<Neighbor> offers = tab_offers(current, radius, tab, clusters, exact);
  nav::describe(offers, current);
  return nav::ring_order(std::move(offers));
}

std::vector<Neighbor> Navigator::tab_offers(const Material& current, double radius, Tab tab,
                                            int clusters, const ExactSteps* exact) const {
  const ModelEmbedding& embedding = embedding_of(current.model);
  switch (tab) {
    case Tab::lobe:
      return lobe_tab(current, radius, exact);
    case Tab::diffuse:
    case Tab::specular:
      return walk_all(tab,
                      nav::color_paths(current, tab == Tab::diffuse ? nav::ColorTerm::diffuse
                                                                    : nav::ColorTerm::specular),
                      embedding, current, radius, exact);
    case Tab::models:
      return models_tab(current, radius, clusters, exact);
    case Tab::gallery:
      return gallery_tab(embedding.embed(current), clusters);
  }
  throw NavigatorError("tab: unknown tab");
}

std::vector<Neighbor> Navigator::gallery(int count) const {
  check_query(1, count);
  std::vector<Neighbor> offers = gallery_tab(embed(matte_), count);
  nav::describe(offers, matte_);
  return offers;
}

std::vector<Neighbor> Navigator::lobe_tab(const Material& current, double radius,
                                          const ExactSteps* exact) const {
  const ModelEmbedding& embedding = embedding_of(current.model);
  return walk_all(Tab::lobe, nav::lobe_paths(current, embedding.grid(), options_.ward_isotropic),
                  embedding, current, radius, exact);
}

namespace {

// The last of `offers`, a models-tab offer found through the embedding, at the exact distance
// `radius` along the path it was walked on from its model's best fit (`walked`; none for a fit
// beyond the radius). A fit that is itself at least `radius` away exactly is offered flagged
// beyond_radius, once per model.
void refine_models_offer(std::vector<Neighbor>& offers, const Walked* walked, double radius,
                         const ExactSteps& exact) {
  Neighbor& n = offers.back();
  const Material fit = walked ? walked->fit : n.material;
  const double fit_distance = exact.distance(fit);
  if (!walked || fit_distance >= radius) {
    const bool offered = std::any_of(offers.begin(), offers.end() - 1, [&](const Neighbor& o) {
      return o.beyond_radius && o.label == n.label;
    });
    if (offered) {
      offers.pop_back();
      return;
    }
    n = {.tab = Tab::models, .label = n.label, .material = fit, .distance = fit_distance};
    n.beyond_radius = true;
    return;
  }
  // The fit's own distance starts the secant: the path leaves from it, not from the current
  // material.
  const nav::Hit moved =
      nav::refine_exactly(walked->path, walked->hit, radius, fit_distance, exact);
  n = neighbor_of(Tab::models, n.label, moved, moved.distance);
}

}  // namespace

// Paper, section 4, with the sphere around the current material: from the current material's
// best fit A' in every other model, that model's neighbours at distance eps from the current
// material along each of its lobe paths from A'. Where the BRDF-space fit is farther than eps,
// A' is the closest material of that model in the metric (nav::closest_in_model); a model whose
// closest is still farther than eps offers it, flagged beyond_radius. Offers within delta of their
// own best fit back in the current model are dropped (the current model shows them already),
// then one is kept per k-means cluster, and of two kept offers within delta of each other only
// the first (they would look the same).
std::vector<Neighbor> Navigator::models_tab(const Material& current, double radius, int clusters,
                                            const ExactSteps* exact) const {
  const Eigen::VectorXf from = embed(current);
  const double delta = options_.delta_factor * radius;
  std::vector<Neighbor> candidates;
  std::vector<Eigen::VectorXf> points;
  // Each candidate's path and the fit it starts from (none for a fit beyond the radius): what
  // exact steps move the kept offers along.
  std::vector<std::optional<Walked>> paths;
  for (const ProfileGrid& g : database_.manifest().grids) {
    if (g.model == current.model || !database_.conversion(current.model, g.model) ||
        !database_.conversion(g.model, current.model))
      continue;
    const ModelEmbedding& embedding = embedding_of(g.model);
    Material fit = convert(current, g.model);
    double residual = embedding_distance(embedding.embed(fit), from);
    if (residual >= radius) {
      // The BRDF-space fit is beyond eps: the closest the model comes in the metric instead,
      // from which the model is walked like from a fit if it comes within eps.
      const nav::Closest closest = nav::closest_in_model(embedding, from, fit);
      fit = closest.material;
      residual = closest.distance;
    }
    Eigen::VectorXf fit_point = embedding.embed(fit);
    if (residual >= radius) {
      Neighbor n{
          .tab = Tab::models, .label = model_name(g.model), .material = fit, .distance = residual};
      n.beyond_radius = true;
      candidates.push_back(std::move(n));
      points.push_back(std::move(fit_point));
      paths.emplace_back();
      continue;
    }
    for (const nav::Path& path : nav::lobe_paths(fit, embedding.grid(), options_.ward_isotropic)) {
      const nav::Hit hit = nav::walk_to_sphere(embedding, from, radius, path, residual);
      Eigen::VectorXf x = embedding.embed(hit.material);
      const Eigen::VectorXf back = embed(convert(hit.material, current.model));
      if (embedding_distance(x, back) < delta) continue;
      candidates.push_back(neighbor_of(Tab::models, model_name(g.model), hit, hit.distance));
      points.push_back(std::move(x));
      paths.emplace_back(Walked{path, fit, hit});
    }
  }
  if (candidates.empty()) return {};
  Eigen::MatrixXf matrix(from.size(), static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    matrix.col(static_cast<Eigen::Index>(i)) = points[i];
  std::vector<Neighbor> out;
  std::vector<std::size_t> kept;
  for (std::size_t i : nav::kmeans_representatives(matrix, {clusters, options_.threads})) {
    const auto alike = [&](std::size_t j) {
      return embedding_distance(points[i], points[j]) < delta;
    };
    if (std::any_of(kept.begin(), kept.end(), alike)) continue;
    kept.push_back(i);
    out.push_back(std::move(candidates[i]));
    if (exact) refine_models_offer(out, paths[i] ? &*paths[i] : nullptr, radius, *exact);
  }
  return out;
}

std::vector<Neighbor> Navigator::gallery_tab(const Eigen::VectorXf& from, int count) const {
  std::vector<Neighbor> out;
  for (std::size_t i :
       nav::kmeans_representatives(gallery_embeddings_, {count, options_.threads})) {
    const Material& m = gallery_materials_[i];
    const auto x = gallery_embeddings_.col(static_cast<Eigen::Index>(i));
    out.push_back({.tab = Tab::gallery,
                   .label = model_name(m.model),
                   .material = m,
                   .distance = static_cast<double>((x - from).norm())});
  }
  return out;
}

void Navigator::build_gallery() {
  matte_ = grey(default_material(database_.manifest().grids.front().model), 0.0);
  const Eigen::VectorXf matte = embed(matte_);
  std::vector<Material> nodes;
  std::vector<double> reference;
  for (const ProfileGrid& g : database_.manifest().grids) {
    for (std::size_t n = 0; n < g.grid.node_count(); ++n) {
      Material m = default_material(g.model);
      m.params = g.grid.node_values(n);
      nodes.push_back(grey(m, 0.0));
      reference.push_back(distance(grey(m, kGalleryReferenceRhoS), matte_));
    }
  }
  std::nth_element(reference.begin(), reference.begin() + reference.size() / 2, reference.end());
  const double common = reference[reference.size() / 2];

  gallery_embeddings_.resize(matte.size(), static_cast<Eigen::Index>(nodes.size()));
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    // rho_s from 0 (matte) up to kRhoSMax, walked to the common distance.
    const Material node = nodes[i];
    const nav::Path path{"", [node](double s) { return grey(node, s); }, {0.0, kRhoSMax}};
    const nav::Hit hit = nav::walk_to_sphere(embedding_of(node.model), matte, common, path);
    gallery_materials_.push_back(hit.material);
    gallery_embeddings_.col(static_cast<Eigen::Index>(i)) = embed(hit.material);
  }
  // The walks read every node's coefficients at every q; later queries read a few nodes'.
  release_pages();
}

void Navigator::release_pages() const {
  for (const ProfileGrid& g : database_.manifest().grids) embedding_of(g.model).release_pages();
}

}  // namespace brdfnav
