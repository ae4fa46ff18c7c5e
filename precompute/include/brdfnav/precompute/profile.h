// Precompute profiles: how dense the database's grids are, at what resolution its images are
// rendered and how many embedding coefficients it keeps (docs/DATABASE.md). Every value of a
// profile is recorded in the database manifest, so a database says exactly how it was made.
#pragma once

#include <brdfnav/core/error.h>
#include <brdfnav/core/grid.h>
#include <brdfnav/core/models.h>
#include <brdfnav/navigator/database.h>
#include <brdfnav/precompute/fit.h>
#include <brdfnav/precompute/pca.h>
#include <brdfnav/renderer/render.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace brdfnav {

using ProfileError = LayerError<struct ProfileErrorTag, ErrorCode::parse>;

struct Profile {
  std::string name;
  int resolution = 128;
  std::vector<ProfileGrid> grids;  // in ModelId order; the named profiles have every model
  int q_nodes = 9;                 // samples of rho_d / (rho_d + rho_s) for the embedding
  PcaOptions pca;                  // pca.components: coefficients kept per channel
  RenderQuality quality;
  FitOptions fit;

  // The grid of `id`, or nullptr when the profile leaves the model out.
  const ParamGrid* grid(ModelId id) const;
  // Total rendered images: the diffuse image plus one specular image per grid node.
  std::size_t image_count() const;
};

// "paper": Table 1 grids at 320 x 320 with 200 coefficients; "default": the same grids at
// 128 x 128 (what `./run demo` uses); "test": grids at 16 x 16 for CI, dense enough for the
// neighbour service's accuracy; "smoke": 2 to 4 nodes per axis at 16 x 16, the whole pipeline in
// about a second, for the CLI, crash-safety and sanitizer tests. Throws ProfileError for any other
// name.
Profile make_profile(const std::string& name);
const std::vector<std::string>& profile_names();

}  // namespace brdfnav
