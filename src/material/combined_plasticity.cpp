#include "material/combined_plasticity.hpp"

#include <cmath>
#include <stdexcept>

#include "core/csv.hpp"
#include "material/sheet_frame.hpp"
#include "material/lane_binding.hpp"

namespace drawbend::material {

void KinematicHardening::validate() const {
  if (chaboche.size() > 3)
    throw std::invalid_argument("kinematic hardening: at most 3 Armstrong-Frederick terms, found " +
                                std::to_string(chaboche.size()));
  for (const Term& t : chaboche) {
    if (!(t.C >= 0) || !std::isfinite(t.C))
      throw std::invalid_argument("kinematic hardening: C must be >= 0 MPa and finite, found " + fmt_shortest(t.C));
    if (!(t.gamma >= 0) || !std::isfinite(t.gamma))
      throw std::invalid_argument("kinematic hardening: gamma must be >= 0 and finite, found " +
                                  fmt_shortest(t.gamma));
  }
  if (!(beta >= 0 && beta <= 1))
    throw std::invalid_argument("kinematic hardening: beta must lie in [0, 1], found " + fmt_shortest(beta));
  if (beta > 0 && !chaboche.empty())
    throw std::invalid_argument("kinematic hardening: give either beta (split form) or C/gamma terms, not both");
}

namespace {
constexpr int kMaxBack = 3;
}  // namespace

CombinedPlasticity::CombinedPlasticity(double youngs_modulus, double poisson_ratio, double density,
                                       HardeningCurve curve, KinematicHardening kinematic, Hill48 yield)
    : el_(youngs_modulus, poisson_ratio, density),
      curve_(std::move(curve)),
      kin_(std::move(kinematic)),
      hill_(yield),
      aniso_(!yield.is_von_mises()) {
  kin_.validate();
  hill_.validate();
  nback_ = kin_.beta > 0 ? 1 : static_cast<int>(kin_.chaboche.size());
  ns_ = 1 + 6 * nback_ + (aniso_ ? 6 : 0);
  s0_ = curve_.initial_yield();
}

CombinedPlasticity::LaneParams CombinedPlasticity::lane_params() const noexcept {
  LaneParams p{el_.lambda, el_.G, el_.E, s0_, kin_.beta, {0, 0, 0}, {0, 0, 0},
               static_cast<int>(kin_.chaboche.size()), nback_, aniso_, hill_, curve_.table()};
  for (int k = 0; k < p.nterms; ++k) {
    p.C[k] = kin_.chaboche[k].C;
    p.gamma[k] = kin_.chaboche[k].gamma;
  }
  return p;
}

double CombinedPlasticity::isotropic_stress(double ep) const {
  const double s = curve_.stress(ep);
  return kin_.beta > 0 ? s0_ + (1.0 - kin_.beta) * (s - s0_) : s;
}

void CombinedPlasticity::init_state(double* state, const SheetAxes& axes) const {
  for (int i = 0; i < ns_; ++i) state[i] = 0.0;
  if (aniso_) {
    double* rd = state + 1 + 6 * nback_;
    for (int i = 0; i < 3; ++i) {
      rd[i] = axes.rd[i];
      rd[3 + i] = axes.nd[i];
    }
  }
}

SheetAxes CombinedPlasticity::axes(const double* state) const {
  SheetAxes a;
  if (!aniso_) return a;
  const double* rd = state + 1 + 6 * nback_;
  for (int i = 0; i < 3; ++i) {
    a.rd[i] = rd[i];
    a.nd[i] = rd[3 + i];
  }
  cross3(a.nd, a.rd, a.td);
  return a;
}

void CombinedPlasticity::back_stress(const double* state, double alpha[6]) const {
  for (int c = 0; c < 6; ++c) alpha[c] = 0.0;
  for (int k = 0; k < nback_; ++k)
    for (int c = 0; c < 6; ++c) alpha[c] += state[1 + 6 * k + c];
}

double CombinedPlasticity::equivalent(const double x[6]) const {
  const double a = x[1] - x[2], b = x[2] - x[0], c = x[0] - x[1];
  const double q2 = hill_.F * a * a + hill_.G * b * b + hill_.H * c * c +
                    2.0 * (hill_.N * x[3] * x[3] + hill_.L * x[4] * x[4] + hill_.M * x[5] * x[5]);
  return std::sqrt(q2);
}

void CombinedPlasticity::solve_relative(double kappa, const double xs[6], double xi[6]) const {
  const double F = hill_.F, G = hill_.G, H = hill_.H;
  const double A[3][3] = {{1.0 + kappa * (G + H), -kappa * H, -kappa * G},
                          {-kappa * H, 1.0 + kappa * (F + H), -kappa * F},
                          {-kappa * G, -kappa * F, 1.0 + kappa * (F + G)}};
  const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                     A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                     A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  const double b0 = xs[0], b1 = xs[1], b2 = xs[2];
  xi[0] = (b0 * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (b1 * A[2][2] - A[1][2] * b2) +
           A[0][2] * (b1 * A[2][1] - A[1][1] * b2)) / det;
  xi[1] = (A[0][0] * (b1 * A[2][2] - A[1][2] * b2) - b0 * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
           A[0][2] * (A[1][0] * b2 - b1 * A[2][0])) / det;
  xi[2] = (A[0][0] * (A[1][1] * b2 - b1 * A[2][1]) - A[0][1] * (A[1][0] * b2 - b1 * A[2][0]) +
           b0 * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) / det;
  xi[3] = xs[3] / (1.0 + kappa * hill_.N);
  xi[4] = xs[4] / (1.0 + kappa * hill_.L);
  xi[5] = xs[5] / (1.0 + kappa * hill_.M);
}

// The steps of update, each inlined into it (the same instructions as when it
// was written out in one piece: the scalar path of the element kernel).
#define DRAWBEND_STEP __attribute__((always_inline)) inline

/// 1. Objectivity: the back stresses and the sheet axes (after them in the
///    state) turn with the spin the element applied to sigma; Q: the sheet
///    axes as rows (identity for von Mises).
DRAWBEND_STEP void CombinedPlasticity::turn_history(const Spin& spin, double* back, double Q[3][3]) const {
  if (spin.dt != 0.0)
    for (int k = 0; k < nback_; ++k) rotate_symmetric(spin, back + 6 * k);
  if (aniso_) {
    double* rd = back + 6 * nback_;
    double* nd = rd + 3;
    if (spin.dt != 0.0) {
      rotate_vector(spin, rd);
      rotate_vector(spin, nd);
      orthonormalise_axes(rd, nd);
    }
    double td[3];
    cross3(nd, rd, td);
    for (int i = 0; i < 3; ++i) {
      Q[0][i] = rd[i];
      Q[1][i] = td[i];
      Q[2][i] = nd[i];
    }
  }
}

/// 2. The elastic trial stress tr and the back stresses in the sheet axes (ts, an).
DRAWBEND_STEP void CombinedPlasticity::trial_in_sheet_axes(const double Q[3][3], const double tr[6],
                                                           const double* back, double ts[6], double (*an)[6]) const {
  if (aniso_) {
    sheet_transform(Q, tr, ts, true);
    for (int k = 0; k < nback_; ++k) sheet_transform(Q, back + 6 * k, an[k], true);
  } else {
    for (int c = 0; c < 6; ++c) ts[c] = tr[c];
    for (int k = 0; k < nback_; ++k)
      for (int c = 0; c < 6; ++c) an[k][c] = back[6 * k + c];
  }
}

/// 3. Plastic: the scalar consistency condition in dl, bracketed and solved;
///    returns dl, with xi (the relative stress) and Rv (the isotropic stress)
///    at it.  f0 > 0: the trial's yield function; s_ep: the curve's stress at ep.
DRAWBEND_STEP double CombinedPlasticity::plastic_multiplier(double ep, double s_ep, double f0, const double ts[6],
                                                            const double (*an)[6], double xi[6], double& Rv) const {
  // The residual is sigma_bar(xi) - R times 1 + kappa (F + G + H), positive
  // for kappa >= 0 (F + G + H is half the trace of T M, whose two non-zero
  // eigenvalues are positive for every Hill'48 that validate() accepts), so
  // the root stays.  For von Mises, where T M is 3/2 on the deviators, the
  // product is q* - R - 3 G dl - (kinematic hardening):
  // linear in dl on a curve segment of the isotropic and split forms, where
  // the plain residual q* / (1 + 3 kappa / 2) - R is not, so the secant lands
  // on the root at its first step (2 evaluations instead of 6 in make bench's
  // material table).  F + G + H is the mean of T M's eigenvalues on the
  // normal deviators; for Hill'48 and Chaboche terms the product is nearly
  // linear (5 evaluations instead of 6 and 8 there; the Rayleigh quotient of
  // T M at the trial direction in its place gave the same counts).
  const double c_lin = hill_.F + hill_.G + hill_.H;
  auto residual = [&](double dl, double out[6], double& R) {
    double kin = 0.0, xstar[6] = {ts[0], ts[1], ts[2], ts[3], ts[4], ts[5]};
    if (kin_.beta > 0) {
      for (int c = 0; c < 6; ++c) xstar[c] -= an[0][c];
      kin = kin_.beta * (curve_.stress(ep + dl) - s_ep);
    } else {
      for (int k = 0; k < nback_; ++k) {
        const double a = 1.0 / (1.0 + kin_.chaboche[k].gamma * dl);
        for (int c = 0; c < 6; ++c) xstar[c] -= a * an[k][c];
        kin += a * kin_.chaboche[k].C * dl;
      }
    }
    R = isotropic_stress(ep + dl);
    const double kappa = (2.0 * el_.G * dl + (2.0 / 3.0) * kin) / R;
    solve_relative(kappa, xstar, out);
    return (equivalent(out) - R) * (1.0 + kappa * c_lin);
  };
  double lo = 0.0, flo = f0, hi = f0 / (3.0 * el_.G), fhi = residual(hi, xi, Rv);
  for (int it = 0; fhi > 0.0 && it < 200; ++it) {
    lo = hi;
    flo = fhi;
    hi *= 2.0;
    fhi = residual(hi, xi, Rv);
  }
  double dl = hi;
  if (fhi != 0.0) {
    int side = 0;
    for (int it = 0; it < 200; ++it) {
      double x = hi - fhi * (hi - lo) / (fhi - flo);
      if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
      const double fx = residual(x, xi, Rv);
      dl = x;
      if (fx == 0.0 || std::abs(fx) <= 1e-13 * Rv || hi - lo <= 1e-15 * hi) break;
      if (fx > 0.0) {
        lo = x;
        flo = fx;
        if (side == 1) fhi *= 0.5;
        side = 1;
      } else {
        hi = x;
        fhi = fx;
        if (side == -1) flo *= 0.5;
        side = -1;
      }
    }
  }
  // xi and Rv are at the accepted dl: every way out of the loops above leaves
  // dl at the residual's last evaluation.
  return dl;
}

/// 4. The back stresses an from the flow direction T M xi / R, and the stress;
///    both turned back to the global axes (sigma, back).
DRAWBEND_STEP void CombinedPlasticity::harden_and_rotate_back(const double Q[3][3], double ep, double s_ep, double dl,
                                                              const double xi[6], double Rv, double (*an)[6],
                                                              double sigma[6], double* back) const {
  double n[6];
  {
    const double F = hill_.F, G = hill_.G, H = hill_.H;
    n[0] = ((G + H) * xi[0] - H * xi[1] - G * xi[2]) / Rv;
    n[1] = (-H * xi[0] + (F + H) * xi[1] - F * xi[2]) / Rv;
    n[2] = (-G * xi[0] - F * xi[1] + (F + G) * xi[2]) / Rv;
    n[3] = hill_.N * xi[3] / Rv;
    n[4] = hill_.L * xi[4] / Rv;
    n[5] = hill_.M * xi[5] / Rv;
  }
  double sl[6] = {xi[0], xi[1], xi[2], xi[3], xi[4], xi[5]};
  for (int k = 0; k < nback_; ++k) {
    double a, incr;
    if (kin_.beta > 0) {
      a = 1.0;
      incr = (2.0 / 3.0) * kin_.beta * (curve_.stress(ep + dl) - s_ep);
    } else {
      a = 1.0 / (1.0 + kin_.chaboche[k].gamma * dl);
      incr = (2.0 / 3.0) * kin_.chaboche[k].C * dl;
    }
    for (int c = 0; c < 6; ++c) {
      an[k][c] = a * (an[k][c] + incr * n[c]);
      sl[c] += an[k][c];
    }
  }
  if (aniso_) {
    sheet_transform(Q, sl, sigma, false);
    for (int k = 0; k < nback_; ++k) sheet_transform(Q, an[k], back + 6 * k, false);
  } else {
    for (int c = 0; c < 6; ++c) sigma[c] = sl[c];
    for (int k = 0; k < nback_; ++k)
      for (int c = 0; c < 6; ++c) back[6 * k + c] = an[k][c];
  }
}
#undef DRAWBEND_STEP

void CombinedPlasticity::update(const double deps[6], const Spin& spin, double sigma[6], double* state) const {
  const double ep = state[0];
  double* back = state + 1;
  double Q[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  turn_history(spin, back, Q);
  // The elastic trial stress, in the sheet axes with the back stresses.
  double tr[6] = {sigma[0], sigma[1], sigma[2], sigma[3], sigma[4], sigma[5]};
  el_.add_elastic(deps, tr);
  double ts[6], an[kMaxBack][6];
  trial_in_sheet_axes(Q, tr, back, ts, an);
  double xs[6];
  for (int c = 0; c < 6; ++c) {
    xs[c] = ts[c];
    for (int k = 0; k < nback_; ++k) xs[c] -= an[k][c];
  }
  const double R0 = isotropic_stress(ep);
  const double f0 = equivalent(xs) - R0;
  if (!(f0 > 0.0)) {
    for (int c = 0; c < 6; ++c) sigma[c] = tr[c];
    return;
  }
  const double s_ep = curve_.stress(ep);
  double xi[6], Rv = R0;
  const double dl = plastic_multiplier(ep, s_ep, f0, ts, an, xi, Rv);
  harden_and_rotate_back(Q, ep, s_ep, dl, xi, Rv, an, sigma, back);
  state[0] = ep + dl;
}

double CombinedPlasticity::tangent_ratio(const double* sigma, const double* state) const {
  const double ep = state[0];
  double xi[6], alpha[6];
  back_stress(state, alpha);
  for (int c = 0; c < 6; ++c) xi[c] = sigma[c] - alpha[c];
  if (aniso_) {
    const SheetAxes a = axes(state);
    const double Q[3][3] = {{a.rd[0], a.rd[1], a.rd[2]}, {a.td[0], a.td[1], a.td[2]}, {a.nd[0], a.nd[1], a.nd[2]}};
    double l[6];
    sheet_transform(Q, xi, l, true);
    for (int c = 0; c < 6; ++c) xi[c] = l[c];
  }
  // Monotonic uniaxial tangent: the curve's slope for the split form; the
  // isotropic slope plus each back stress's C exp(-gamma eps_p) for Chaboche.
  const double f = equivalent(xi) / isotropic_stress(ep);
  if (f <= 0.90) return 1.0;  // yield_proximity_ratio's value without the tangent
  double H = curve_.slope(ep);
  for (const auto& t : kin_.chaboche) H += t.C * std::exp(-t.gamma * ep);
  return yield_proximity_ratio(f, H / (el_.E + H));
}

std::string CombinedPlasticity::describe() const {
  std::string k;
  if (kin_.beta > 0) {
    k = "split kinematic fraction beta = " + fmt_shortest(kin_.beta);
  } else if (!kin_.chaboche.empty()) {
    k = "Chaboche";
    for (const auto& t : kin_.chaboche) k += " (C = " + fmt_shortest(t.C) + " MPa, gamma = " + fmt_shortest(t.gamma) + ")";
  } else {
    k = "isotropic only";
  }
  return std::string(aniso_ ? hill_.describe() : "von Mises") + " plasticity, " + k + " (E = " + fmt(el_.E) +
         " MPa, nu = " + fmt(el_.nu) + ", rho = " + fmt(el_.rho) + " t/mm^3, " + std::to_string(curve_.size()) +
         "-point curve, initial yield " + fmt(s0_) + " MPa)";
}

void CombinedPlasticity::bind_lanes(LaneBinding& b) const {
  b.combined = true;
  b.combined_params = lane_params();
}

}  // namespace drawbend::material
