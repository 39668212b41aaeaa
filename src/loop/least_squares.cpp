// Levenberg-Marquardt with a forward-difference Jacobian (least_squares.hpp).
#include "loop/least_squares.hpp"

#include <algorithm>
#include <cmath>

namespace drawbend::loop {

double levenberg_marquardt(Eigen::VectorXd& th, const ResidualFn& resid, Eigen::MatrixXd& J, bool& converged) {
  const int p = static_cast<int>(th.size());
  Eigen::VectorXd r = resid(th);
  double sse = r.squaredNorm(), lambda = 1e-3;
  J.resize(r.size(), p);
  auto jacobian = [&]() {
    for (int j = 0; j < p; ++j) {
      Eigen::VectorXd t2 = th;
      const double h = 1e-7 * std::max(1.0, std::abs(th[j]));
      t2[j] += h;
      J.col(j) = (r - resid(t2)) / h;  // d(prediction)/d(theta)
    }
  };
  converged = false;
  for (int it = 0; it < 100; ++it) {
    jacobian();
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 20; ++tries) {
      Eigen::MatrixXd Ad = A;
      for (int j = 0; j < p; ++j) Ad(j, j) += lambda * std::max(A(j, j), 1e-12);
      const Eigen::VectorXd t2 = th + Ad.ldlt().solve(g);
      const Eigen::VectorXd r2 = resid(t2);
      const double s2 = r2.squaredNorm();
      if (std::isfinite(s2) && s2 < sse) {
        const double rel = (sse - s2) / std::max(sse, 1e-300);
        th = t2;
        r = r2;
        sse = s2;
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
        if (rel < 1e-12) converged = true;
        break;
      }
      lambda *= 10;
    }
    if (!improved || converged) {
      converged = true;
      break;
    }
  }
  jacobian();
  return sse;
}

}  // namespace drawbend::loop
