#pragma once
// The new (pressure-map) method to identify mu(p) from draw-bend tests,
// thesis Eqs. (4.1)-(4.5) and (5.3).
//
// For pin j the friction force predicted by a polynomial mu(p) = sum_k a_k p^k is
// Eq. (4.2):
//   F_T,j = sum_i mu(c_j P'_ij) c_j P'_ij A_ij = sum_k a_k c_j^(k+1) S_j,k+1,
//   S_j,n = sum_i P'_ij^n A_ij,
// with P'_ij the nodal pressures of the frictionless (rotating-pin) map, A_ij
// the nodal areas and c_j the fixed/rotating average-pressure ratio.  The model
// is linear in a, so minimising Eq. (4.3) is linear least squares with the
// matrix M_jk = c_j^(k+1) S_j,k+1 of Eqs. (4.5)/(5.3).  With as many pins as
// coefficients M is square and solved exactly; with more pins it is solved in
// the least-squares sense (column-pivoted QR); fewer pins is an error.
//
// Units: P' in MPa, A in mm^2, forces in N.  The map must describe the same
// strip extent as the forces: a half-model map used with full-strip measured
// forces needs its areas doubled (PressureMap::scaled_areas(2)).
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "analysis/polynomial.hpp"

namespace drawbend::analysis {

struct PressureMap {
  std::string label;          ///< e.g. "12.7 mm pin, frictionless"
  std::vector<double> p_MPa;  ///< nodal contact pressure P'_i
  std::vector<double> area_mm2;  ///< nodal tributary area A_i

  /// S_n = sum_i P_i^n A_i [N when n = 1].
  double moment(int n) const;
  double normal_force() const { return moment(1); }
  PressureMap scaled_areas(double factor) const;
  void validate() const;  ///< equal lengths, finite, P >= 0, A >= 0
};

struct PinTest {
  PressureMap map;              ///< frictionless (rotating-pin) map
  double c = 1.0;               ///< average-pressure ratio fixed/rotating
  double friction_force_N = 0;  ///< measured pure friction force F_T
};

struct NewMethodResult {
  Polynomial mu;
  Eigen::MatrixXd M;      ///< Eq. (4.5) matrix, one row per pin
  Eigen::VectorXd rhs;    ///< measured friction forces
  bool least_squares = false;
  double residual_N = 0;  ///< || M a - F || (zero for an exact solve)
  double condition = 0;   ///< 2-norm condition number of M after scaling its columns to unit norm
};

/// Eq. (4.2): friction force of one pin for a given mu(p); validates the map.
double predicted_friction_force(const PressureMap& map, double c, const Polynomial& mu);

/// Identify mu(p) of the given polynomial order (0 = constant, 1 = linear, ...).
NewMethodResult solve_new_method(const std::vector<PinTest>& pins, int order);

}  // namespace drawbend::analysis
