// Columns computed from the measured forces: response_columns.hpp.
#include "loop/response_columns.hpp"

#include <cmath>
#include <map>

#include <Eigen/Dense>

namespace drawbend::loop {

namespace {

// Residual sum of squares of y on the columns of B (each centred and scaled,
// plus an intercept), by a rank-revealing QR.
double rss(const Eigen::MatrixXd& B, const Eigen::VectorXd& y) {
  const Eigen::Index n = B.rows();
  Eigen::MatrixXd A(n, B.cols() + 1);
  A.col(0).setOnes();
  for (Eigen::Index j = 0; j < B.cols(); ++j) {
    const Eigen::VectorXd c = B.col(j).array() - B.col(j).mean();
    const double s = c.norm();
    A.col(j + 1) = s > 0 ? Eigen::VectorXd(c / s) : c;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  const Eigen::VectorXd r = y - A * qr.solve(y);
  return r.squaredNorm();
}

}  // namespace

std::vector<ResponseColumn> response_columns(const Dataset& data) {
  std::vector<ResponseColumn> out;
  const auto& R = data.rows;
  for (size_t e = 0; e < data.extra_columns.size(); ++e) {
    // Numeric values (NaN: missing), the rows with a value per pin.
    const auto xs = numeric_extra(data, e);
    if (!xs) continue;
    const std::vector<double>& x = *xs;
    std::map<double, std::vector<size_t>> by_pin;
    for (size_t i = 0; i < R.size(); ++i)
      if (std::isfinite(x[i]) && R[i].outlet_force_N > 0 && R[i].back_tension_N > 0) by_pin[R[i].pin_d_mm].push_back(i);
    // Varies within some test?
    std::map<std::string, double> first;
    bool varies = false;
    for (size_t i = 0; i < R.size() && !varies; ++i)
      if (std::isfinite(x[i])) varies = !first.emplace(R[i].test_id, x[i]).second && first[R[i].test_id] != x[i];
    if (!varies) continue;
    double with = 0, without = 0, total = 0;
    for (const auto& [pin, rows] : by_pin) {
      const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
      if (n < 20) continue;
      Eigen::MatrixXd B(n, 8);
      Eigen::VectorXd y(n);
      for (Eigen::Index k = 0; k < n; ++k) {
        const Sample& s = R[rows[k]];
        const double fb = s.back_tension_N, fo = s.outlet_force_N, u = std::log(fo / fb);
        B.row(k) << fb, std::log(fb), fb * fb, fo, std::log(fo), u * u, fo * fo, fo * fb;
        y(k) = x[rows[k]];
      }
      with += rss(B, y);
      without += rss(B.leftCols(3), y);
      total += (y.array() - y.mean()).square().sum();
    }
    // A column the back tension (nearly) determines is not the response's.
    if (total > 0 && without > kResponseFraction * total && with < kResponseFraction * without)
      out.push_back({data.extra_columns[e], with / without});
  }
  return out;
}

}  // namespace drawbend::loop
