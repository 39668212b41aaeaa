#include "material/yld2004_plasticity.hpp"

#include <atomic>
#include <cmath>
#include <stdexcept>

#include "core/csv.hpp"
#include "material/lane_binding.hpp"
#include "material/sheet_frame.hpp"

namespace drawbend::material {

namespace {
constexpr int kMaxBackYld = 3;
constexpr int kMaxIter = 60;     // iterations per (sub-)increment
constexpr int kMaxSub = 256;     // at most this many sub-increments (1, 4, 16, 64, 256)
constexpr double kTol = 1e-6;    // converged: |f| <= kTol R and 2 G x |n' - n| <= kTol R
inline double contract(const double a[6], const double b[6]) {  // a : b, tensor shears
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}
}  // namespace

Yld2004Plasticity::Yld2004Plasticity(double youngs_modulus, double poisson_ratio, double density,
                                     HardeningCurve curve, KinematicHardening kinematic, const Yld2004& yield)
    : el_(youngs_modulus, poisson_ratio, density), curve_(std::move(curve)), kin_(std::move(kinematic)) {
  kin_.validate();
  if (!std::isfinite(yield.a) || !(yield.a >= 2.0)) yield.validate();  // the exponent's message
  yld_ = yield.normalised();
  const double u[6] = {1, 0, 0, 0, 0, 0};
  scale_ = yield.equivalent(u);
  yld_.validate();
  nback_ = kin_.beta > 0 ? 1 : static_cast<int>(kin_.chaboche.size());
  ns_ = 1 + 6 * nback_ + 6;
  s0_ = curve_.initial_yield();
}

double Yld2004Plasticity::isotropic_stress(double ep) const {
  const double s = curve_.stress(ep);
  return kin_.beta > 0 ? s0_ + (1.0 - kin_.beta) * (s - s0_) : s;
}

void Yld2004Plasticity::init_state(double* state, const SheetAxes& axes) const {
  for (int i = 0; i < ns_; ++i) state[i] = 0.0;
  double* rd = state + 1 + 6 * nback_;
  for (int i = 0; i < 3; ++i) {
    rd[i] = axes.rd[i];
    rd[3 + i] = axes.nd[i];
  }
}

SheetAxes Yld2004Plasticity::axes(const double* state) const {
  SheetAxes a;
  const double* rd = state + 1 + 6 * nback_;
  for (int i = 0; i < 3; ++i) {
    a.rd[i] = rd[i];
    a.nd[i] = rd[3 + i];
  }
  cross3(a.nd, a.rd, a.td);
  return a;
}

void Yld2004Plasticity::back_stress(const double* state, double alpha[6]) const {
  for (int c = 0; c < 6; ++c) alpha[c] = 0.0;
  for (int k = 0; k < nback_; ++k)
    for (int c = 0; c < 6; ++c) alpha[c] += state[1 + 6 * k + c];
}

// The back stresses at the end of the increment for the multiplier dl and the normal n (backward Euler,
// as CombinedPlasticity: a_k = 1 / (1 + gamma_k dl); the split form's secant of the curve); returns
// n : d alpha / d dl, the kinematic part of the linearisation.
double Yld2004Plasticity::kinematic_rate(const double n[6], const double an[][6], double ep, double dl,
                                         double out[][6]) const {
  double rate = 0.0;
  if (kin_.beta > 0) {
    const double ds = curve_.stress(ep + dl) - curve_.stress(ep);
    for (int c = 0; c < 6; ++c) out[0][c] = an[0][c] + (2.0 / 3.0) * kin_.beta * ds * n[c];
    rate = (2.0 / 3.0) * kin_.beta * curve_.slope(ep + dl) * contract(n, n);
  } else {
    for (int k = 0; k < nback_; ++k) {
      const double C = kin_.chaboche[k].C, g = kin_.chaboche[k].gamma, a = 1.0 / (1.0 + g * dl);
      for (int c = 0; c < 6; ++c) out[k][c] = a * (an[k][c] + (2.0 / 3.0) * C * dl * n[c]);
      rate += (2.0 / 3.0) * C * contract(n, n) - g * contract(n, out[k]);
    }
  }
  return rate;
}

bool Yld2004Plasticity::return_map(double ts[6], double an[][6], double ep, double& dl, double sb,
                                   const double n_trial[6]) const {
  const double G2 = 2.0 * el_.G;
  double xi[6], n[6], nn[6], sg[6], ac[kMaxBackYld][6];
  // The trial point (x = 0): sigma_bar sb and its normal n_trial, the first guess.
  for (int c = 0; c < 6; ++c) nn[c] = n_trial[c];
  double x = 0.0, kin = kinematic_rate(nn, an, ep + dl, 0.0, ac);
  for (int c = 0; c < 6; ++c) n[c] = nn[c];
  for (int it = 0; it < kMaxIter; ++it) {
    const double R = isotropic_stress(ep + dl + x);
    const double f = sb - R;
    if (!std::isfinite(f)) return false;
    // Converged: f = 0 and the end point's normal is the one it was built with, both to kTol R in stress
    // (2 G x |n' - n| is how far the end point would move with the new normal).
    double dn = 0.0;
    for (int c = 0; c < 6; ++c) dn = std::max(dn, std::abs(nn[c] - n[c]));
    if (it > 0 && std::abs(f) <= kTol * R && G2 * x * dn <= kTol * R) {
      for (int c = 0; c < 6; ++c) {
        ts[c] = sg[c];
        for (int k = 0; k < nback_; ++k) an[k][c] = ac[k][c];
      }
      dl += x;
      return true;
    }
    const double hiso = (kin_.beta > 0 ? 1.0 - kin_.beta : 1.0) * curve_.slope(ep + dl + x);
    const double denom = G2 * contract(nn, nn) + hiso + kin;
    if (!(denom > 0) || !std::isfinite(denom)) return false;
    x = std::max(0.0, x + f / denom);
    for (int c = 0; c < 6; ++c) n[c] = nn[c];
    // The end point for (x, n): sigma = sigma_trial - 2 G x n, the back stresses, and its own normal.
    kin = kinematic_rate(n, an, ep + dl, x, ac);
    for (int c = 0; c < 6; ++c) {
      sg[c] = ts[c] - G2 * x * n[c];
      xi[c] = sg[c];
      for (int k = 0; k < nback_; ++k) xi[c] -= ac[k][c];
    }
    sb = yld_.gradient(xi, nn);
    if (!std::isfinite(sb)) return false;
  }
  return false;
}

void Yld2004Plasticity::update(const double deps[6], const Spin& spin, double sigma[6], double* state) const {
  const double ep = state[0];
  double* back = state + 1;
  // 1. Objectivity: back stresses and sheet axes turn with the spin the element applied to sigma.
  if (spin.dt != 0.0)
    for (int k = 0; k < nback_; ++k) rotate_symmetric(spin, back + 6 * k);
  double* rd = back + 6 * nback_;
  double* nd = rd + 3;
  if (spin.dt != 0.0) {
    rotate_vector(spin, rd);
    rotate_vector(spin, nd);
    orthonormalise_axes(rd, nd);
  }
  double td[3], Q[3][3];
  cross3(nd, rd, td);
  for (int i = 0; i < 3; ++i) Q[0][i] = rd[i], Q[1][i] = td[i], Q[2][i] = nd[i];
  // 2. Elastic trial stress in the sheet axes.
  double tr[6] = {sigma[0], sigma[1], sigma[2], sigma[3], sigma[4], sigma[5]};
  el_.add_elastic(deps, tr);
  double ts[6], an[kMaxBackYld][6], xi[6];
  sheet_transform(Q, tr, ts, true);
  for (int k = 0; k < nback_; ++k) sheet_transform(Q, back + 6 * k, an[k], true);
  for (int c = 0; c < 6; ++c) {
    xi[c] = ts[c];
    for (int k = 0; k < nback_; ++k) xi[c] -= an[k][c];
  }
  double nt[6];
  const double sbt = yld_.gradient(xi, nt);
  if (!(sbt - isotropic_stress(ep) > 0.0)) {
    for (int c = 0; c < 6; ++c) sigma[c] = tr[c];
    return;
  }
  // 3. Plastic: the return on the whole increment, else on 4, 16, 64, 256 equal sub-increments.
  double s0[6], dts[6], trial[6];
  sheet_transform(Q, sigma, s0, true);
  for (int c = 0; c < 6; ++c) trial[c] = ts[c], dts[c] = ts[c] - s0[c];
  double dl = 0.0;
  bool ok = false;
  bool split_used = false;
  for (int m = 1; m <= kMaxSub && !ok; m *= 4) {
    split_used = m > 1;
    for (int k = 0; k < nback_; ++k) sheet_transform(Q, back + 6 * k, an[k], true);
    for (int c = 0; c < 6; ++c) ts[c] = m == 1 ? trial[c] : s0[c];
    dl = 0.0;
    ok = true;
    for (int sub = 1; sub <= m && ok; ++sub) {
      if (m > 1)
        for (int c = 0; c < 6; ++c) ts[c] += dts[c] / m;  // this sub-increment's elastic trial
      double sb = sbt;
      if (m > 1) {
        for (int c = 0; c < 6; ++c) {
          xi[c] = ts[c];
          for (int k = 0; k < nback_; ++k) xi[c] -= an[k][c];
        }
        sb = yld_.gradient(xi, nt);
      }
      if (sb - isotropic_stress(ep + dl) > 0.0) ok = return_map(ts, an, ep, dl, sb, nt);
    }
  }
  counts_->plastic.fetch_add(1, std::memory_order_relaxed);
  if (!ok) counts_->fallback.fetch_add(1, std::memory_order_relaxed);
  if (split_used) counts_->split.fetch_add(1, std::memory_order_relaxed);
  if (!ok) {  // admissible fallback: the last iterate scaled radially onto the surface
    for (int c = 0; c < 6; ++c) {
      xi[c] = ts[c];
      for (int k = 0; k < nback_; ++k) xi[c] -= an[k][c];
    }
    const double q = isotropic_stress(ep + dl) / yld_.equivalent(xi);
    for (int c = 0; c < 6; ++c) ts[c] = ts[c] - xi[c] + q * xi[c];
  }
  // 4. Back to global axes.
  sheet_transform(Q, ts, sigma, false);
  for (int k = 0; k < nback_; ++k) sheet_transform(Q, an[k], back + 6 * k, false);
  state[0] = ep + dl;
}

Yld2004Plasticity::LaneParams Yld2004Plasticity::lane_params() const noexcept {
  LaneParams p{el_.lambda, el_.G, el_.E, s0_, kin_.beta, {0, 0, 0}, {0, 0, 0},
               static_cast<int>(kin_.chaboche.size()), nback_, yld_.a,
               yld_.a == std::floor(yld_.a) && yld_.a <= 64,  // Yld2004's own test (yld2004.cpp, evaluate)
               {}, {}, curve_.table(), this};
  for (int k = 0; k < p.nterms; ++k) {
    p.C[k] = kin_.chaboche[k].C;
    p.gamma[k] = kin_.chaboche[k].gamma;
  }
  for (int i = 0; i < 9; ++i) p.c1[i] = yld_.c1[i], p.c2[i] = yld_.c2[i];
  return p;
}

void Yld2004Plasticity::bind_lanes(LaneBinding& b) const {
  b.yld2004 = true;
  b.yld2004_params = lane_params();
}

void Yld2004Plasticity::count_lane_returns(long plastic) const {
  counts_->plastic.fetch_add(plastic, std::memory_order_relaxed);
}

Yld2004Plasticity::ReturnCounts Yld2004Plasticity::return_counts() const {
  return {counts_->plastic.load(std::memory_order_relaxed), counts_->split.load(std::memory_order_relaxed),
          counts_->fallback.load(std::memory_order_relaxed)};
}

std::vector<std::pair<std::string, long>> Yld2004Plasticity::event_counts() const {
  const ReturnCounts c = return_counts();
  return {{"plastic_updates", c.plastic}, {"split_updates", c.split}, {"fallback_updates", c.fallback}};
}

double Yld2004Plasticity::tangent_ratio(const double* sigma, const double* state) const {
  const double ep = state[0];
  double xi[6], alpha[6], l[6];
  back_stress(state, alpha);
  for (int c = 0; c < 6; ++c) xi[c] = sigma[c] - alpha[c];
  const SheetAxes a = axes(state);
  const double Q[3][3] = {{a.rd[0], a.rd[1], a.rd[2]}, {a.td[0], a.td[1], a.td[2]}, {a.nd[0], a.nd[1], a.nd[2]}};
  sheet_transform(Q, xi, l, true);
  const double f = yld_.equivalent(l) / isotropic_stress(ep);
  if (f <= 0.90) return 1.0;
  double H = curve_.slope(ep);
  for (const auto& t : kin_.chaboche) H += t.C * std::exp(-t.gamma * ep);
  return yield_proximity_ratio(f, H / (el_.E + H));
}

std::string Yld2004Plasticity::describe() const {
  std::string k;
  if (kin_.beta > 0) {
    k = "split kinematic fraction beta = " + fmt_shortest(kin_.beta);
  } else if (!kin_.chaboche.empty()) {
    k = "Chaboche";
    for (const auto& t : kin_.chaboche) k += " (C = " + fmt_shortest(t.C) + " MPa, gamma = " + fmt_shortest(t.gamma) + ")";
  } else {
    k = "isotropic only";
  }
  return yld_.describe() + (scale_ != 1.0 ? " (input scaled by 1/" + fmt(scale_, 6) + " to sigma_bar(RD) = 1)" : "") +
         " plasticity, " + k + " (E = " + fmt(el_.E) + " MPa, nu = " + fmt(el_.nu) + ", rho = " + fmt(el_.rho) +
         " t/mm^3, " + std::to_string(curve_.size()) + "-point curve, initial yield " + fmt(s0_) + " MPa)";
}

}  // namespace drawbend::material
