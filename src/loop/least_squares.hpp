// Levenberg-Marquardt for the loop's nonlinear least-squares fits.
//
// Contract:
//  - minimises |r(theta)|^2 from the given start; returns the final SSE and
//    leaves J = d(prediction)/d(theta) = -dr/dtheta (forward differences,
//    step 1e-7 max(1, |theta_j|)) at the solution, for standard errors;
//  - `converged` is set when a step gains less than 1e-12 of the SSE or no
//    step (up to 20 damping increases) lowers it; at most 100 iterations;
#pragma once

#include <functional>

#include <Eigen/Dense>

namespace drawbend::loop {

using ResidualFn = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

double levenberg_marquardt(Eigen::VectorXd& th, const ResidualFn& resid, Eigen::MatrixXd& J, bool& converged);

}  // namespace drawbend::loop
