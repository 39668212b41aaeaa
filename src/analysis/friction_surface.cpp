#include "analysis/friction_surface.hpp"

#include <cmath>
#include <stdexcept>

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
  const double e_mid = use_printed_eta ? s.eta_as_printed(lines[1].v_mm_s) : s.eta(lines[1].v_mm_s);
  const auto L = lagrange3(e_mid);
  const double p_nodes[3] = {p_min, 0.5 * (p_min + p_max), p_max};
  for (int i = 0; i < 3; ++i) {
    const double lo = lines[0].mu(p_nodes[i]), hi = lines[2].mu(p_nodes[i]);
    const double mid_measured = lines[1].mu(p_nodes[i]);
    s.mu[3 * i + 0] = lo;
    s.mu[3 * i + 2] = hi;
    // Solve L0*lo + L1*x + L2*hi = mid_measured for the mid-speed node x.
    s.mu[3 * i + 1] = (mid_measured - L[0] * lo - L[2] * hi) / L[1];
  }
  return s;
}

}  // namespace drawbend::analysis
