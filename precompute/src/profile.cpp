#include <brdfnav/precompute/profile.h>

namespace brdfnav {

namespace {

// The parameter tables' own grids: Table 1 of the paper with the reference sheet's ranges.
std::vector<ProfileGrid> table_grids() {
  std::vector<ProfileGrid> grids;
  for (const ModelInfo& m : models()) grids.push_back({m.id, ParamGrid(m.params)});
  return grids;
}

ProfileGrid grid_of(ModelId id, std::vector<std::vector<double>> axes) {
  return {id, ParamGrid(model_info(id).params, std::move(axes))};
}

// Small grids that still span the tables' ranges. Lafortune keeps cz = 1/sqrt(3) (the Phong
// lobe) with close nodes either side, where the lobe changes fastest. He is the slowest model to
// render, so it gets the fewest nodes.
std::vector<ProfileGrid> test_grids() {
  std::vector<ProfileGrid> grids;
  grids.push_back(grid_of(ModelId::blinn_phong, {{2, 50, 1200, 80000}}));
  grids.push_back(grid_of(ModelId::ward, {{0.005, 0.05, 0.5}, {0.005, 0.05, 0.5}}));
  grids.push_back(grid_of(ModelId::cook_torrance, {{0.01, 1}, {0.005, 0.06, 0.7}}));
  grids.push_back(grid_of(ModelId::lafortune, {{0.54, 0.57735026918962573, 0.6}, {2, 16384}}));
  grids.push_back(grid_of(ModelId::he, {{0.02, 2.56}, {2, 128}, {1.5, 4}}));
  return grids;
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
  static const std::vector<std::string> names{"test", "default", "paper"};
  return names;
}

Profile make_profile(const std::string& name) {
  Profile p;
  p.name = name;
  p.pca.components = 200;
  if (name == "paper") {
    p.resolution = 320;
    p.grids = table_grids();
  } else if (name == "default") {
    p.resolution = 128;
    p.grids = table_grids();
  } else if (name == "test") {
    // The renderer sets this: He's eight images are most of the build, which takes about 30 s
    // at 16 x 16 on a 2-core machine (docs/DATABASE.md).
    p.resolution = 16;
    p.grids = test_grids();
    p.q_nodes = 5;
    p.pca.components = 24;
    // A coarser fit quadrature: the test profile checks the pipeline, not the fits' accuracy.
    p.fit.n_wo = 4;
    p.fit.n_wi = 48;
    p.fit.starts = 1;
  } else {
    throw ProfileError("unknown precompute profile '" + name +
                       "' (expected test, default or paper)");
  }
  return p;
}

}  // namespace brdfnav
