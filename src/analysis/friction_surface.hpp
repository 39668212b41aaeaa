#pragma once
// The nine-node quadratic friction surface mu(p, v), thesis Eqs. (6.1)-(6.3).
//
// Node numbering (Eq. 6.1): node k = 3 i + j + 1 with i, j in {0, 1, 2};
// i indexes the pressure coordinate xi = -1, 0, +1 and j the speed coordinate
// eta = -1, 0, +1.  So nodes 1, 2, 3 lie at p_min; 4, 5, 6 at the mid pressure;
// 7, 8, 9 at p_max; and nodes 1, 4, 7 at v_min; 3, 6, 9 at v_max.
//
// Natural coordinates (Eq. 6.3, corrected):
//   xi  = 2 (p - p_min)/(p_max - p_min) - 1,   eta = 2 (v - v_min)/(v_max - v_min) - 1.
// The thesis prints eta = 2 v/(v_max - v_min) - 1, which puts v_min at
// eta = -0.867 instead of -1 (it only works for p because p_min = 0).  Table 6.1
// is reproduced with the corrected map, not with the printed one.
//
// Units: p in MPa, v in mm/s.  Default domain: p 0-80 MPa, v 6.35-101.6 mm/s.
#include <array>
#include <cmath>
#include <vector>

#include "analysis/polynomial.hpp"

namespace drawbend::analysis {

/// The anisotropic ellipse of Sec. 6.4 (Fig. 6.5): the friction coefficient
/// at angle phi from RD between mu_RD = a and mu_TD = b (each from the surface),
///   mu(phi) = a b / sqrt(b^2 cos^2 phi + a^2 sin^2 phi),
/// from c = cos phi and s = sin phi.  When the denominator vanishes (a and b
/// both ~0) it returns a c^2 + b s^2 instead of 0/0.  Inline: the loop's fits
/// call it per row and iteration.
inline double ellipse_mu(double a, double b, double c, double s) {
  const double den = std::sqrt(b * b * c * c + a * a * s * s);
  if (den < 1e-12) return a * c * c + b * s * s;
  return a * b / den;
}

/// The nine shape functions of Eq. (6.1) at (xi, eta); they sum to one.
std::array<double, 9> nine_node_shape(double xi, double eta);

/// Eq. (6.1) exactly as printed (its N5 repeats N4's formula).  Kept so that
/// the report can show that the printed set is not a partition of unity.
std::array<double, 9> nine_node_shape_as_printed(double xi, double eta);

/// A friction-coefficient curve mu(p) measured at one sliding speed.
struct SpeedLine {
  double v_mm_s = 0.0;
  Polynomial mu;
};

struct FrictionSurface {
  double p_min = 0.0, p_max = 80.0;     ///< MPa
  double v_min = 6.35, v_max = 101.6;   ///< mm/s
  std::array<double, 9> mu{};           ///< nodal values mu_1..mu_9

  double xi(double p) const { return 2.0 * (p - p_min) / (p_max - p_min) - 1.0; }
  double eta(double v) const { return 2.0 * (v - v_min) / (v_max - v_min) - 1.0; }
  /// The thesis's printed speed map, eta = 2 v/(v_max - v_min) - 1.
  double eta_as_printed(double v) const { return 2.0 * v / (v_max - v_min) - 1.0; }

  /// Throws std::invalid_argument unless the node coordinates are ordered
  /// (p_min < p_max, 0 < v_min < v_max) and the nodal values are finite.
  void validate() const;

  /// Eq. (6.2) at (p, v); extrapolates outside the domain (callers decide
  /// whether to clamp; the solver's friction law does that).
  double operator()(double p, double v) const;
};

/// Build the nine nodal values from three speed lines (Section 6.2, Fig. 6.2):
/// at each pressure node the quadratic in eta through the nodal values passes
/// through the three lines' values.  With the corrected map the slowest and
/// fastest lines fall on eta = -1 and +1 and give nodes 1,4,7 and 3,6,9
/// directly, and the middle line fixes nodes 2,5,8.  Lines are ordered by speed;
/// the first and last define v_min and v_max.  `use_printed_eta` places all
/// three lines with the printed Eq. (6.3) instead.
FrictionSurface surface_from_lines(const std::vector<SpeedLine>& lines, double p_min, double p_max,
                                   bool use_printed_eta = false);

}  // namespace drawbend::analysis
