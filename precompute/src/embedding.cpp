#include <brdfnav/precompute/embedding.h>

#include <brdfnav/core/cube_root.h>

#include <algorithm>
#include <cmath>

namespace brdfnav {

namespace {

// Masked pixels of one image, one channel each: pixels x 3.
Eigen::MatrixXf masked_channels(const Image& image, const Image& mask_source,
                                const std::vector<std::size_t>& covered) {
  if (image.width != mask_source.width || image.height != mask_source.height)
    throw ImageError("embedding: image size " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " differs from the diffuse image's");
  Eigen::MatrixXf out(static_cast<Eigen::Index>(covered.size()), 3);
  for (std::size_t i = 0; i < covered.size(); ++i) {
    const float* px = &image.rgba[4 * covered[i]];
    if (px[3] < 0.5f) throw ImageError("embedding: image mask differs from the diffuse image's");
    for (int c = 0; c < 3; ++c) out(static_cast<Eigen::Index>(i), c) = px[c];
  }
  return out;
}

std::vector<std::size_t> covered_pixels(const Image& diffuse) {
  std::vector<std::size_t> covered;
  for (std::size_t i = 0; i < diffuse.rgba.size() / 4; ++i)
    if (diffuse.rgba[4 * i + 3] > 0.5f) covered.push_back(i);
  if (covered.empty()) throw ImageError("embedding: the diffuse image covers no pixel");
  return covered;
}

}  // namespace

Embedding build_embedding(const Image& diffuse, const std::vector<ModelImages>& models,
                          const std::vector<double>& q_nodes, const PcaOptions& options) {
  const std::vector<std::size_t> covered = covered_pixels(diffuse);
  const Eigen::MatrixXf id = masked_channels(diffuse, diffuse, covered);
  std::vector<Eigen::MatrixXf> spec;  // every model's node images, in model order
  std::vector<std::size_t> first_column;
  std::size_t cols = 0;
  for (const ModelImages& m : models) {
    first_column.push_back(cols);
    for (const Image& img : m.specular) spec.push_back(masked_channels(img, diffuse, covered));
    cols += q_nodes.size() * m.grid.node_count() * 3;
  }

  // Column j of the data matrix: model by first_column, then (qi * nodes + node) * 3 + channel;
  // scaled by 1/sqrt(3 * pixels) so that Euclidean distance is the RMS metric.
  const float norm = 1.0f / std::sqrt(3.0f * static_cast<float>(covered.size()));
  const auto column = [&](std::size_t j, std::size_t first_row, Eigen::Ref<Eigen::VectorXf> out) {
    const std::size_t mi =
        std::upper_bound(first_column.begin(), first_column.end(), j) - first_column.begin() - 1;
    const std::size_t nodes = models[mi].grid.node_count(), local = j - first_column[mi];
    std::size_t image = local / 3 % nodes;
    for (std::size_t i = 0; i < mi; ++i) image += models[i].grid.node_count();
    const auto q = float(q_nodes[local / 3 / nodes]);
    const auto c = static_cast<Eigen::Index>(local % 3);
    const float* d = &id(static_cast<Eigen::Index>(first_row), c);
    const float* s = &spec[image](static_cast<Eigen::Index>(first_row), c);
    for (Eigen::Index p = 0; p < out.size(); ++p)
      out[p] = norm * cube_root(q * d[p] + (1 - q) * s[p]);
  };
  const BlockSource source = [&](std::size_t first_row, std::size_t first_col,
                                 Eigen::Ref<Eigen::MatrixXf> block) {
    for (Eigen::Index b = 0; b < block.cols(); ++b) column(first_col + b, first_row, block.col(b));
  };

  Embedding e;
  e.basis = uncentered_pca(covered.size(), cols, source, options);
  for (std::size_t mi = 0; mi < models.size(); ++mi) {
    const auto n = static_cast<Eigen::Index>(q_nodes.size() * models[mi].grid.node_count() * 3);
    e.models.emplace_back(
        models[mi].model, models[mi].grid, q_nodes,
        e.basis.coefficients.middleCols(static_cast<Eigen::Index>(first_column[mi]), n));
  }
  return e;
}

}  // namespace brdfnav
