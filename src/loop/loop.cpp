// The loop; see loop.hpp.
#include "loop/loop.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <boost/math/distributions/fisher_f.hpp>

#include "core/csv.hpp"

namespace drawbend::loop {

std::string base_model_text(bool bending_linear) {
  return std::string("constant mu per cell (rope formula Eq. 5.1, RD/TD ellipse), bending force ") +
         (bending_linear ? "F_B = b0 + b1 F_back" : "F_B constant (Swift Eq. 2.1 form)") +
         " per pin from the rotating-pin rows";
}

namespace {

// Parameters belonging to the effect just added (names the base does not have).
std::vector<Param> new_params(const Fit& before, const Fit& after) {
  std::vector<Param> out;
  for (const auto& p : after.params) {
    bool old = false;
    for (const auto& q : before.params) old = old || q.name == p.name;
    if (!old) out.push_back(p);
  }
  return out;
}

ModelSpec with_effect(const Design& d, const ModelSpec& s, EffectKind k, const std::string& variable) {
  ModelSpec t = s;
  Effect e{k, variable, 0};
  if (k == EffectKind::bending_tension) t.bending_linear = true;
  if (k == EffectKind::depletion) {  // lambda: grid, then golden section in log(lambda), by the full-data fit
    auto rss = [&](double lam) {
      ModelSpec u = s;
      u.effects.push_back({k, variable, lam});
      return fit_model(d, u).rss;
    };
    const std::vector<double> grid = {10.0, 25.0, 50.0, 100.0, 200.0, 400.0, 800.0};
    size_t bi = 0;
    double best = INFINITY;
    for (size_t i = 0; i < grid.size(); ++i) {
      const double r = rss(grid[i]);
      if (r < best) best = r, bi = i;
    }
    double a = std::log(grid[bi > 0 ? bi - 1 : 0]), b = std::log(grid[std::min(bi + 1, grid.size() - 1)]);
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = rss(std::exp(x1)), f2 = rss(std::exp(x2));
    for (int it = 0; it < 20; ++it) {
      if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = rss(std::exp(x1));
      else a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = rss(std::exp(x2));
    }
    e.lambda_mm = std::exp(0.5 * (a + b));
    if (rss(e.lambda_mm) > best) e.lambda_mm = grid[bi];
  }
  t.effects.push_back(e);
  return t;
}

bool applicable(const Design& d, const ModelSpec& s, EffectKind k) {
  if (s.has(k) && k != EffectKind::drift) return false;
  if (k == EffectKind::bending_tension && s.bending_linear) return false;
  if (k == EffectKind::pin_surface && d.pins.size() < 2) return false;
  if (k == EffectKind::depletion && !d.data->has_sliding) return false;
  return true;
}

// Nested-model F test on the joint fits (bending and friction together).
double f_test(const JointFit& a, const JointFit& b) {
  const int q = b.p - a.p, dof = b.n - b.p;
  if (q <= 0 || dof <= 0 || !(b.rss > 0)) return b.rss < a.rss ? 0.0 : 1.0;
  const double F = ((a.rss - b.rss) / q) / (b.rss / dof);
  if (!(F > 0)) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::fisher_f_distribution<double>(q, dof), F));
}

// A significant candidate without a library effect: confirm it by a generic,
// non-physical linear term mu (1 + beta z(x)) in the joint fit (F test).  NaN
// when the variable has no numeric value per row (categorical, or derived from
// the prediction).
double confirm_generic(const Design& d, const ModelSpec& spec, const JointFit& cur, const std::string& name) {
  ModelSpec t = spec;
  t.effects.push_back({EffectKind::drift, name, 0});
  try {
    return f_test(cur, fit_joint(d, t));
  } catch (const InputError&) {
    return std::nan("");
  }
}

}  // namespace

