#pragma once
// Barlat's Yld2004-18p yield function for solids (Barlat et al. 2005, Int. J.
// Plasticity 21:1009-1039), in the sheet's own axes 1 = RD, 2 = TD, 3 = ND.
//
//   s = deviator of sigma,  S' = C' s,  S'' = C'' s   (two linear transformations)
//   Phi = sum_{i,j = 1..3} |S'_i - S''_j|^a = 4 sigma_bar^a,
//
// S'_i, S''_j the principal values of the symmetric tensors S', S''.  In
// Barlat's form, with c = (c12, c13, c21, c23, c31, c32, c44, c55, c66):
//   S'_11 = -(c12 s22 + c13 s33),  S'_22 = -(c21 s11 + c23 s33),
//   S'_33 = -(c31 s11 + c32 s22),  S'_23 = c44 s23,  S'_31 = c55 s31,  S'_12 = c66 s12,
// and the same with C''.  All coefficients 1 make C' act as the identity on
// deviators; with a = 2 the function is then von Mises, and for any a the
// uniaxial yield stress equals sigma_bar.  With C' = C'' and a = 2 it is a
// Hill'48 quadratic: sigma_bar^2 = (3/2) |dev S'|^2.  a = 8 for FCC metals (Barlat
// et al. 2005); any a >= 2 is accepted.
//
// Principal values: material/principal_values.hpp (no trigonometry: the
// isolated root of the scaled characteristic cubic by two Newton steps, the
// other two from the tensor itself, exact to round-off also where two
// coincide); a triple root returns the mean.
// Gradient d sigma_bar / d sigma without eigenvectors: for a symmetric X with
// eigenvalues x1 >= x2 >= x3 and a scalar g applied to them, sum_i g(x_i) P_i
// (P_i the eigenprojectors) equals the interpolating polynomial
//   g[x1] I + g[x1, x2] (X - x1 I) + g[x1, x2, x3] (X - x1 I)(X - x2 I)
// in divided differences, which stays finite when eigenvalues coincide: a
// divided difference over values closer than 1e-5 of their scale is replaced by
// the derivative at the midpoint (error O(1e-10) relative; the eigenprojectors
// of a double root are not unique, this sum is).
//
// Normalisation: the hardening curve is that of uniaxial tension along RD, so
// a parameter set is used scaled (C' and C'' by one factor k, Phi by k^a) so
// that sigma_bar of unit RD tension is 1: normalised() does it, and every
// ratio below is to sigma_0 (RD) whatever the scaling.
//
// Set-up check (validate): a finite, a >= 2, finite coefficients, and the
// yield surface closed and convex, sampled: 72 directions in each of 13 planes
// of the deviator space (the pi-plane of the normal stresses, the three shears
// with each normal deviator direction and with each other, and the sheet plane
// (s11, s22, s12)), Phi > 0 on every direction (closed) and the locus turning
// one way (convex; the turn of each three consecutive points at least -1e-9 of
// the squared spacing).  Barlat et al. 2005 prove the function convex for
// a >= 1, so the turn test guards the implementation; a set whose surface is
// not closed (Phi = 0 on some deviator) is refused.
#include <array>
#include <string>

namespace drawbend::material {

/// Closed-form eigenvalues of the symmetric 3x3 matrix of a Voigt tensor (xx,
/// yy, zz, xy, yz, zx; tensor shears), in descending order.
void sym_eigenvalues(const double v[6], double lam[3]);

struct Yld2004 {
  double a = 8.0;
  /// c12, c13, c21, c23, c31, c32, c44 (yz), c55 (zx), c66 (xy): C' (c1) and C'' (c2).
  std::array<double, 9> c1{1, 1, 1, 1, 1, 1, 1, 1, 1}, c2{1, 1, 1, 1, 1, 1, 1, 1, 1};

  static Yld2004 isotropic(double a);
  /// The same set scaled so that sigma_bar of unit RD tension is 1.
  Yld2004 normalised() const;
  /// Throws std::invalid_argument with the reason (see the header).
  void validate() const;

  /// sigma_bar of a stress in the sheet axes (Voigt, tensor shears) [its units].
  double equivalent(const double s[6]) const;
  /// sigma_bar and n = d sigma_bar / d sigma (tensor components: d sigma_bar = sum_i n_ii d s_ii +
  /// 2 sum_{i<j} n_ij d s_ij); n is deviatoric and homogeneous of degree 0.  Zero stress: 0, n = 0.
  double gradient(const double s[6], double n[6]) const;

  /// Uniaxial yield stress at angle t (rad) to RD over sigma_0; r-value at t (from the gradient).
  double uniaxial_ratio(double t) const;
  double r_value(double t) const;
  /// Equibiaxial yield stress over sigma_0; biaxial strain ratio rb = d eps_22 / d eps_11 there.
  double biaxial_ratio() const;
  double biaxial_r() const;
  /// Plane-strain tension along t (zero strain rate across it in the sheet plane, sigma_33 = 0): the major
  /// stress over sigma_0.
  double plane_strain_ratio(double t) const;

  std::string describe() const;
};

}  // namespace drawbend::material
