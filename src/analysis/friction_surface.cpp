#include "analysis/friction_surface.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

namespace drawbend::analysis {

namespace {
// One-dimensional quadratic Lagrange functions on nodes -1, 0, +1.
std::array<double, 3> lagrange3(double s) {
  return {0.5 * (s * s - s), 1.0 - s * s, 0.5 * (s * s + s)};
}
}  // namespace

std::array<double, 9> nine_node_shape(double xi, double eta) {
  const auto a = lagrange3(xi), b = lagrange3(eta);
  std::array<double, 9> N{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) N[3 * i + j] = a[i] * b[j];
  return N;
}

std::array<double, 9> nine_node_shape_as_printed(double xi, double eta) {
  auto N = nine_node_shape(xi, eta);
  N[4] = 0.5 * (1.0 - xi * xi) * (eta * eta - eta);  // printed N5 = printed N4
  return N;
}

double FrictionSurface::operator()(double p, double v) const {
  const auto N = nine_node_shape(xi(p), eta(v));
  double m = 0.0;
  for (int k = 0; k < 9; ++k) m += N[k] * mu[k];
  return m;
}

void FrictionSurface::validate() const {
  auto bad = [](const std::string& what) { throw std::invalid_argument("friction surface: " + what); };
  if (!(std::isfinite(p_min) && std::isfinite(p_max) && p_min < p_max))
    bad("expected pressure nodes in increasing order (p_min < p_max), found p_min = " + std::to_string(p_min) +
        " MPa, p_max = " + std::to_string(p_max) + " MPa");
  if (!(std::isfinite(v_max) && v_min > 0 && v_min < v_max))
    bad("expected speed nodes in increasing order (0 < v_min < v_max), found v_min = " + std::to_string(v_min) +
        " mm/s, v_max = " + std::to_string(v_max) + " mm/s");
  for (int k = 0; k < 9; ++k)
    if (!std::isfinite(mu[k])) bad("expected finite nodal values, found mu_" + std::to_string(k + 1) + " = " + std::to_string(mu[k]));
}

FrictionSurface surface_from_lines(const std::vector<SpeedLine>& lines, double p_min, double p_max,
                                   bool use_printed_eta) {
  if (lines.size() != 3) throw std::invalid_argument("surface_from_lines: need exactly three speed lines");
  if (!(lines[0].v_mm_s < lines[1].v_mm_s && lines[1].v_mm_s < lines[2].v_mm_s))
    throw std::invalid_argument("surface_from_lines: speeds must increase strictly");
  if (!(p_min < p_max)) throw std::invalid_argument("surface_from_lines: p_min must be < p_max");
  FrictionSurface s;
  s.p_min = p_min;
  s.p_max = p_max;
  s.v_min = lines[0].v_mm_s;
  s.v_max = lines[2].v_mm_s;
  // Each line sits at some eta (the corrected map puts the outer lines at -1
  // and +1; the printed map does not).  At each pressure node the quadratic in
  // eta through the nodal values must pass through the three measured values:
  // a 3 x 3 Lagrange system.
  Eigen::Matrix3d A;
  for (int r = 0; r < 3; ++r) {
    const double e = use_printed_eta ? s.eta_as_printed(lines[r].v_mm_s) : s.eta(lines[r].v_mm_s);
    const auto L = lagrange3(e);
    A.row(r) << L[0], L[1], L[2];
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(A);
  const double p_nodes[3] = {p_min, 0.5 * (p_min + p_max), p_max};
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d measured(lines[0].mu(p_nodes[i]), lines[1].mu(p_nodes[i]), lines[2].mu(p_nodes[i]));
    const Eigen::Vector3d nodal = lu.solve(measured);
    for (int j = 0; j < 3; ++j) s.mu[3 * i + j] = nodal(j);
  }
  s.validate();
  return s;
}

}  // namespace drawbend::analysis
