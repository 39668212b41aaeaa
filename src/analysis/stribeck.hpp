#pragma once
// The Stribeck friction curve, thesis Eqs. (3.1) and (3.2) (Ter Haar 1996).
//
// Units.  Inputs in the study's units (v in mm/s, p in MPa, R_a in um, eta in
// Pa s) are converted to SI inside lubricant_number so that
//   L = v eta / (p R_a)
// is dimensionless: (m/s)(Pa s) / (Pa m) = 1.  eta must therefore be the
// dynamic viscosity; the thesis calls it "kinematic" but gives Pa s, the unit
// of dynamic viscosity, and only the dynamic one makes L dimensionless.
//
// Log base.  Eq. (3.2) prints log10 in the numerator and an unsubscripted log
// in the denominator.  We read both as the same base: the argument of tanh is
// then a ratio of logarithms, which is independent of the base, the curve
// passes its midpoint (mu_BL + mu_EHL)/2 at L = sqrt(L_BL L_EHL), and it takes
// the value 0.5[(mu_BL+mu_EHL) + tanh(1)(mu_BL-mu_EHL)] at L = L_BL and the
// mirror value at L = L_EHL, whatever the base.  Mixing log10 with ln would
// stretch the transition by ln(10) = 2.303, so that L_BL and L_EHL would no
// longer mark the regime transitions their names promise.
// Limits: mu -> mu_BL as L -> 0 and mu -> mu_EHL as L -> infinity (L_BL < L_EHL).
#include <string>

namespace drawbend::analysis {

struct StribeckParams {
  double mu_BL = 0.0;   ///< boundary-lubrication friction coefficient [-]
  double mu_EHL = 0.0;  ///< (elasto)hydrodynamic friction coefficient [-]
  double L_BL = 0.0;    ///< lubricant number at the boundary transition [-]
  double L_EHL = 0.0;   ///< lubricant number at the hydrodynamic transition [-]
  double Ra_um = 0.0;   ///< sheet roughness R_a [um]
  double eta_Pa_s = 0.0;  ///< dynamic viscosity [Pa s]

  /// Throws std::invalid_argument with a clear message when not physical
  /// (mu < 0, L <= 0, L_BL >= L_EHL, R_a or eta <= 0).
  void validate(const std::string& where = "Stribeck parameters") const;
};

/// Eq. (3.1): L = v eta / (p R_a), with v [mm/s], p [MPa]; dimensionless.
double lubricant_number(double v_mm_s, double p_MPa, const StribeckParams& s);

/// Eq. (3.2): mu(L).  L must be positive.
double stribeck_mu(double L, const StribeckParams& s);

/// mu at a contact state: Eq. (3.2) at L from Eq. (3.1).
double stribeck_mu(double v_mm_s, double p_MPa, const StribeckParams& s);

/// The six parameters from a CSV file with columns parameter,value (names
/// mu_BL, mu_EHL, L_BL, L_EHL, Ra, eta), validated; throws InputError (file:line).
StribeckParams load_stribeck(const std::string& path);

}  // namespace drawbend::analysis
