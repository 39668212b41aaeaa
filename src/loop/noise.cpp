// Replicate noise from within-test scatter; see noise.hpp.
#include "loop/noise.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

namespace drawbend::loop {

NoiseFloor replicate_noise(const Design& d, const std::vector<double>* values) {
  NoiseFloor nf;
  const auto& R = d.data->rows;
  nf.order = d.data->has_time ? "time_s" : d.data->has_sliding ? "sliding_distance_mm" : "file";
  std::map<std::string, std::vector<int>> tests;
  if (values && values->size() != R.size())
    throw std::logic_error("replicate_noise: " + std::to_string(values->size()) + " values for " +
                           std::to_string(R.size()) + " rows");
  const auto y_of = [&](size_t i) { return values ? (*values)[i] : R[i].outlet_force_N; };
  for (size_t i = 0; i < R.size(); ++i)
    if (!values || std::isfinite(y_of(i))) tests[R[i].test_id].push_back(static_cast<int>(i));
  double num = 0, den = 0, mean_y = 0;
  for (const auto& s : R) mean_y += std::abs(s.outlet_force_N) / R.size();
  for (auto& [id, ix] : tests) {
    const int n = static_cast<int>(ix.size());
    if (n < 4) continue;
    std::stable_sort(ix.begin(), ix.end(), [&](int a, int b) {
      if (d.data->has_time) return R[a].time_s < R[b].time_s;
      if (d.data->has_sliding) return R[a].sliding_mm < R[b].sliding_mm;
      return R[a].line < R[b].line;
    });
    // Columns: 1, F and F^2 (F the back tension scaled to [-1, 1] within the
    // test), and the run position t in [-1, 1] up to t^3; fewer with few rows.
    const int q = n >= 8 ? 6 : n >= 6 ? 4 : 2;
    double fmin = INFINITY, fmax = -INFINITY;
    for (int k = 0; k < n; ++k)
      fmin = std::min(fmin, R[ix[k]].back_tension_N), fmax = std::max(fmax, R[ix[k]].back_tension_N);
    Eigen::MatrixXd X(n, q);
    Eigen::VectorXd y(n);
    for (int k = 0; k < n; ++k) {
      const double t = n > 1 ? 2.0 * k / (n - 1) - 1 : 0;
      const double F = fmax > fmin ? 2 * (R[ix[k]].back_tension_N - fmin) / (fmax - fmin) - 1 : 0;
      X(k, 0) = 1;
      X(k, 1) = F;
      if (q >= 4) X(k, 2) = t, X(k, 3) = t * t;
      if (q >= 6) X(k, 4) = F * F, X(k, 5) = t * t * t;
      y[k] = y_of(static_cast<size_t>(ix[k]));
    }
    const auto qr = X.colPivHouseholderQr();
    const int rank = static_cast<int>(qr.rank());
    if (n - rank < 1) continue;
    const Eigen::VectorXd e = y - X * qr.solve(y);
    num += e.squaredNorm();
    den += n - rank;
    nf.tests++;
    nf.rows += n;
  }
  if (den > 0) {
    nf.sigma_N = std::sqrt(num / den);
    nf.dof = den;
    nf.exact = nf.sigma_N < 1e-6 * std::max(1.0, mean_y);
  }
  return nf;
}

}  // namespace drawbend::loop
