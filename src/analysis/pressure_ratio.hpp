#pragma once
// The average-pressure ratio c between a fixed-pin test and a rotating-pin
// test (thesis Eq. 4.2, Tables 4.2, 5.15, 5.18).  By Eq. (2.2) the average
// pressure is proportional to F_x + F_y at the same pin radius and width, so
//   c = (F_x + F_y)_fixed / (F_x' + F_y')_rotating.
// Forces in N, any consistent basis (full strip or half model).
namespace drawbend::analysis {

/// c from the four tension forces (Table 4.2 definition).
double pressure_ratio(double Fx_fixed, double Fy_fixed, double Fx_rot, double Fy_rot);

/// c from force-fit quantities at one back tension, taking the rotating-pin
/// outlet force as F_back + F_bend:
///   c = (2 F_back + F_bend + F_fric) / (2 F_back + F_bend).
double pressure_ratio_from_fits(double Fback, double Ffric, double Fbend);

/// The rotating-pin bending force that makes pressure_ratio_from_fits return c:
///   F_bend' = (2 F_back + F_bend + F_fric)/c - 2 F_back, with F_bend the
/// fixed-pin-side bending used in the numerator.  Used to ask which rotating-pin
/// force a printed c implies.
double implied_rotating_bending(double Fback, double Ffric, double Fbend_numerator, double c);

/// Eq. (2.2) at one pin and width: the average pressure follows the mean strip
/// tension (F_x + F_y)/2.  A pressure p_ref [MPa] known at back tension F_ref
/// with bending force FB_ref (and no friction) becomes, at back tension F with
/// bending force FB and friction force Ff (F_y = F + FB + Ff),
///   p = p_ref (2 F + FB + Ff) / (2 F_ref + FB_ref).
/// Evaluated in exactly that order (the loop's fits depend on its bits).
/// Inline: the loop's fits call it per row and iteration.
inline double pressure_at_tension(double p_ref_MPa, double F, double FB, double Ff, double F_ref, double FB_ref) {
  return p_ref_MPa * (2 * F + FB + Ff) / (2 * F_ref + FB_ref);
}

}  // namespace drawbend::analysis
