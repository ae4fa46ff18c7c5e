// Model-to-model conversion (paper, section 4): the parameters of model B, with an RGB rho_s
// scale, whose lobe is closest to a target lobe in the cosine-weighted BRDF-space L2 metric
//   E(p, s) = sum_c integral (f_A,c(wi, wo) - s_c f_B(wi, wo; p))^2 cos_i cos_o dwi dwo.
// The scale is solved in closed form for every p (variable projection); p is found by
// Levenberg-Marquardt (Eigen) from the best grid nodes of B.
#pragma once

#include <brdfnav/core/models.h>

#include <vector>

namespace brdfnav {

// Direction pairs and weights such that sum_k w_k g(wi_k, wo_k) approximates
// integral g cos_i cos_o dwi dwo over both hemispheres. Outgoing directions are stratified in
// cos_o; incident directions are importance-sampled from a mixture of the target lobe's own
// sampler and the cosine, so sharp targets are resolved (deterministic: fixed strata).
struct FitQuadrature {
  std::vector<Vec3> wi, wo;
  std::vector<double> weight;
};
FitQuadrature make_fit_quadrature(const Lobe& target, int n_wo, int n_wi);

struct FitOptions {
  int n_wo = 8;    // outgoing directions of the quadrature
  int n_wi = 192;  // incident directions per outgoing direction
  int starts = 3;  // LM runs from the best grid nodes
  int max_iterations = 60;
};

struct LobeFit {
  ModelId model;
  std::vector<double> params;  // in model_info(model).params order
  Rgb scale;                   // rho_s multiplier: target ~= scale * lobe_B(params)
  double relative_error;       // sqrt(E / integral |f_A|^2 cos cos), at the fit's quadrature
  int evaluations;             // objective evaluations spent (for the benchmark)
};

// Best fit of `target` (a lobe with rho_s = 1) by a lobe of `model`, with the parameters kept
// inside the model's grid range.
LobeFit fit_lobe(const Lobe& target, ModelId model, const FitOptions& options = {});

}  // namespace brdfnav
