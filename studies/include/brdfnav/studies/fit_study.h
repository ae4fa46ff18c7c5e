// How close conversions fitted in the image metric are to the BRDF-space fits the database
// holds (docs/VALIDATION.md; the paper, section 4, says the two are similar). A fit in the image
// metric minimises the embedded distance to the source material over the target model's
// parameters, with the rho_s scale per channel solved in closed form, so it needs no rendering.
#pragma once

#include <brdfnav/precompute/database.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace brdfnav {

struct ImageFit {
  Material material;  // of the target model
  double distance;    // embedded distance to the target embedding
};

// The material of `model` (parameters inside its embedding's grid, rho_d = 0, RGB rho_s) nearest
// to `target` (an embedding of a material with rho_d = 0, ModelEmbedding::embed's layout):
// Levenberg-Marquardt from the three nodes or cell centres of the grid nearest to `target` and
// from `start`, the best result kept.
ImageFit fit_in_embedding(const ModelEmbedding& model, const Eigen::VectorXf& target,
                          const std::vector<double>& start);

struct FitPairStudy {
  ModelId from, to;
  int samples = 0;
  // Medians over the sampled nodes of `from`: embedded distance from the node's material to
  // its BRDF-space fit (the conversion table) and to its image-metric fit, and between the fits.
  double brdf_fit = 0, image_fit = 0, between = 0;
};

struct FitStudy {
  int per_pair = 0;
  std::vector<FitPairStudy> pairs;  // every ordered pair of the database's models
  // Over every sample: median and p90 of (BRDF-fit distance) / (image-fit distance), >= 1.
  double ratio_median = 0, ratio_p90 = 0;
};

// `per_pair` random nodes (from a fixed seed) of every model, rho_d = 0 and rho_s = 1, each
// converted into every other model both ways.
FitStudy fit_study(const Database& db, int per_pair, std::uint32_t seed = 1);

}  // namespace brdfnav
