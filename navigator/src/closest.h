// The material of a model that comes closest to the current one in the metric. The models tab
// starts from the current material's best fit by each other model, which the builder found in
// BRDF space; where that fit is farther than eps, the offer is the closest the model comes in
// the image metric instead (the paper's fits and the metric disagree by 1.5x in median,
// docs/VALIDATION.md), and a model that comes within eps that way is walked from there.
#pragma once

#include <brdfnav/core/material.h>
#include <brdfnav/navigator/embedding.h>

#include <Eigen/Core>

namespace brdfnav::nav {

struct Closest {
  Material material;
  double distance;  // embedded, from the centre
  int evaluations;  // embeddings computed
};

// A pattern search from `start` (a material of the embedding's model) over the model's lobe
// parameters, in grid coordinates within the database's range, and a factor on rho_s (its log2
// in [-4, 4], rho_s at most kRhoSMax): each round tries one step up and one down on every
// coordinate and keeps the first that comes closer to `centre`; when none does, the steps halve,
// down to 1/32 of a grid cell. At most `max_evaluations` embeddings; never farther than `start`.
Closest closest_in_model(const ModelEmbedding& embedding, const Eigen::VectorXf& centre,
                         const Material& start, int max_evaluations = 200);

}  // namespace brdfnav::nav