LoopResult run_loop(const Design& d, const LoopOptions& o) {
  LoopResult res;
  res.base_model = base_model_text(o.bending_linear);
  res.maps = d.maps->label();
  res.folds = make_folds(d, o.cv, o.folds);
  res.cv_mode = res.folds.mode;
  ModelSpec spec;
  spec.bending_linear = o.bending_linear;
  CvResult cur = cross_validate(d, spec, res.folds);
  res.cv.push_back(cur);
  Fit cur_fit = fit_model(d, spec);
  JointFit cur_joint = fit_joint(d, spec);
  std::vector<std::string> used_vars;
  for (int step = 0; step < o.max_steps; ++step) {
    const auto cands = make_candidates(d, cur.pred);
    if (step == 0) res.candidates = cands;
    const auto rank = rank_candidates(cands, cur.resid, res.folds, o.permutations, o.seed + 1000003ULL * step, o.alpha);
    res.rankings.push_back(rank);
    const double thr = o.alpha / std::max<size_t>(1, rank.size());
    bool accepted = false;
    std::vector<std::string> unexplained_now;
    for (const auto& c : rank) {
      if (!c.significant) break;
      std::vector<EffectKind> kinds;
      for (EffectKind k : effects_for(c.name))
        if (applicable(d, spec, k) &&
            !(k == EffectKind::drift && std::find(used_vars.begin(), used_vars.end(), c.name) != used_vars.end()))
          kinds.push_back(k);
      if (kinds.empty()) {
        const double pg = confirm_generic(d, spec, cur_joint, c.name);
        if (std::isnan(pg)) res.screened.push_back(c.name + " (round " + std::to_string(step + 1) + ", p_perm " +
                                                  fmt(c.p_value, 3) + "; categorical or derived: no model test)");
        else if (pg <= thr) unexplained_now.push_back(c.name + " (no library effect; generic linear term F-test p " +
                                                      fmt(pg, 3) + ")");
        continue;
      }
      Step s;
      s.variable = c.name;
      s.p_permutation = c.p_value;
      s.threshold = thr;
      s.rms_before = cur.rms;
      s.max_before = cur.max_abs;
      double best = INFINITY;
      ModelSpec best_spec;
      CvResult best_cv;
      JointFit best_joint;
      for (EffectKind k : kinds) {
        const ModelSpec t = with_effect(d, spec, k, c.name);
        CvResult cv = cross_validate(d, t, res.folds);
        const JointFit jf = fit_joint(d, t);
        const double pf = f_test(cur_joint, jf);
        s.tried.push_back({effect_name(k) + " (F-test p " + fmt(pf, 3) + ")", cv.rms});
        if (pf <= thr && cv.rms < best) best = cv.rms, best_spec = t, best_cv = cv, best_joint = jf,
                                                   s.effect = effect_name(k), s.meaning = effect_meaning(k),
                                                   s.p_value = pf;
      }
      if (!(best < cur.rms)) {
        const double pg = confirm_generic(d, spec, cur_joint, c.name);
        if (!std::isnan(pg) && pg <= thr)
          unexplained_now.push_back(c.name + " (library effects failed; generic linear term F-test p " + fmt(pg, 3) +
                                    ")");
        else
          res.screened.push_back(c.name + " (round " + std::to_string(step + 1) + ", p_perm " + fmt(c.p_value, 3) +
                                 "; not confirmed by a model F test)");
        continue;
      }
      const Fit f = fit_model(d, best_spec);
      s.params = new_params(cur_fit, f);
      s.rms_after = best_cv.rms;
      s.max_after = best_cv.max_abs;
      res.steps.push_back(s);
      used_vars.push_back(c.name);
      spec = best_spec;
      cur = best_cv;
      cur_fit = f;
      cur_joint = best_joint;
      res.cv.push_back(cur);
      accepted = true;
      break;
    }
    for (const auto& u : unexplained_now)
      if (std::find(res.unexplained.begin(), res.unexplained.end(), u) == res.unexplained.end())
        res.unexplained.push_back(u);
    if (accepted) continue;
    bool any_sig = false;
    for (const auto& c : rank) any_sig = any_sig || c.significant;
    if (!any_sig) {
      std::ostringstream m;
      m << "no candidate significant at the Bonferroni threshold p <= " << fmt(thr, 3) << " (alpha " << fmt(o.alpha)
        << " / " << rank.size() << " candidates) with a positive cross-validated error reduction";
      if (!rank.empty()) m << "; smallest p: " << rank.front().name << " p = " << fmt(rank.front().p_value, 3);
      res.stopped_because = m.str();
    } else if (!unexplained_now.empty()) {
      std::string v;
      for (const auto& u : unexplained_now) v += (v.empty() ? "" : "; ") + u;
      res.stopped_because = "significant candidates that no library effect explains: " + v;
    } else {
      res.stopped_because = "candidates passed the permutation screen but none was confirmed by a model F test at p <= " +
                            fmt(thr, 3) + " (see screened)";
    }
    break;
  }
  if (res.stopped_because.empty()) res.stopped_because = "maximum number of steps (" + std::to_string(o.max_steps) + ")";
  res.final_fit = cur_fit;
  return res;
}

namespace {
std::string jstr(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    if (c == '\n') {
      o += "\\n";
      continue;
    }
    o += c;
  }
  return o + "\"";
}
std::string jnum(double v) { return std::isfinite(v) ? fmt(v, 8) : "null"; }
}  // namespace

std::string summary_json(const LoopResult& r) {
  std::ostringstream o;
  o << "{\n  \"base_model\": " << jstr(r.base_model) << ",\n  \"maps\": " << jstr(r.maps)
    << ",\n  \"cv\": " << jstr(r.cv_mode) << ",\n  \"steps\": [";
  for (size_t i = 0; i < r.steps.size(); ++i) {
    const Step& s = r.steps[i];
    o << (i ? "," : "") << "\n    {\"variable\": " << jstr(s.variable) << ", \"effect\": " << jstr(s.effect)
      << ", \"p_value\": " << jnum(s.p_value) << ", \"p_permutation\": " << jnum(s.p_permutation)
      << ", \"threshold\": " << jnum(s.threshold)
      << ", \"rms_before\": " << jnum(s.rms_before) << ", \"rms_after\": " << jnum(s.rms_after)
      << ", \"max_before\": " << jnum(s.max_before) << ", \"max_after\": " << jnum(s.max_after)
      << ", \"parameters\": {";
    for (size_t k = 0; k < s.params.size(); ++k)
      o << (k ? ", " : "") << jstr(s.params[k].name) << ": {\"value\": " << jnum(s.params[k].value)
        << ", \"se\": " << jnum(s.params[k].se) << "}";
    o << "}}";
  }
  o << (r.steps.empty() ? "" : "\n  ") << "],\n  \"unexplained\": [";
  for (size_t i = 0; i < r.unexplained.size(); ++i) o << (i ? ", " : "") << jstr(r.unexplained[i]);
  o << "],\n  \"screened_not_confirmed\": [";
  for (size_t i = 0; i < r.screened.size(); ++i) o << (i ? ", " : "") << jstr(r.screened[i]);
  o << "],\n  \"stopped_because\": " << jstr(r.stopped_because) << "\n}\n";
  return o.str();
}

}  // namespace drawbend::loop
