// Finding the point at distance eps along a path of materials (paper, Figure 5): the one search
// behind every tab of the navigator.
#pragma once

#include <brdfnav/core/grid.h>
#include <brdfnav/core/material.h>
#include <brdfnav/navigator/embedding.h>
#include <brdfnav/navigator/navigator.h>

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace brdfnav::nav {

// Materials of one model along s in [0, breaks.back()], starting at the current one (s = 0).
// Between consecutive breaks the path stays inside one cell of the database grid (or one slice
// of a colour ray), where the embedding is smooth.
struct Path {
  std::string label;
  std::function<Material(double s)> material;
  std::vector<double> breaks;  // increasing, breaks.front() == 0
};

struct Hit {
  Material material;
  double distance;  // embedded, from the centre (or exact, after refine_exactly)
  bool reached;     // false: the whole path stays inside the sphere, `material` is its end
  double s = 0;     // where on the path
};

// Walks `path` segment by segment and finds the crossing of the sphere, on the embedded
// distance, inside the first segment whose end is at least `radius` from `centre`; the hit is
// the crossing's outer side (distance >= radius, within 1e-4 of it). Along one parameter the
// embedding is a cubic inside a grid cell, smooth and nearly straight at the scale of a cell, so
// a path that leaves the sphere inside a segment is still outside at its end. The path starts
// at `start_distance` from the centre (0: at the centre), which must be below `radius`.
Hit walk_to_sphere(const ModelEmbedding& embedding, const Eigen::VectorXf& centre, double radius,
                   const Path& path, double start_distance = 0);

// The hit moved along its path until `exact` (the distance a render measures from the centre's
// material) is within `steps.tolerance` of the radius: secant steps from the embedding's hit,
// the path's start at `start_exact` (0 when it starts at the centre), at most `steps.renders`
// evaluations. Returns the hit whose exact distance is closest to the radius, with that
// distance; a path whose end stays inside the sphere gives its end, not reached.
Hit refine_exactly(const Path& path, const Hit& hit, double radius, double start_exact,
                   const ExactSteps& steps);

// The iso-parameter paths from `m` through `grid`: every parameter up ("<name>+") and down
// ("<name>-"), each in its own scale (log or linear), to the end of the grid. With
// `ward_isotropic`, Ward also gets "alpha+" / "alpha-": both slopes scaled by one factor.
std::vector<Path> lobe_paths(const Material& m, const ParamGrid& grid, bool ward_isotropic);

}  // namespace brdfnav::nav
