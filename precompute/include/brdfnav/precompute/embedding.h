// The builder's side of the unified embedding (brdfnav/navigator/embedding.h): the shared PCA
// basis over every model's cube-root images, and each model's coefficients over its grid.
#pragma once

#include <brdfnav/core/image.h>
#include <brdfnav/navigator/embedding.h>
#include <brdfnav/precompute/pca.h>

#include <vector>

namespace brdfnav {

// What the embedding is built from: the diffuse image (its alpha is the mask shared by every
// image) and, per model, the specular image (rho_s = 1) at every node of its grid.
struct ModelImages {
  ModelId model;
  ParamGrid grid;
  std::vector<Image> specular;  // grid.node_count() images
};

struct Embedding {
  PcaBasis basis;  // over single-channel cube-root images, masked pixels only
  std::vector<ModelEmbedding> models;
};

// Builds the shared basis over every model's (q, node, channel) cube-root images and projects
// them. Throws ImageError when an image's size or mask differs from the diffuse image's.
Embedding build_embedding(const Image& diffuse, const std::vector<ModelImages>& models,
                          const std::vector<double>& q_nodes, const PcaOptions& options);

}  // namespace brdfnav
