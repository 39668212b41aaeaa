#include "analysis/new_method.hpp"

#include <cmath>
#include <stdexcept>

namespace drawbend::analysis {

double PressureMap::moment(int n) const {
  double s = 0.0;
  for (std::size_t i = 0; i < p_MPa.size(); ++i) s += std::pow(p_MPa[i], n) * area_mm2[i];
  return s;
}

PressureMap PressureMap::scaled_areas(double factor) const {
  PressureMap m = *this;
  for (auto& a : m.area_mm2) a *= factor;
  return m;
}

void PressureMap::validate() const {
  if (p_MPa.size() != area_mm2.size())
    throw std::invalid_argument("pressure map '" + label + "': pressure and area lists differ in length");
  if (p_MPa.empty()) throw std::invalid_argument("pressure map '" + label + "' is empty");
  for (std::size_t i = 0; i < p_MPa.size(); ++i) {
    if (!std::isfinite(p_MPa[i]) || p_MPa[i] < 0.0)
      throw std::invalid_argument("pressure map '" + label + "': node " + std::to_string(i) +
                                  " has a negative or non-finite pressure");
    if (!std::isfinite(area_mm2[i]) || area_mm2[i] < 0.0)
      throw std::invalid_argument("pressure map '" + label + "': node " + std::to_string(i) +
                                  " has a negative or non-finite area");
  }
}

double predicted_friction_force(const PressureMap& map, double c, const Polynomial& mu) {
  map.validate();
  double F = 0.0;
  for (std::size_t i = 0; i < map.p_MPa.size(); ++i) {
    const double p = c * map.p_MPa[i];
    F += mu(p) * p * map.area_mm2[i];
  }
  return F;
}

NewMethodResult solve_new_method(const std::vector<PinTest>& pins, int order) {
  if (order < 0) throw std::invalid_argument("new method: polynomial order must be >= 0");
  const int n = order + 1;
  const int m = static_cast<int>(pins.size());
  if (m < n)
    throw std::invalid_argument("new method: " + std::to_string(m) + " pin(s) cannot determine " +
                                std::to_string(n) + " coefficient(s); use more pins or a lower order");
  NewMethodResult r;
  r.M.resize(m, n);
  r.rhs.resize(m);
  for (int j = 0; j < m; ++j) {
    pins[j].map.validate();
    if (!(pins[j].c > 0.0)) throw std::invalid_argument("new method: c must be > 0 for pin " + std::to_string(j));
    for (int k = 0; k < n; ++k) r.M(j, k) = std::pow(pins[j].c, k + 1) * pins[j].map.moment(k + 1);
    r.rhs(j) = pins[j].friction_force_N;
  }
  // Scale columns so that the conditioning reflects the problem, not the units.
  Eigen::VectorXd scale = r.M.colwise().norm().transpose();
  for (int k = 0; k < n; ++k)
    if (scale(k) == 0.0) throw std::invalid_argument("new method: all pressure moments vanish (empty contact?)");
  const Eigen::MatrixXd Ms = r.M * scale.cwiseInverse().asDiagonal();
  Eigen::VectorXd a;
  if (m == n) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Ms);
    if (!lu.isInvertible()) throw std::runtime_error("new method: the pin maps are linearly dependent");
    a = lu.solve(r.rhs);
  } else {
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Ms);
    if (qr.rank() < n) throw std::runtime_error("new method: the pin maps are linearly dependent (rank-deficient)");
    a = qr.solve(r.rhs);
    r.least_squares = true;
  }
  a = a.cwiseQuotient(scale);
  r.mu.a.assign(a.data(), a.data() + n);
  r.residual_N = (r.M * a - r.rhs).norm();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Ms);
  const auto sv = svd.singularValues();
  r.condition = sv(sv.size() - 1) > 0 ? sv(0) / sv(sv.size() - 1) : INFINITY;
  return r;
}

}  // namespace drawbend::analysis
