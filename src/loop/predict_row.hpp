#pragma once
// Internal to the loop's force model: the force model evaluated at a row, base
// model plus effects.  Inline, because the fits (model.cpp) call it per row and
// Levenberg-Marquardt step.
//   rotating pin:  F_out = F_back + F_B
//   fixed pin:     F_out = F_back + F_B + F_fric,  F_fric = F_back (exp(mu Theta) - 1)  (Eq. 5.1)
//   mu = (ellipse(mu_RD, mu_TD; phi) + a1 p) * factor * pinf   (terms from effect_rules.hpp)
// with the map pressure p following the mean strip tension (Eq. 2.2, as map_pressure).
#include <cmath>

#include "analysis/friction_surface.hpp"
#include "analysis/pressure_ratio.hpp"
#include "analysis/rope.hpp"
#include "loop/effect_rules.hpp"

namespace drawbend::loop {

namespace detail {

// A row's prediction in three steps, so that two rows' map iterations can be
// interleaved (predict_rows2): begin (the bending line, the effects' terms;
// done when the row needs no iteration), step (one map iteration), end.  The
// operations of each row are predict_row's, in the same order.
struct RowState {
  const Row* r = nullptr;
  bool done = false;
  double value = 0;  // the prediction, when done
  double bend = 0, bend_ref = 0, mu0 = 0, ff = 0, mu = 0;
  int iters = 0;
  Terms t;
};

inline void predict_row_begin(const Design& d, const Fit& f, const Layout& L, const Eigen::VectorXd& th, int i,
                              const Row* override_row, RowState& s) {
  const Row& r = override_row ? *override_row : d.rows[i];
  s.r = &r;
  s.done = true;
  const double bend_x = f.bend_extra.empty() ? 0.0 : f.bend_extra[i];  // bending-channel effects
  const double bend = f.b0[r.pin] + f.b1[r.pin] * r.fback + bend_x;
  if (std::isnan(bend)) return void(s.value = std::nan(""));
  if (r.rotating) {
    if (!f.has_force) return void(s.value = r.fback + bend);
    Terms t;
    for (size_t k = 0; k < f.spec.effects.size(); ++k)
      if (f.spec.effects[k].kind == EffectKind::force_offset) {
        const Effect& e = f.spec.effects[k];
        visit_rule(e.kind, [&](auto rule) { rule.apply(EffectArgs{d, f, r, i, k, e, th.data() + L.eff_start[k]}, t); });
      }
    return void(s.value = r.fback + bend + t.add_N);
  }
  const int ir = L.mu_rd[r.cell], it = L.mu_td[r.cell];
  double mu0;
  if (ir >= 0 && it >= 0) mu0 = analysis::ellipse_mu(th[ir], th[it], r.cos_phi, r.sin_phi);
  else mu0 = th[ir >= 0 ? ir : it];
  if (!f.seen.empty() && ((ir >= 0 && !f.seen[ir]) || (it >= 0 && !f.seen[it]))) return void(s.value = std::nan(""));
  Terms t;
  for (size_t k = 0; k < f.spec.effects.size(); ++k) {
    const Effect& e = f.spec.effects[k];
    const EffectArgs a{d, f, r, i, k, e, th.data() + L.eff_start[k]};
    visit_rule(e.kind, [&](auto rule) { rule.apply(a, t); });
  }
  s.done = false;
  s.bend = bend, s.mu0 = mu0, s.t = t, s.ff = 0, s.mu = 0;
  s.iters = t.a1 != 0 ? 4 : 1;
  s.bend_ref = f.b0[r.pin] + f.b1[r.pin] * r.fref + bend_x;
}

// One iteration: the map follows the mean tension (Eq. 2.2), friction included.
inline void predict_row_step(RowState& s) {
  const Row& r = *s.r;
  const double p = analysis::pressure_at_tension(r.pw_ref, r.fback, s.bend, s.ff, r.fref, s.bend_ref);  // map_pressure
  s.mu = (s.mu0 + s.t.a1 * p) * s.t.factor * s.t.pinf;
  s.ff = analysis::friction_from_mu(s.mu, r.fback, kWrapRad);
}

inline double predict_row_end(const RowState& s, double* mu_out, double* p_out) {
  if (s.done) return s.value;
  const Row& r = *s.r;
  if (mu_out) *mu_out = s.mu;
  if (p_out) *p_out = analysis::pressure_at_tension(r.pw_ref, r.fback, s.bend, s.ff, r.fref, s.bend_ref);
  return r.fback + s.bend + s.ff + s.t.add_N;
}

inline double predict_row(const Design& d, const Fit& f, const Layout& L, const Eigen::VectorXd& th, int i,
                          double* mu_out, const Row* override_row, double* p_out) {
  RowState s;
  predict_row_begin(d, f, L, th, i, override_row, s);
  if (s.done) return s.value;
  for (int k = 0; k < s.iters; ++k) predict_row_step(s);
  return predict_row_end(s, mu_out, p_out);
}

// Two rows' predictions, each bit for bit predict_row's (no override, no mu
// or pressure out), their map iterations interleaved: each iteration is a
// chain of a division and an exp, so one row's waits while the other's runs.
inline void predict_rows2(const Design& d, const Fit& f, const Layout& L, const Eigen::VectorXd& th, int i1, int i2,
                          double& v1, double& v2) {
  RowState a, b;
  predict_row_begin(d, f, L, th, i1, nullptr, a);
  predict_row_begin(d, f, L, th, i2, nullptr, b);
  const int na = a.done ? 0 : a.iters, nb = b.done ? 0 : b.iters;
  for (int k = 0; k < na || k < nb; ++k) {
    if (k < na) predict_row_step(a);
    if (k < nb) predict_row_step(b);
  }
  v1 = predict_row_end(a, nullptr, nullptr), v2 = predict_row_end(b, nullptr, nullptr);
}

/// The columns of th that predict_row(d, f, L, th, i, ...) may read for row i
/// (a superset; least_squares.hpp checks it), appended to out: the row's cell's
/// mu_RD and mu_TD, and what each effect's rule may read (rule_reads).
inline void row_reads(const Design& d, const Fit& f, const Layout& L, int i, std::vector<int>& out) {
  const Row& r = d.rows[i];
  static const Eigen::VectorXd none;  // EffectArgs::th is not read by rule_reads
  if (!r.rotating) {
    if (L.mu_rd[r.cell] >= 0) out.push_back(L.mu_rd[r.cell]);
    if (L.mu_td[r.cell] >= 0) out.push_back(L.mu_td[r.cell]);
  } else if (!f.has_force) {
    return;
  }
  for (size_t k = 0; k < f.spec.effects.size(); ++k) {
    const Effect& e = f.spec.effects[k];
    if (r.rotating && e.kind != EffectKind::force_offset) continue;
    const EffectArgs a{d, f, r, i, k, e, none.data()};
    const size_t at = out.size();
    visit_rule(e.kind, [&](auto rule) { rule_reads<decltype(rule)>(a, out); });
    for (size_t j = at; j < out.size(); ++j) out[j] += L.eff_start[k];
  }
}

}  // namespace detail

}  // namespace drawbend::loop
