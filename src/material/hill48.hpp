#pragma once
// Hill's 1948 quadratic yield function for solids (3D, not plane stress), in
// the sheet's own axes 1 = RD, 2 = TD, 3 = ND:
//   sigma_bar^2 = F (s22 - s33)^2 + G (s33 - s11)^2 + H (s11 - s22)^2
//               + 2 L s23^2 + 2 M s31^2 + 2 N s12^2,
// normalised so that uniaxial tension along RD yields at the hardening curve's
// stress (G + H = 1).  Von Mises is F = G = H = 1/2, L = M = N = 3/2.
//
// Two ways to set it, both standard (e.g. Banabic, Sheet Metal Forming
// Processes, Springer 2010, Sec. 3.3):
//  - from r-values (Lankford coefficients) at 0, 45, 90 deg to RD:
//      G = 1/(1 + r0), H = r0/(1 + r0), F = r0/(r90 (1 + r0)),
//      N = (r0 + r90)(1 + 2 r45) / (2 r90 (1 + r0));
//  - from yield-stress ratios to RD, s45 = sigma45/sigma0, s90, and the
//    equibiaxial sb = sigma_b/sigma0: with S = 1 + 1/s90^2 + 1/sb^2,
//      F = S/2 - 1, G = S/2 - 1/s90^2, H = S/2 - 1/sb^2,
//      N = (4/s45^2 - F - G)/2.
// The out-of-plane shears L and M are not measured on sheet; both default to
// the isotropic 3/2.
//
// Uniaxial tension at angle t to RD in the sheet plane (c = cos t, s = sin t):
//   sigma_t = 1 / sqrt(F s^4 + G c^4 + H (c^2 - s^2)^2 + 2 N s^2 c^2),
//   r_t = (H + (2N - F - G - 4H) s^2 c^2) / (F s^2 + G c^2).
#include <string>

namespace drawbend::material {

struct Hill48 {
  double F = 0.5, G = 0.5, H = 0.5, L = 1.5, M = 1.5, N = 1.5;

  static Hill48 von_mises() { return {}; }
  /// From r0, r45, r90 (> 0).  Throws std::invalid_argument naming the bad value.
  static Hill48 from_r_values(double r0, double r45, double r90);
  /// From sigma45/sigma0, sigma90/sigma0 and sigma_b/sigma0 (> 0).  Throws
  /// std::invalid_argument when a ratio is not positive or the result is not
  /// a convex yield surface.
  static Hill48 from_stress_ratios(double s45, double s90, double sb);

  /// Throws std::invalid_argument unless the quadratic form is positive
  /// definite on deviatoric stresses (convex, closed yield surface).
  void validate() const;
  bool is_von_mises() const { return F == 0.5 && G == 0.5 && H == 0.5 && L == 1.5 && M == 1.5 && N == 1.5; }

  /// Yield stress ratio sigma_t/sigma_0 and r-value in uniaxial tension at
  /// angle t (radians) to RD in the sheet plane (the closed forms above).
  double uniaxial_ratio(double t) const;
  double r_value(double t) const;
  /// Equibiaxial yield stress ratio sigma_b/sigma_0 = 1/sqrt(F + G).
  double biaxial_ratio() const;

  std::string describe() const;
};

}  // namespace drawbend::material
