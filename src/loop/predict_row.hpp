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

/// Does a fixed-pin row read its cell's mu_RD (mu_TD)?  A cell with one of
/// the two (ir or it < 0) reads it alone; with both, the ellipse: every row
/// off 90 deg reads mu_RD and every row off 0 deg mu_TD (at 0 deg it is mu_RD
/// whatever mu_TD is; cos 90 deg is 6e-17, not 0).
inline bool reads_rd(const Row& r, int it) { return it < 0 || r.cos_phi > 1e-9; }
inline bool reads_td(const Row& r, int ir) { return ir < 0 || r.sin_phi > 1e-9; }

// analysis::wrap_factor(mu, kWrapRad) (rope.hpp) with the last argument and value kept per thread: the rows of one test usually share
// mu (same cell, direction and group levels, no pressure term), and a
// Jacobian's column and a fit's residuals visit them in turn.  exp is a pure
// function, so a repeated mu gives the same bits (+0 and -0 both give 1; a
// NaN never compares equal and is computed).
inline double wrap_exp(double mu) {
  thread_local double last_mu = std::nan(""), last_e = std::nan("");
  if (!(mu == last_mu)) last_mu = mu, last_e = analysis::wrap_factor(mu, kWrapRad);
  return last_e;
}

// Flattened: the effects' rules (visit_rule and each rule's apply) inline in
// it, not a call per effect and row with its arguments through memory.
[[gnu::flatten]] inline double predict_row(const Design& d, const Fit& f, const Layout& L, const Eigen::VectorXd& th,
                                           int i, double* mu_out, const Row* override_row, double* p_out) {
  const Row& r = override_row ? *override_row : d.rows[i];
  const double bend_x = f.bend_extra.empty() ? 0.0 : f.bend_extra[i];  // bending-channel effects
  const double bend = f.b0[r.pin] + f.b1[r.pin] * r.fback + bend_x;
  if (std::isnan(bend)) return std::nan("");
  if (r.rotating) {
    if (!f.has_force) return r.fback + bend;
    Terms t;
    for (size_t k = 0; k < f.spec.effects.size(); ++k)
      if (f.spec.effects[k].kind == EffectKind::force_offset) {
        const Effect& e = f.spec.effects[k];
        visit_rule(e.kind, [&](auto rule) { rule.apply(EffectArgs{d, f, r, i, k, e, th.data() + L.eff_start[k]}, t); });
      }
    return r.fback + bend + t.add_N;
  }
  const int ir = L.mu_rd[r.cell], it = L.mu_td[r.cell];
  double mu0;
  if (ir >= 0 && it >= 0) mu0 = analysis::ellipse_mu(th[ir], th[it], r.cos_phi, r.sin_phi);
  else mu0 = th[ir >= 0 ? ir : it];
  // A row reading a parameter no training row reads is not predictable (NaN:
  // left out of a fit's rows and of the held-out error); a row that does not
  // read it (0 deg for mu_TD, 90 deg for mu_RD) is.
  if (!f.seen.empty() && ((ir >= 0 && !f.seen[ir] && reads_rd(r, it)) || (it >= 0 && !f.seen[it] && reads_td(r, ir))))
    return std::nan("");
  Terms t;
  for (size_t k = 0; k < f.spec.effects.size(); ++k) {
    const Effect& e = f.spec.effects[k];
    const EffectArgs a{d, f, r, i, k, e, th.data() + L.eff_start[k]};
    visit_rule(e.kind, [&](auto rule) { rule.apply(a, t); });
  }
  double ff = 0, mu = 0;
  const int iters = t.a1 != 0 ? 4 : 1;
  const double bend_ref = f.b0[r.pin] + f.b1[r.pin] * r.fref + bend_x;
  for (int k = 0; k < iters; ++k) {  // the map follows the mean tension (Eq. 2.2), friction included
    const double p = analysis::pressure_at_tension(r.pw_ref, r.fback, bend, ff, r.fref, bend_ref);  // map_pressure
    // Without a pressure term (a1 = +-0) and with p finite, a1 p is +-0 and
    // mu0 + a1 p is mu0 itself unless mu0 is zero: the same mu without waiting
    // on p's division (p still decides the other cases, as written).
    if (iters == 1 && std::isfinite(p) && mu0 != 0) mu = mu0 * t.factor * t.pinf;
    else mu = (mu0 + t.a1 * p) * t.factor * t.pinf;
    ff = analysis::friction_from_wrap(wrap_exp(mu), r.fback);  // friction_from_mu, exp memoised
  }
  if (mu_out) *mu_out = mu;
  if (p_out) *p_out = analysis::pressure_at_tension(r.pw_ref, r.fback, bend, ff, r.fref, bend_ref);
  return r.fback + bend + ff + t.add_N;
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
