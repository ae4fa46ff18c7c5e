#include <brdfnav/precompute/profile.h>

namespace brdfnav {

namespace {

// The parameter tables' own grids: Table 1 of the paper with this project's ranges.
std::vector<ProfileGrid> table_grids() {
  std::vector<ProfileGrid> grids;
  for (const ModelInfo& m : models()) grids.push_back({m.id, ParamGrid(m.params)});
  return grids;
}

ProfileGrid grid_of(ModelId id, std::vector<std::vector<double>> axes) {
  return {id, ParamGrid(model_info(id).params, std::move(axes))};
}

// `count` nodes evenly spaced in the parameter's scale over [min, max].
std::vector<double> axis_between(ModelId id, std::size_t d, double min, double max, int count) {
  ParamSpec spec = model_info(id).params[d];
  spec.nodes = {};
  spec.grid_min = min;
  spec.grid_max = max;
  spec.grid_count = count;
  return grid_nodes(spec);
}

// `count` nodes evenly spaced in the parameter's scale over its table's grid range (a denser or
// coarser version of the table's own axis).
std::vector<double> table_axis(ModelId id, std::size_t d, int count) {
  const ParamSpec& spec = model_info(id).params[d];
  return axis_between(id, d, spec.grid_min, spec.grid_max, count);
}

// The default profile's grids: the tables' own, but He's eta. With the table's five etas
// (1.2, 1.5, 2, 4, 9) the blend check (docs/DATABASE.md) vouched for no He cell: along eta alone
// the thumbnails' blend was 0.1-0.3 eps from the render at a cell's midpoint, because the
// Fresnel factor turns fast near eta = 1 and the Catmull-Rom weights assume even steps that the
// table's (in log eta) are not. Ten nodes evenly spaced in log eta from 1.1 keep every cell
// above eta = 1.39 within 0.04 eps along eta; the first (1.1-1.39), where the factor turns
// fastest, stays 0.14-0.27 eps and its materials are rendered. The images along eta of one
// (sigma, tau) share their quadrature (Renderer::specular of several lobes): twice the nodes
// cost far less than twice the time.
std::vector<ProfileGrid> default_grids() {
  std::vector<ProfileGrid> grids = table_grids();
  for (ProfileGrid& g : grids)
    if (g.model == ModelId::he)
      g = grid_of(ModelId::he,
                  {g.grid.axis(0), g.grid.axis(1), axis_between(ModelId::he, 2, 1.1, 9.0, 10)});
  return grids;
}

// The test profile's grids: the tables' ranges (Lafortune's cz in the band around
// 1/sqrt(3) where its lobe shows, He's eta 1.5..4), as densely as the neighbour service needs at
// 16 x 16. The counts were raised until neighbours at embedded distance eps rendered at eps
// within 5% (median) and 10% (90th percentile) over 10 random materials per model and several
// seeds (docs/NAVIGATION.md, Accuracy): the spline between nodes models the images only where a
// cell is small against the image's curvature, and eps = 0.01 is a small step.
std::vector<ProfileGrid> test_grids() {
  using M = ModelId;
  std::vector<ProfileGrid> grids;
  grids.push_back(grid_of(M::blinn_phong, {table_axis(M::blinn_phong, 0, 20)}));
  grids.push_back(grid_of(M::ward, {table_axis(M::ward, 0, 19), table_axis(M::ward, 1, 19)}));
  grids.push_back(grid_of(
      M::cook_torrance, {table_axis(M::cook_torrance, 0, 8), table_axis(M::cook_torrance, 1, 14)}));
  grids.push_back(
      grid_of(M::lafortune, {{0.54, 0.55, 0.555, 0.56, 0.565, 0.57, 0.572, 0.575,
                              0.57735026918962573, 0.58, 0.5825, 0.585, 0.59, 0.595, 0.6},
                             table_axis(M::lafortune, 1, 20)}));
  grids.push_back(grid_of(
      M::he, {table_axis(M::he, 0, 12), table_axis(M::he, 1, 12), {1.5, 1.9, 2.5, 3.2, 4}}));
  grids.push_back(grid_of(M::ggx, {table_axis(M::ggx, 0, 17), table_axis(M::ggx, 1, 17)}));
  return grids;
}

// The smoke profile's grids: 2 to 4 nodes per axis over the same ranges. Enough for every stage
// of the pipeline, nothing more: its neighbours are not at eps.
std::vector<ProfileGrid> smoke_grids() {
  std::vector<ProfileGrid> grids;
  grids.push_back(grid_of(ModelId::blinn_phong, {{2, 50, 1200, 80000}}));
  grids.push_back(grid_of(ModelId::ward, {{0.005, 0.05, 0.5}, {0.005, 0.05, 0.5}}));
  grids.push_back(grid_of(ModelId::cook_torrance, {{0.01, 1}, {0.005, 0.06, 0.7}}));
  grids.push_back(grid_of(ModelId::lafortune, {{0.54, 0.57735026918962573, 0.6}, {2, 16384}}));
  grids.push_back(grid_of(ModelId::he, {{0.02, 2.56}, {2, 128}, {1.5, 4}}));
  grids.push_back(grid_of(ModelId::ggx, {{0.01, 0.1, 1}, {0.01, 0.1, 1}}));
  return grids;
}

// What the test and smoke profiles share: 16 x 16 images and a coarse fit quadrature (they check
// the pipeline and the navigation, not the fits' accuracy).
Profile small_profile(const std::string& name, std::vector<ProfileGrid> grids, int q_nodes,
                      int components) {
  Profile p;
  p.name = name;
  p.resolution = 16;
  p.grids = std::move(grids);
  p.q_nodes = q_nodes;
  p.pca.components = components;
  p.fit.n_wo = 4;
  p.fit.n_wi = 48;
  p.fit.starts = 1;
  return p;
}

}  // namespace

std::size_t Profile::image_count() const {
  std::size_t n = 1;
  for (const ProfileGrid& g : grids) n += g.grid.node_count();
  return n;
}

const ParamGrid* Profile::grid(ModelId id) const {
  for (const ProfileGrid& g : grids)
    if (g.model == id) return &g.grid;
  return nullptr;
}

const std::vector<std::string>& profile_names() {
  static const std::vector<std::string> names{"test", "smoke", "default", "paper"};
  return names;
}

Profile make_profile(const std::string& name) {
  // About 15 s on a 2-core machine (docs/DATABASE.md). 9 samples of the colour ratio as in the
  // other profiles, and 100 of the ~200 covered pixels' dimensions, keep the colour tabs' and the
  // lobe tab's neighbours at eps (5 samples: the diffuse tab's p90 was 12.5% instead of 5.3%).
  if (name == "test") return small_profile(name, test_grids(), 9, 100);
  if (name == "smoke") return small_profile(name, smoke_grids(), 5, 24);  // about 1 s
  if (name != "paper" && name != "default")
    throw ProfileError("unknown precompute profile '" + name +
                       "' (expected test, smoke, default or paper)");
  Profile p;
  p.name = name;
  p.resolution = name == "paper" ? 320 : 128;
  p.grids = name == "paper" ? table_grids() : default_grids();
  p.pca.components = 200;
  return p;
}

}  // namespace brdfnav
