#pragma once
// The thesis's mu(p, v) friction law in the solver (Secs. 6.2-6.4, Eqs. 6.1-6.3).
//
// Two nine-node quadratic surfaces, one along the rolling direction and one
// along the transverse direction (Table 6.1), give the semi-axes of the
// elliptical stick/slip limit (Eq. 6.3b, Fig. 6.5):
//   mu_1 = mu_RD(p, v),  mu_2 = mu_TD(p, v).
// The contact code does the radial return onto that ellipse (contact.cpp).
//
// Evaluation.  Eq. (6.2) is a biquadratic polynomial in the natural
// coordinates (xi, eta) of Eq. (6.3, corrected map).  The nine products of
// one-dimensional Lagrange functions are expanded once, at construction, into
// monomial coefficients C_ab (mu = sum C_ab xi^a eta^b), so one evaluation of
// both directions costs two affine maps and 2 x 8 multiply-adds (Horner), and
// equals analysis::FrictionSurface to rounding (tested).
//
// Outside the domain (p_min..p_max, v_min..v_max; Sec. 6.3: 0-80 MPa,
// 6.35-101.6 mm/s) the law CLAMPS the input to the domain edge: the quadratic
// surface is a fit inside the measured range and is not trusted outside it
// (extrapolated to v = 0, the RD surface at 80 MPa reaches 0.28 and at 0 MPa
// goes towards 0; extrapolation of a quadratic can even turn negative).
// In particular a sticking node (v < v_min) gets the friction of the slowest
// measured line.  Each clamped evaluation is counted per node (pressure out of
// range, speed below, speed above) so that a run can report how often it left
// the domain (counters(), printed once at the end of `drawbend run` and
// written to summary.csv).  The result is also floored at 0 (a negative
// coefficient has no meaning; never reached with Table 6.1, tested).
//
// Speed input (Sec. 3.3.2).  mu falls with speed at high pressure (RD at
// 80 MPa: 0.21 at 6.35 mm/s, 0.047 at 101.6 mm/s), the speed-weakening that
// made the per-cycle Stribeck update unstable (Figs. 3.5-3.7).  As there, the
// speed input is the node's sliding speed averaged over `interval` cycles;
// until the first interval completes, the running mean of the partial
// interval.  The pressure is the current one (the law is re-evaluated every
// cycle, only the speed is lagged).  interval = 1: the instantaneous speed.
//
// Per-node state (7 doubles): speed sum, count, last interval mean + 1 (0:
// none yet), evaluations, clamped pressure, clamped low speed, clamped high speed.
// Units: MPa, mm/s.
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "analysis/friction_surface.hpp"
#include "friction/friction_law.hpp"

namespace drawbend::friction {

class SurfaceLaw final : public FrictionLaw {
 public:
  /// rd, td: the two surfaces, on the same domain (p_min < p_max, v_min < v_max);
  /// interval >= 1 cycles.  Throws std::invalid_argument naming what is wrong.
  SurfaceLaw(const analysis::FrictionSurface& rd, const analysis::FrictionSurface& td, int interval);

  Limit limit(const ContactState& s) const override;
  int state_size() const override { return 7; }
  std::string describe() const override;
  std::vector<std::pair<std::string, double>> counters(const std::vector<double>& state) const override;

  /// (mu_RD, mu_TD) at (p, v) after clamping to the domain; no state.
  Limit at(double p, double v) const;
  const analysis::FrictionSurface& rd() const { return rd_; }
  const analysis::FrictionSurface& td() const { return td_; }
  int interval() const { return interval_; }

 private:
  analysis::FrictionSurface rd_, td_;
  std::array<double, 9> c_rd_{}, c_td_{};  // C[3a + b]: coefficient of xi^a eta^b
  double sx_ = 0, ox_ = 0, se_ = 0, oe_ = 0;  // xi = sx p + ox, eta = se v + oe
  int interval_;
};

/// The input domain of Sec. 6.3 (defaults) [MPa, mm/s].
struct SurfaceDomain {
  double p_min = 0.0, p_max = 80.0, v_min = 6.35, v_max = 101.6;
};

/// RD and TD surfaces from nodal values in the format of Table 6.1 (columns
/// node, mu_RD, mu_TD; nine rows numbered 1 to 9 in order, node k = 3i + j + 1
/// as in analysis/friction_surface.hpp).  Throws InputError naming the file,
/// line and column of a bad cell (node numbering out of order, mu < 0, ...).
std::pair<analysis::FrictionSurface, analysis::FrictionSurface> load_surface_nodes(const std::string& csv,
                                                                                   const SurfaceDomain& d);

/// RD and TD surfaces from chapter-5 speed lines mu = a0 + a1 p in the format of
/// Table 5.16 (columns direction, speed_mm_s, a0, a1_per_MPa; three lines per
/// direction in increasing speed), built as in Sec. 6.2 (surface_from_lines).
/// v_min and v_max are the outer lines' speeds.  Throws InputError naming the
/// file, line and column of a bad cell.
std::pair<analysis::FrictionSurface, analysis::FrictionSurface> load_surface_lines(const std::string& csv,
                                                                                   double p_min, double p_max);

}  // namespace drawbend::friction

namespace drawbend::friction {

/// Steady sliding at angle phi [rad] from e1 under the radial return of
/// contact.cpp: the friction force is antiparallel to the slip and lies on the
/// ellipse, so |F_t|/F_n = mu1 mu2 / sqrt(mu2^2 cos^2 phi + mu1^2 sin^2 phi).
inline double ellipse_mu(const Limit& l, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  return l.mu1 * l.mu2 / std::sqrt(l.mu2 * l.mu2 * c * c + l.mu1 * l.mu1 * s * s);
}

}  // namespace drawbend::friction
