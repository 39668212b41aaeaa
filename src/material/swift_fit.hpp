#pragma once
// Swift hardening law  sigma = K (eps0 + eps_p)^n  fitted to a tensile test's
// yield stress, ultimate tensile strength and n-value (thesis Table 5-1), and
// its tabulation into the piecewise-linear curve the solver reads.
//
// Fit conditions (n fixed to the test's n-value):
//  1. yield:     K (eps0 + eps_y)^n = YS, with eps_y the plastic strain at
//                which YS is taken.  Table 5-1's YS is the 0.2 % offset proof
//                stress, i.e. the flow stress at eps_p = 0.002, and the
//                shipped tables take it there (table_5_1_yield_plastic_strain;
//                until issue 51 they took it at eps_p = 0, as the curve's
//                initial flow stress, which read 106.2 MPa at eps_p = 0.002).
//  2. necking:   Considere's condition d sigma / d eps_p = sigma (rigid-plastic,
//                elastic strain neglected) holds at eps0 + eps_p = n, i.e. at
//                the true (logarithmic) strain eps_u = n - eps0 of the specimen;
//                there the engineering stress is the UTS:
//                    UTS = sigma(eps_u) * exp(-eps_u) = K n^n exp(eps0 - n).
// Dividing the two gives one equation for eps0,
//    g(eps0) = n ln(n / (eps0 + eps_y)) + eps0 - n - ln(UTS / YS) = 0,
// with g' = 1 - n/(eps0 + eps_y) < 0 on (0, n - eps_y): a unique root, found by
// bisection to round-off.  Then K = YS / (eps0 + eps_y)^n.
#include <vector>

#include "material/hardening_curve.hpp"

namespace drawbend::material {

struct SwiftLaw {
  double K = 0.0;     ///< MPa
  double eps0 = 0.0;  ///< pre-strain offset
  double n = 0.0;     ///< hardening exponent
  /// True flow stress at plastic strain ep, MPa.
  double stress(double ep) const;
  /// True plastic strain at the Considere point, n - eps0.
  double necking_strain() const { return n - eps0; }
  /// Engineering stress at the Considere point, sigma(n - eps0) exp(-(n - eps0)).
  double engineering_uts() const;
};

/// The plastic strain at which a 0.2 % offset proof stress is a flow stress:
/// the eps_y of the shipped tables (data/materials/aa5754_o_{rd,td}.csv).
inline constexpr double table_5_1_yield_plastic_strain = 0.002;

/// Fit K and eps0 (see above).  Throws std::invalid_argument unless
/// 0 < YS < UTS, 0 < n < 1, 0 <= eps_y and a root exists.
SwiftLaw fit_swift(double yield_stress, double uts_engineering, double n, double yield_plastic_strain = 0.0);

/// Plastic-strain grid of the shipped tables: 63 points from 0 to 1.0, spaced
/// roughly in proportion to (eps0 + eps_p) so that linear interpolation of
/// the Swift law is within 0.04 % everywhere (finest, 0.0005, at yield).
/// Issue 51 added 0.0325 and 0.075: the fit with the YS at eps_p = 0.002 has
/// a smaller eps0, and on the 61 points of before it reached 0.0435 %.
std::vector<double> swift_table_strains();

/// Number of decimals of the stress column in the shipped tables.
inline constexpr int swift_table_stress_decimals = 4;

/// The curve a table holds: Swift stresses at `strains`, rounded to
/// swift_table_stress_decimals as printed.
HardeningCurve tabulate(const SwiftLaw& law, const std::vector<double>& strains);

}  // namespace drawbend::material
