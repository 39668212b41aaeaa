#pragma once
// The bending force of a rotating-pin draw-bend test from beam theory: an
// independent, semi-analytic model of what the finite-element runs compute,
// used to trace the bending-force residual (Chapter 8) without re-running the
// solver for every constitutive assumption.
//
// A strip of thickness t and width w is drawn under a constant tension T over
// a pin of diameter D: each section is bent from straight to the mid-surface
// curvature kappa = 1 / (D/2 + t/2) and unbent again to straight.  In steady
// state the force difference across a rotating (frictionless) pin equals the
// bending work per unit length of strip,
//     F_B = oint M dkappa   [N = N mm / mm],
// to first order in the stretch (the work T d(eps_m) of the membrane strain is
// carried by the tensions themselves).  The section is Euler-Bernoulli
// (plane sections, the strain eps_m + z kappa), cut into equal layers through
// the thickness, each in a uniaxial state along the strip scaled by a
// constraint factor c: the layer's stress is sigma = c s with s the
// equivalent stress, so c = 2/sqrt(3) is plane strain across the width for a
// von Mises material, c = 1 plane stress (a free beam), and Hosford's
// non-quadratic surface gives its own plane-strain factor
// (hosford_plane_strain_factor).  The layer's modulus is the plane-strain
// modulus E / (1 - nu^2) when c > 1, E otherwise.
//
// Hardening: the monotonic flow curve sigma_f(p) is kept, and an
// Armstrong-Frederick back stress X (dX = C dp sgn - gamma X dp, saturating
// at X_sat = C / gamma) is carved out of it, R(p) = sigma_f(p) - X_sat
// (1 - exp(-gamma p)).  X_sat = 0 is isotropic hardening; the yield condition
// is |s - X| <= R(p).  Each layer is integrated exactly for the back stress
// (closed form at fixed sign) and by Newton for p, the membrane strain by
// bisection so that the section carries T.
//
// Units: mm, N, MPa.  Closed forms (tests/unit/test_bending_work.cpp): rigid,
// perfectly plastic, no tension: F_B = 2 M_p kappa = c sigma_0 w t^2 / (2 rho);
// elastic: F_B = 0.
#include <functional>

namespace drawbend::analysis {

struct BendMaterial {
  double E_MPa = 70000;
  double nu = 0.33;
  std::function<double(double)> flow;   ///< monotonic flow stress [MPa] at equivalent plastic strain p
  std::function<double(double)> dflow;  ///< its slope d sigma_f / dp [MPa]
  double x_sat_MPa = 0;  ///< saturated Armstrong-Frederick back stress (0: isotropic hardening)
  double gamma = 0;      ///< its rate [-] (X reaches 95 % of X_sat at p = 3 / gamma)
  double constraint = 1.1547005383792515;  ///< c = sigma_x / s at yield: 2/sqrt(3) plane strain (von Mises), 1 plane stress
};

struct BendCase {
  double pin_diameter_mm = 12.7;
  double thickness_mm = 1.05;
  double width_mm = 25.4;  ///< the width the force refers to (full strip)
  double tension_N = 0;    ///< constant tension during bending and unbending
  int layers = 200;
  int steps = 200;  ///< curvature increments in each of bending and unbending
  /// false: the small-strain beam, thickness fixed (as before issue 51's
  /// trace of the FE's shortfall).  true: the section thins as the strip
  /// stretches, t = t0 exp(-eps_m) (incompressible plastic flow, width held:
  /// the plane-strain state; the layers' heights and areas follow, and the
  /// bend's curvature is 1 / (D/2 + t/2) at the thickness the section has
  /// when it reaches the pin).  The finite-element strip thins; on the 12.7 mm
  /// pin at 1500 N this takes 4.9 % off F_B (docs/issue51-large-pin.md).
  bool thinning = false;
};

struct BendResult {
  double bending_force_N = 0;  ///< oint M dkappa
  double max_plastic_strain = 0;
  double membrane_strain = 0;  ///< mid-surface strain after the cycle (stretch of the strip)
};

/// Bend to 1 / (D/2 + t/2) and unbend under constant tension; throws
/// std::invalid_argument on a non-positive geometry, a missing flow curve, a
/// back stress that leaves no elastic range at p = 0 or a tension the section
/// cannot carry.
BendResult bend_unbend(const BendCase& bc, const BendMaterial& m);

/// Plane-strain factor of Hosford's isotropic yield surface with exponent a
/// (|s1 - s2|^a + |s2 - s3|^a + |s3 - s1|^a = 2 s^a): sigma_1 / s at yield with
/// eps_2 = 0 and sigma_3 = 0.  a = 2 (von Mises): 2/sqrt(3); a = 1 and
/// a -> infinity (Tresca): 1.  Throws std::invalid_argument for a < 1.
double hosford_plane_strain_factor(double a);

}  // namespace drawbend::analysis
