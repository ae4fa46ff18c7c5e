// The unified Euclidean embedding of all models (paper, section 3.2), extended to coloured
// materials. Per channel c the cube-root image of a material is
//   cbrt(rho_d,c I_d,c + rho_s,c I_s,c(p)) = s_c^(1/3) cbrt(q_c I_d,c + (1 - q_c) I_s,c(p)),
// with s_c = rho_d,c + rho_s,c and q_c = rho_d,c / s_c in [0, 1] (the paper's rho_d/rho_s axis,
// bounded so that pure diffuse and pure specular are both on the grid). Single-channel cube-root
// images over a grid of (q, p) share one uncentered PCA basis; a material's embedding is the
// concatenation of its three channels' interpolated coefficients, each scaled by s_c^(1/3), and
// the Euclidean distance between embeddings approximates the RMS metric of image.h. This is the
// read side (a material's embedding from stored coefficients); the builder's
// brdfnav/precompute/embedding.h computes the coefficients.
#pragma once

#include <brdfnav/core/grid.h>
#include <brdfnav/core/material.h>

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace brdfnav {

namespace db {
class MappedFile;
}

// `count` values of q = rho_d / (rho_d + rho_s) uniform in cube root, from 0 to 1: the cube
// root image changes fastest near q = 0, where a little diffuse light fills the dark pixels.
std::vector<double> diffuse_fraction_nodes(int count);

// Embedding coefficients of one model over its (q, parameter) grid. Copies share the
// coefficients, which are immutable.
class ModelEmbedding {
 public:
  using Coefficients = Eigen::Map<const Eigen::MatrixXf>;

  // `coefficients` is k x (q_nodes.size() * grid.node_count() * 3); column
  // (qi * node_count + node) * 3 + channel, already scaled so that Euclidean distance is the
  // metric.
  ModelEmbedding(ModelId model, ParamGrid grid, std::vector<double> q_nodes,
                 Eigen::MatrixXf coefficients);
  // The same matrix in a mapped database file, column-major; the embedding keeps the file.
  ModelEmbedding(ModelId model, ParamGrid grid, std::vector<double> q_nodes,
                 std::shared_ptr<const db::MappedFile> file, Coefficients coefficients);

  ModelId model() const { return model_; }
  const ParamGrid& grid() const { return grid_; }
  const std::vector<double>& q_nodes() const { return q_nodes_; }
  const Coefficients& coefficients() const { return coefficients_; }
  int components() const { return static_cast<int>(coefficients_.rows()); }

  // Gives back this process's pages of a mapped file's coefficients: they stay in the system's
  // page cache and are mapped again when next read. For a pass that touched every node (the
  // gallery), so that the process keeps only what later queries read. Nothing for an owned
  // matrix.
  void release_pages() const;

  // The 3k-vector of a material of this model (parameters off the grid are interpolated by
  // the cubic spline of ParamGrid::cubic_corners in grid coordinates, which follows the images'
  // change between sparse nodes far better than multilinear interpolation; outside the grid
  // they are clamped to it).
  Eigen::VectorXf embed(const Material& m) const;

 private:
  // Coefficients of one channel of cbrt(q I_d + (1 - q) I_s(p)), interpolated.
  Eigen::VectorXf channel(const std::vector<ParamGrid::Corner>& corners, double q,
                          int channel) const;

  ModelId model_;
  ParamGrid grid_;
  std::vector<double> q_nodes_;
  std::shared_ptr<const Eigen::MatrixXf> owned_;  // one of the two holds the coefficients
  std::shared_ptr<const db::MappedFile> mapped_;
  Coefficients coefficients_;
};

// Euclidean distance between two embeddings (the metric's approximation).
inline double embedding_distance(const Eigen::VectorXf& a, const Eigen::VectorXf& b) {
  return static_cast<double>((a - b).norm());
}

}  // namespace brdfnav
