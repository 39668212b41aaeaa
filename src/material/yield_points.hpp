#pragma once
// The material-test points of an orthotropic yield function, from the
// function itself (its value and gradient), for any model F with
//   double F::equivalent(const double s[6]) const;
//   double F::gradient(const double s[6], double n[6]) const;   // n = d sigma_bar / d sigma
// in the sheet axes (Voigt xx, yy, zz, xy, yz, zx; tensor shears).  Ratios are
// to the yield stress of uniaxial tension along RD (sigma_0).
//  - uniaxial tension at t to RD: sigma_t / sigma_0, and r_t = d eps_ww / d eps_33
//    (w across t in the sheet plane) from the normal;
//  - equibiaxial tension: sigma_b / sigma_0 and rb = d eps_22 / d eps_11;
//  - plane strain along t (d eps_ww = 0, sigma_33 = 0, no shear in the (t, w)
//    axes): the stress ratio beta = sigma_ww / sigma_tt by bisection on
//    [0, 1] (extended to 256 when d eps_ww is still negative at 1) to 1e-14,
//    then sigma_tt / sigma_0.  NaN when uniaxial tension along t does not
//    contract across it (d eps_ww >= 0 at beta = 0).
//  - the flange of a drawn cup at polar angle t to RD: radial tension and hoop
//    compression of equal size (sigma_r = -sigma_h, the pure shear of the
//    flange's inner part), and the strain ratio -d eps_r / d eps_h of the
//    normal (1 for an isotropic sheet: no thickness change; below 1 the
//    flange thickens there, above 1 it thins).
#include <cmath>

namespace drawbend::material::points {

inline void tension(double t, double s[6]) {
  const double c = std::cos(t), n = std::sin(t);
  s[0] = c * c, s[1] = n * n, s[2] = 0, s[3] = c * n, s[4] = 0, s[5] = 0;
}
/// d eps_ww of a normal n, w at t + 90 deg in the sheet plane.
inline double across(const double n[6], double t) {
  const double c = std::cos(t), q = std::sin(t);
  return n[0] * q * q + n[1] * c * c - 2.0 * n[3] * c * q;
}

template <class F>
double uniaxial_ratio(const F& f, double t) {
  double s0[6], s[6];
  tension(0.0, s0);
  tension(t, s);
  return f.equivalent(s0) / f.equivalent(s);
}
template <class F>
double r_value(const F& f, double t) {
  double s[6], n[6];
  tension(t, s);
  f.gradient(s, n);
  return across(n, t) / n[2];
}
template <class F>
double biaxial_ratio(const F& f) {
  double s0[6];
  tension(0.0, s0);
  const double b[6] = {1, 1, 0, 0, 0, 0};
  return f.equivalent(s0) / f.equivalent(b);
}
template <class F>
double biaxial_r(const F& f) {
  const double b[6] = {1, 1, 0, 0, 0, 0};
  double n[6];
  f.gradient(b, n);
  return n[1] / n[0];
}
template <class F>
double plane_strain_ratio(const F& f, double t) {
  const double c = std::cos(t), q = std::sin(t);
  const auto stress = [&](double beta, double s[6]) {
    s[0] = c * c + beta * q * q, s[1] = q * q + beta * c * c, s[2] = 0, s[3] = c * q * (1 - beta), s[4] = 0, s[5] = 0;
  };
  const auto eww = [&](double beta) {
    double s[6], n[6];
    stress(beta, s);
    f.gradient(s, n);
    return across(n, t);
  };
  double lo = 0.0, hi = 1.0;
  if (!(eww(lo) < 0.0)) return std::nan("");
  for (int k = 0; k < 8 && eww(hi) < 0.0; ++k) lo = hi, hi *= 2.0;
  for (int k = 0; k < 200 && hi - lo > 1e-14; ++k) {
    const double mid = 0.5 * (lo + hi);
    (eww(mid) < 0.0 ? lo : hi) = mid;
  }
  double s0[6], s[6];
  tension(0.0, s0);
  stress(0.5 * (lo + hi), s);
  return f.equivalent(s0) / f.equivalent(s);
}

template <class F>
double flange_shear_ratio(const F& f, double t) {
  const double c = std::cos(t), q = std::sin(t);
  // sigma = e_r e_r - e_h e_h with e_r = (c, q), e_h = (-q, c)
  const double s[6] = {c * c - q * q, q * q - c * c, 0, 2.0 * c * q, 0, 0};
  double n[6];
  f.gradient(s, n);
  const double er = n[0] * c * c + n[1] * q * q + 2.0 * n[3] * c * q;
  return -er / across(n, t);
}

}  // namespace drawbend::material::points
