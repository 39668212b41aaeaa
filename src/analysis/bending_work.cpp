#include "analysis/bending_work.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace drawbend::analysis {

namespace {

struct Layers {
  std::vector<double> sig, x, p;  // stress along the strip [MPa], back stress (equivalent) [MPa], eq. plastic strain
};

class Section {
 public:
  Section(const BendCase& bc, const BendMaterial& m) : m_(m), n_(bc.layers) {
    const double c = m.constraint;
    modulus_ = c > 1 ? m.E_MPa / (1 - m.nu * m.nu) : m.E_MPa;
    ec_ = modulus_ / (c * c);  // d s / d(c eps) for the equivalent quantities
    width_ = bc.width_mm;
    set_thickness(bc.thickness_mm);
  }
  /// The layers' heights and areas for the section's current thickness.
  void set_thickness(double t) {
    t_ = t;
    z_.resize(n_);
    for (int i = 0; i < n_; ++i) z_[i] = ((i + 0.5) / n_ - 0.5) * t;
    dA_ = width_ * t / n_;
  }
  double thickness() const { return t_; }  ///< the section's current thickness [mm]
  // Without a back stress (x_sat 0) the same numbers without the exponentials.
  double R(double p) const {
    return m_.x_sat_MPa == 0 ? m_.flow(p) : m_.flow(p) - m_.x_sat_MPa * (1 - std::exp(-m_.gamma * p));
  }
  double dR(double p) const {
    return m_.x_sat_MPa == 0 ? m_.dflow(p) : m_.dflow(p) - m_.x_sat_MPa * m_.gamma * std::exp(-m_.gamma * p);
  }

  /// Layers after the strain increment d_eps = dm + z dk from state `a`.
  void update(const Layers& a, double dm, double dk, Layers& out) const {
    const double c = m_.constraint;
    out = a;
    for (int i = 0; i < n_; ++i) {
      const double s_tr = (a.sig[i] + modulus_ * (dm + z_[i] * dk)) / c;
      const double xi = s_tr - a.x[i];
      if (std::abs(xi) - R(a.p[i]) <= 0) {
        out.sig[i] = s_tr * c;
        continue;
      }
      const double sg = xi > 0 ? 1.0 : -1.0, X0 = a.x[i], p0 = a.p[i];
      const double lim = sg * m_.x_sat_MPa;  // the back stress's limit at this sign
      double dp = 0;
      for (int it = 0; it < 60; ++it) {
        const double ex = X0 == lim ? 1.0 : std::exp(-m_.gamma * dp);  // X0 == lim: X stays lim
        const double X = lim + (X0 - lim) * ex, dX = -(X0 - lim) * m_.gamma * ex;
        const double g = sg * (s_tr - sg * ec_ * dp - X) - R(p0 + dp);
        const double dg = -ec_ - sg * dX - dR(p0 + dp);
        const double step = g / dg;
        dp -= step;
        if (std::abs(step) <= 1e-14 * (1 + dp)) break;
      }
      const double ex = X0 == lim ? 1.0 : std::exp(-m_.gamma * dp);
      out.x[i] = lim + (X0 - lim) * ex;
      out.p[i] = p0 + dp;
      out.sig[i] = (s_tr - sg * ec_ * dp) * c;
    }
  }
  double force(const Layers& l) const {
    double f = 0;
    for (double s : l.sig) f += s * dA_;
    return f;
  }
  double moment(const Layers& l) const {
    double mo = 0;
    for (int i = 0; i < n_; ++i) mo += l.sig[i] * z_[i] * dA_;
    return mo;
  }
  /// The membrane increment that keeps the section's force at T.  The force
  /// rises monotonically (and continuously) with the membrane strain, so its
  /// root is bracketed in [-0.2, 0.2]; regula falsi with the Illinois halving
  /// closes the bracket to adjacent doubles (or 128 halvings: 1e-39 of the
  /// 0.4 bracket, where bisection stopped at 64), with a bisection step
  /// whenever a secant step fails to halve the bracket (so it at least halves
  /// each iteration).  Bisection alone took 66 section updates
  /// a step, and test_bending_work 52 s (2026-12-06, 2-core Intel Xeon).
  double carry(const Layers& a, double dk, double T, Layers& out, double& dm) const {
    double lo = -0.2, hi = 0.2;
    update(a, hi, dk, out);
    double fhi = force(out) - T;
    if (fhi < 0) throw std::invalid_argument("bend_unbend: the section cannot carry the tension " + std::to_string(T) + " N");
    update(a, lo, dk, out);
    double flo = force(out) - T;
    int side = 0;  // which end moved last: -1 lo, +1 hi (the Illinois halving of the other's value)
    for (int it = 0; it < 128 && std::nextafter(lo, hi) < hi; ++it) {
      const double width = hi - lo;
      double x = flo < 0 && fhi > 0 ? lo - flo * (width / (fhi - flo)) : 0.5 * (lo + hi);
      if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
      update(a, x, dk, out);
      const double f = force(out) - T;
      if (f > 0) {
        hi = x, fhi = f;
        if (side == 1) flo *= 0.5;
        side = 1;
      } else {
        lo = x, flo = f;
        if (side == -1) fhi *= 0.5;
        side = -1;
      }
      if (f == 0) {
        lo = hi = x;
        break;
      }
      if (hi - lo > 0.5 * width) {  // the secant crept along one end: bisect
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        update(a, mid, dk, out);
        const double fm = force(out) - T;
        (fm > 0 ? hi : lo) = mid;
        (fm > 0 ? fhi : flo) = fm;
        side = 0;
      }
    }
    dm = 0.5 * (lo + hi);
    update(a, dm, dk, out);
    return moment(out);
  }

