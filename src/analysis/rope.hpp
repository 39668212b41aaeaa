#pragma once
// The conventional (rope-formula) analysis of the draw-bend test, thesis Chapter 2.
// Units: forces N, lengths mm, stresses and pressures MPa (= N/mm^2), angles rad.
//
// Full strip or half model?  The thesis measures forces on the whole 25.4 mm
// strip (Chapter 5) but simulates the top half by symmetry (Chapters 2-4), so
// its simulated forces are half-model forces.  Eq. (2.2) gives the same
// pressure either way provided force and width describe the same extent; the
// functions below take the force basis explicitly so that the width used is
// never ambiguous.
#include <cmath>

namespace drawbend::analysis {

enum class ForceBasis { full_strip, half_model };

/// Width that matches the force basis: full width, or half of it.
double basis_width(double full_width_mm, ForceBasis basis);

/// Eq. (2.1), Swift (1948): bending force
///   F_B = sigma_y t^2 w / (2 r) * tan(Theta/2)
/// w is the width that matches the force basis.
double swift_bending_force(double sigma_y_MPa, double t_mm, double full_width_mm, double r_mm,
                           double theta_rad, ForceBasis basis);

/// Eq. (2.2): average contact pressure P = (F_x + F_y) / (2 r w).
double average_pressure(double Fx_N, double Fy_N, double r_mm, double full_width_mm, ForceBasis basis);

/// Eq. (2.3): mu = (1/Theta) ln((F_y - F_B) / F_x).
/// Throws std::domain_error when the argument of ln is not positive.
double mu_rope(double Fx_N, double Fy_N, double FB_N, double theta_rad);

/// Eq. (5.1) generalised to any wrap: mu = (1/Theta) ln((F_fric + F_back) / F_back),
/// where F_fric = F_y - F_x - F_B is the pure friction force.  Theta = pi/2 gives Eq. (5.1).
double mu_from_friction(double Ffric_N, double Fback_N, double theta_rad);

/// Eq. (5.1) solved for the friction force (the inverse of mu_from_friction,
/// the capstan law of Eq. 2.3 without bending): F_fric = F_back (exp(mu Theta) - 1).
/// Computed as exp(...) - 1, not expm1, so that the loop's fits keep their bits.
/// Inline: the loop's Levenberg-Marquardt fits call it per row and iteration.
/// Split in two for callers that keep exp(mu Theta) (the loop's predict_row
/// memoises it): wrap_factor = exp(mu Theta), friction_from_wrap = F_back (e - 1).
inline double wrap_factor(double mu, double theta_rad) { return std::exp(mu * theta_rad); }
inline double friction_from_wrap(double wrap, double Fback_N) { return Fback_N * (wrap - 1); }
inline double friction_from_mu(double mu, double Fback_N, double theta_rad) {
  return friction_from_wrap(wrap_factor(mu, theta_rad), Fback_N);
}

}  // namespace drawbend::analysis
