// The loop's force model fitted to the rows: the bending line per pin, the
// friction parameters by Levenberg-Marquardt with standard errors, and the
// joint fit of both (for F tests).  Design: design.cpp; prediction:
// predict_row.hpp; the effects: effect_rules.hpp.
#include <algorithm>
#include <cmath>

#include "analysis/rope.hpp"
#include "core/csv.hpp"
#include "loop/least_squares.hpp"
#include "loop/predict_row.hpp"

namespace drawbend::loop {

using detail::Layout;
using detail::layout;
using detail::predict_row;

bool ModelSpec::has(EffectKind k) const {
  for (const auto& e : effects)
    if (e.kind == k) return true;
  return false;
}

std::string ModelSpec::describe() const {
  std::string s = bending_linear ? "base (linear bending)" : "base (constant bending)";
  for (const auto& e : effects) s += " + " + effect_name(e.kind) + (e.variable.empty() ? "" : "(" + e.variable + ")");
  return s;
}

namespace {

// Per-pin least-squares bending line on the training rotating rows.  Not
// analysis::fit_line: that one takes the means as (sum x)/n where this sums
// x/n (other last bits), and the standard errors here need sxx and the means.
void fit_bending(const Design& d, const std::vector<int>& train, bool linear, Fit& f) {
  const size_t np = d.pins.size();
  f.b0.assign(np, std::nan(""));
  f.b1.assign(np, 0.0);
  for (size_t p = 0; p < np; ++p) {
    std::vector<double> x, y;
    for (int i : train)
      if (d.rows[i].rotating && d.rows[i].pin == static_cast<int>(p)) {
        x.push_back(d.rows[i].fback);
        y.push_back(d.rows[i].y - d.rows[i].fback);
      }
    if (x.empty()) {
      f.b0[p] = p < d.bend_fallback.size() ? d.bend_fallback[p] : std::nan("");
      continue;
    }
    const double n = x.size();
    double mx = 0, my = 0;
    for (size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
    double sxx = 0, sxy = 0;
    for (size_t k = 0; k < x.size(); ++k) sxx += (x[k] - mx) * (x[k] - mx), sxy += (x[k] - mx) * (y[k] - my);
    const bool line = linear && x.size() >= 3 && sxx > 1e-9;
    const double b1 = line ? sxy / sxx : 0.0, b0 = my - b1 * mx;
    double rss = 0;
    for (size_t k = 0; k < x.size(); ++k) rss += std::pow(y[k] - b0 - b1 * x[k], 2);
    const double dof = n - (line ? 2 : 1);
    const double s2 = dof > 0 ? rss / dof : 0;
    f.b0[p] = b0;
    f.b1[p] = b1;
    const std::string pin = fmt(d.pins[p]) + " mm";
    if (line) {
      f.params.push_back({"bending b1 " + pin, b1, std::sqrt(s2 / sxx), "-"});
      f.params.push_back({"bending b0 " + pin, b0, std::sqrt(s2 * (1 / n + mx * mx / sxx)), "N"});
    } else {
      f.params.push_back({"bending F_B " + pin, b0, std::sqrt(s2 / n), "N"});
    }
  }
}

}  // namespace

Fit fit_model(const Design& d, const ModelSpec& spec, const std::vector<int>& train_in) {
  std::vector<int> train = train_in;
  if (train.empty())
    for (size_t i = 0; i < d.rows.size(); ++i) train.push_back(static_cast<int>(i));
  Fit f;
  f.spec = spec;
  fit_bending(d, train, spec.bending_linear || spec.has(EffectKind::bending_tension), f);
  const Layout L = layout(d, spec);
  f.drift_z.assign(spec.effects.size(), {});
  f.level.assign(spec.effects.size(), {});
  f.level_names.assign(spec.effects.size(), {});
  for (size_t k = 0; k < spec.effects.size(); ++k) {
    const EffectKind kk = spec.effects[k].kind;
    if (kk == EffectKind::drift || kk == EffectKind::generic_linear || kk == EffectKind::generic_saturating)
      f.drift_z[k] = d.zscore(spec.effects[k].variable);
    if (kk == EffectKind::categorical) f.level[k] = d.levels(spec.effects[k].variable, &f.level_names[k]);
  }
  std::vector<int> rows;
  for (int i : train)
    if (!d.rows[i].rotating && !std::isnan(f.b0[d.rows[i].pin])) rows.push_back(i);
  // Initial mu per cell and direction from Eq. (5.1) row by row.
  Eigen::VectorXd th = Eigen::VectorXd::Zero(L.n);
  std::vector<double> sum(L.n, 0.0), cnt(L.n, 0.0);
  for (int i : rows) {
    const Row& r = d.rows[i];
    const double ffric = r.y - r.fback - (f.b0[r.pin] + f.b1[r.pin] * r.fback);
    const double mu = ffric > 0 ? analysis::mu_from_friction(ffric, r.fback, kWrapRad) : 0.0;
    const int k = (r.phi < M_PI / 4 ? L.mu_rd : L.mu_td)[r.cell];
    sum[k] += mu;
    cnt[k] += 1;
  }
  for (size_t c = 0; c < d.cells.size(); ++c)
    for (int k : {L.mu_rd[c], L.mu_td[c]})
      if (k >= 0) th[k] = cnt[k] > 0 ? sum[k] / cnt[k] : 0.1;
  f.seen.assign(L.n, 1);
  for (size_t c = 0; c < d.cells.size(); ++c)
    for (int k : {L.mu_rd[c], L.mu_td[c]})
      if (k >= 0 && cnt[k] == 0) f.seen[k] = 0;
  const int n = static_cast<int>(rows.size()), p = L.n;
  auto resid = [&](const Eigen::VectorXd& t) {
    Eigen::VectorXd r(n);
    for (int k = 0; k < n; ++k) r[k] = d.rows[rows[k]].y - predict_row(d, f, L, t, rows[k], nullptr);
    return r;
  };
  auto row = [&](const Eigen::VectorXd& t, int k) { return d.rows[rows[k]].y - predict_row(d, f, L, t, rows[k], nullptr); };
  Eigen::MatrixXd J;
  double sse = 0;
  if (n > 0) sse = levenberg_marquardt(th, resid, J, f.converged, row);
  f.theta = th;
  f.rss = sse;
  f.n_fixed = n;
  f.n_friction_params = p;
  // Standard errors: s^2 (J^T J)^-1 at the solution.
  if (n > 0 && p > 0) {
    const double s2 = n > p ? sse / (n - p) : 0.0;
    const Eigen::MatrixXd cov = (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse() * s2;
    const auto names = detail::friction_names(d, spec, L, f.level_names);
    for (int j = 0; j < p; ++j) f.params.push_back({names[j], th[j], std::sqrt(std::max(0.0, cov(j, j))), "-"});
  }
  return f;
}

JointFit fit_joint(const Design& d, const ModelSpec& spec) {
  Fit f = fit_model(d, spec);
  const Layout L = layout(d, spec);
  const bool linear = spec.bending_linear || spec.has(EffectKind::bending_tension);
  std::vector<int> pins;  // pins with a bending line
  for (size_t p = 0; p < d.pins.size(); ++p)
    if (!std::isnan(f.b0[p])) pins.push_back(static_cast<int>(p));
  const int nb = static_cast<int>(pins.size()) * (linear ? 2 : 1);
  Eigen::VectorXd th(nb + L.n);
  for (size_t k = 0; k < pins.size(); ++k) {
    th[k] = f.b0[pins[k]];
    if (linear) th[pins.size() + k] = f.b1[pins[k]];
  }
  th.tail(L.n) = f.theta;
  std::vector<int> rows;
  for (size_t i = 0; i < d.rows.size(); ++i)
    if (!std::isnan(f.b0[d.rows[i].pin])) rows.push_back(static_cast<int>(i));
  auto resid = [&](const Eigen::VectorXd& t) {
    Fit g = f;
    for (size_t k = 0; k < pins.size(); ++k) {
      g.b0[pins[k]] = t[k];
      if (linear) g.b1[pins[k]] = t[pins.size() + k];
    }
    const Eigen::VectorXd tf = t.tail(L.n);
    Eigen::VectorXd r(rows.size());
    for (size_t k = 0; k < rows.size(); ++k) r[k] = d.rows[rows[k]].y - predict_row(d, g, L, tf, rows[k], nullptr);
    return r;
  };
  // One row at t (the sparse Jacobian): the bending lines and friction
  // parameters of the last t kept, not copied per row.
  Fit g = f;
  Eigen::VectorXd last, tf;
  auto row = [&](const Eigen::VectorXd& t, int k) {
    if (last.size() != t.size() || !(last.array() == t.array()).all()) {
      last = t;
      for (size_t q = 0; q < pins.size(); ++q) {
        g.b0[pins[q]] = t[q];
        if (linear) g.b1[pins[q]] = t[pins.size() + q];
      }
      tf = t.tail(L.n);
    }
    return d.rows[rows[k]].y - predict_row(d, g, L, tf, rows[k], nullptr);
  };
  Eigen::MatrixXd J;
  bool conv = false;
  JointFit j;
  j.rss = levenberg_marquardt(th, resid, J, conv, row);
  j.n = static_cast<int>(rows.size());
  j.p = static_cast<int>(th.size());
  return j;
}

}  // namespace drawbend::loop
