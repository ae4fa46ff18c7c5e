// Eigen's Levenberg-Marquardt with a forward-difference Jacobian over a residual function, the
// one optimiser of the conversion fits (precompute/src/fit.cpp) and of the image-metric fits
// (studies/src/fit_study.cpp). Public so that the studies fit with the builder's own optimiser:
// an image fit is compared with the database's BRDF-space fit, and the two must differ only in
// what they minimise.
#pragma once

#include <unsupported/Eigen/LevenbergMarquardt>
#include <unsupported/Eigen/NumericalDiff>

#include <utility>

namespace brdfnav {

// Minimises |r(x)|^2 from x, where residual(x, r) fills the `residuals` entries of r, in at most
// max_evaluations evaluations. `step_squared` sets the finite-difference step, sqrt of it
// relative to x (0: Eigen's default, sqrt of the machine epsilon).
template <typename Residual>
Eigen::VectorXd levenberg_marquardt(Residual residual, int residuals, Eigen::VectorXd x,
                                    int max_evaluations, double step_squared = 0) {
  struct Functor : Eigen::DenseFunctor<double> {
    Residual f;
    Functor(Residual r, int n, int m) : DenseFunctor(n, m), f(std::move(r)) {}
    int operator()(const InputType& in, ValueType& out) const {
      f(in, out);
      return 0;
    }
  };
  Functor functor(std::move(residual), static_cast<int>(x.size()), residuals);
  Eigen::NumericalDiff<Functor> numeric(functor, step_squared);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Functor>> lm(numeric);
  lm.setMaxfev(max_evaluations);
  lm.minimize(x);
  return x;
}

}  // namespace brdfnav
