#include <brdfnav/navigator/embedding.h>

#include "mapped_file.h"

#include <algorithm>
#include <cmath>

namespace brdfnav {

namespace {

// Locates q on the cube-root q axis: (index, fraction) into q_nodes.
std::pair<std::size_t, double> locate_q(const std::vector<double>& nodes, double q) {
  const double x = std::cbrt(std::clamp(q, 0.0, 1.0));
  std::size_t i = 0;
  while (i + 2 < nodes.size() && std::cbrt(nodes[i + 1]) <= x) ++i;
  const double lo = std::cbrt(nodes[i]), hi = std::cbrt(nodes[i + 1]);
  return {i, std::clamp((x - lo) / (hi - lo), 0.0, 1.0)};
}

}  // namespace

std::vector<double> diffuse_fraction_nodes(int count) {
  std::vector<double> q(count);
  for (int i = 0; i < count; ++i) q[i] = std::pow(double(i) / (count - 1), 3.0);
  q.back() = 1.0;
  return q;
}

ModelEmbedding::ModelEmbedding(ModelId model, ParamGrid grid, std::vector<double> q_nodes,
                               Eigen::MatrixXf coefficients)
    : model_(model),
      grid_(std::move(grid)),
      q_nodes_(std::move(q_nodes)),
      owned_(std::make_shared<const Eigen::MatrixXf>(std::move(coefficients))),
      coefficients_(owned_->data(), owned_->rows(), owned_->cols()) {}

ModelEmbedding::ModelEmbedding(ModelId model, ParamGrid grid, std::vector<double> q_nodes,
                               std::shared_ptr<const db::MappedFile> file,
                               Coefficients coefficients)
    : model_(model),
      grid_(std::move(grid)),
      q_nodes_(std::move(q_nodes)),
      mapped_(std::move(file)),
      coefficients_(coefficients) {}

void ModelEmbedding::release_pages() const {
  if (mapped_) mapped_->release_pages();
}

Eigen::VectorXf ModelEmbedding::channel(const std::vector<ParamGrid::Corner>& corners, double q,
                                        int c) const {
  const auto [qi, qt] = locate_q(q_nodes_, q);
  const std::size_t nodes = grid_.node_count();
  Eigen::VectorXf out = Eigen::VectorXf::Zero(coefficients_.rows());
  for (int dq = 0; dq < 2; ++dq) {
    const double wq = dq == 0 ? 1 - qt : qt;
    if (wq == 0) continue;
    for (const ParamGrid::Corner& k : corners) {
      const auto column = static_cast<Eigen::Index>(((qi + dq) * nodes + k.node) * 3 + c);
      out += static_cast<float>(wq * k.weight) * coefficients_.col(column);
    }
  }
  return out;
}

Eigen::VectorXf ModelEmbedding::embed(const Material& m) const {
  const std::vector<ParamGrid::Corner> corners = grid_.cubic_corners(m.params);
  const Eigen::Index k = coefficients_.rows();
  Eigen::VectorXf out(3 * k);
  for (int c = 0; c < 3; ++c) {
    const double s = m.rho_d[c] + m.rho_s[c];
    if (!(s > 0)) {
      out.segment(c * k, k).setZero();  // black channel: the cube-root image is 0
      continue;
    }
    out.segment(c * k, k) = static_cast<float>(std::cbrt(s)) * channel(corners, m.rho_d[c] / s, c);
  }
  return out;
}

}  // namespace brdfnav
