#include <brdfnav/precompute/profile.h>

#include <cmath>

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

// `count` nodes over [min, max] whose steps in the parameter's scale grow by `ratio` from min:
// crowded where the images change fastest, smooth for the spline (ParamGrid::cubic_corners).
std::vector<double> graded_between(ModelId id, std::size_t d, double min, double max, int count,
                                   double ratio) {
  const ParamSpec& spec = model_info(id).params[d];
  const double lo = to_scale(spec, min), span = to_scale(spec, max) - lo;
  const double first = span * (ratio - 1) / (std::pow(ratio, count - 1) - 1);
  std::vector<double> nodes{min};
  double at = lo, step = first;
  for (int k = 1; k + 1 < count; ++k, step *= ratio) nodes.push_back(from_scale(spec, at += step));
  nodes.push_back(max);
  return nodes;
}

// `count` nodes evenly spaced in the parameter's scale over its table's grid range (a denser or
// coarser version of the table's own axis).
std::vector<double> table_axis(ModelId id, std::size_t d, int count) {
  const ParamSpec& spec = model_info(id).params[d];
  return axis_between(id, d, spec.grid_min, spec.grid_max, count);
}

// Nodes on [lo, hi] with one at `centre`: `first` apart beside it, the steps then growing by
// a constant ratio on each side, solved so that `left` steps reach lo and `right` steps hi.
// Catmull-Rom weights assume even steps; a constant ratio close to 1 keeps neighbouring cells
// nearly even while the nodes crowd where the images change fastest.
std::vector<double> graded_axis(double lo, double centre, double hi, double first, int left,
                                int right) {
  const auto side = [first](double span, int steps) {
    double a = 1.0, b = 4.0;  // sum of first * r^k, k < steps, grows with r
    for (int i = 0; i < 200; ++i) {
      const double r = 0.5 * (a + b);
      double sum = 0, step = first;
      for (int k = 0; k < steps; ++k, step *= r) sum += step;
      (sum > span ? b : a) = r;
    }
    std::vector<double> offsets;
    double sum = 0, step = first;
    for (int k = 0; k < steps; ++k, step *= a) offsets.push_back(sum += step);
    offsets.back() = span;  // exactly at the end
    return offsets;
  };
  std::vector<double> nodes;
  const std::vector<double> below = side(centre - lo, left), above = side(hi - centre, right);
  for (auto d = below.rbegin(); d != below.rend(); ++d) nodes.push_back(centre - *d);
  nodes.push_back(centre);
  for (double d : above) nodes.push_back(centre + d);
  return nodes;
}

// The default profile's grids: the tables' own for Blinn-Phong, Ward, Cook-Torrance and GGX,
// whose blend check (docs/DATABASE.md) vouched for nearly every cell; denser for He and
// Lafortune, where the table's grids left the thumbnails' blend far from the render between
// nodes, so that every image of theirs had to be rendered while the artist waited. Measured
// along one axis at a time, at the midpoints between nodes, at 128 px:
// - He's eta: the table's five nodes (1.2, 1.5, 2, 4, 9) were 0.1-0.3 eps off, the Fresnel
//   factor turning fast near eta = 1. Ten evenly spaced in log eta from 1.1: within 0.04 eps
//   above eta = 1.39, but the first cell (1.1-1.39), where the factor turns fastest, 0.27 eps
//   (0.17 with the spline's quadratic ends). Ten graded in log eta, each step 1.3 times the one
//   before (1.1, 1.14, ...; 3.1 times finer at 1.1): within 0.020 eps in every cell at five
//   sigma-tau pairs from (0.02, 2) to (2.56, 128). Still one pass of the renderer per sigma
//   and tau (kFresnelBatch).
// - He's sigma and tau: up to 0.22 eps between the table's nodes; 0.06 with twice as many.
//   He's images along eta share their quadrature (one pass per sigma and tau), so its 2,550
//   images take a few minutes.
// - Lafortune's cz: up to 0.6 eps between the table's nodes. Its switch at 1/sqrt(3) narrows
//   like 1/n: the lobe's grazing part fades like exp(-2.6 n |cz - 1/sqrt(3)|), and the images'
//   slope jumps there (ParamSpec::kink). Graded from 0.001 apart (51 nodes), the cells beside the
//   switch were 0.1 eps off at n = 100 and 9.9 at n = 16,384. Along cz at n = 16,384, 2e-5 apart
//   with the spline one-sided at the kink: within 0.084 eps (0.40 with it reaching across). 91
//   nodes: 2e-5 apart at the switch, each step about 1.21 times the one before, out to 0 and 1.
// - Lafortune's n: up to 0.11 eps between the table's 13 nodes; 19.
std::vector<ProfileGrid> default_grids() {
  using M = ModelId;
  std::vector<ProfileGrid> grids = table_grids();
  for (ProfileGrid& g : grids) {
    if (g.model == M::he)
      g = grid_of(M::he, {table_axis(M::he, 0, 15), table_axis(M::he, 1, 17),
                          graded_between(M::he, 2, 1.1, 9.0, 10, 1.3)});
    if (g.model == M::lafortune)
      g = grid_of(M::lafortune, {graded_axis(0.0, 1 / std::sqrt(3.0), 1.0, 2e-5, 46, 44),
                                 table_axis(M::lafortune, 1, 19)});
  }
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