 private:
  const BendMaterial& m_;
  int n_;
  double modulus_ = 0, ec_ = 0, dA_ = 0, width_ = 0, t_ = 0;
  std::vector<double> z_;
};

}  // namespace

BendResult bend_unbend(const BendCase& bc, const BendMaterial& m) {
  if (!(bc.pin_diameter_mm > 0 && bc.thickness_mm > 0 && bc.width_mm > 0 && bc.tension_N >= 0))
    throw std::invalid_argument("bend_unbend: pin diameter, thickness and width must be > 0, tension >= 0");
  if (bc.layers < 2 || bc.steps < 1) throw std::invalid_argument("bend_unbend: at least 2 layers and 1 step");
  if (!m.flow || !m.dflow) throw std::invalid_argument("bend_unbend: no flow curve");
  if (!(m.E_MPa > 0 && m.constraint >= 1 && m.x_sat_MPa >= 0 && m.gamma >= 0))
    throw std::invalid_argument("bend_unbend: E > 0, constraint >= 1, X_sat >= 0 and gamma >= 0 required");
  if (!(m.flow(0) > 0)) throw std::invalid_argument("bend_unbend: the flow curve must start above 0 MPa");
  Section sec(bc, m);
  // Plane strain across the width with plastic incompressibility: the
  // section thins as the strip stretches, t = t0 exp(-eps_m).
  auto thin = [&](double em) {
    if (bc.thinning) sec.set_thickness(bc.thickness_mm * std::exp(-em));
  };
  Layers a{std::vector<double>(bc.layers, 0.0), std::vector<double>(bc.layers, 0.0),
           std::vector<double>(bc.layers, 0.0)};
  Layers b = a;
  double dm = 0, em = 0;
  sec.carry(a, 0.0, bc.tension_N, b, dm);  // the straight strip under tension
  em += dm;
  std::swap(a, b);
  thin(em);
  const double kappa = 1.0 / (bc.pin_diameter_mm / 2 + sec.thickness() / 2);
  double work = 0;
  for (const double dk : {kappa / bc.steps, -kappa / bc.steps})
    for (int k = 0; k < bc.steps; ++k) {
      const double m0 = sec.moment(a);
      const double m1 = sec.carry(a, dk, bc.tension_N, b, dm);
      work += 0.5 * (m0 + m1) * dk;  // trapezoidal M dkappa
      em += dm;
      std::swap(a, b);
      thin(em);
    }
  BendResult r;
  r.bending_force_N = work;
  r.max_plastic_strain = *std::max_element(a.p.begin(), a.p.end());
  r.membrane_strain = em;
  return r;
}

double hosford_plane_strain_factor(double a) {
  if (!(a >= 1)) throw std::invalid_argument("hosford_plane_strain_factor: the exponent must be >= 1");
  // For the isotropic Hosford surface the plane-strain state (d f / d s2 = 0
  // at s3 = 0) is s2 = s1 / 2 for every a: the two terms |s2 - s1|^(a-1) and
  // |s2|^(a-1) balance there.  Then f = s1 ((1 + 2 (1/2)^a) / 2)^(1/a).
  return 1.0 / std::pow((1 + 2 * std::pow(0.5, a)) / 2, 1 / a);
}

}  // namespace drawbend::analysis
