// The loop; see loop.hpp.
#include "loop/loop.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
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

bool applicable(const Design& d, const ModelSpec& s, EffectKind k, const std::string& var) {
  for (const auto& e : s.effects)
    if (e.kind == k && (e.variable == var || (k != EffectKind::drift && k != EffectKind::generic_linear &&
                                               k != EffectKind::generic_saturating && k != EffectKind::categorical)))
      return false;
  if (k == EffectKind::bending_tension && s.bending_linear) return false;
  if (k == EffectKind::pin_surface && d.pins.size() < 2) return false;
  if (k == EffectKind::depletion && !d.data->has_sliding) return false;
  if ((k == EffectKind::direction_harmonic || k == EffectKind::direction_fourier ||
       k == EffectKind::direction_level) && d.direction_is_level)
    return false;
  if (k == EffectKind::direction_level && d.n_dir_params < 1) return false;
  if (k == EffectKind::direction_fourier && d.n_dir_params < 2) return false;
  if (k == EffectKind::generic_linear || k == EffectKind::generic_saturating || k == EffectKind::drift) {
    try {
      d.zscore(var);
    } catch (const InputError&) {
      return false;
    }
  }
  if (k == EffectKind::categorical && d.data->extra_index(var) < 0) return false;
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

// Effects to try for a candidate: the library's, then generic ones for
// variables the library does not know (columns of the data, not the model's
// own inputs or derived quantities).
std::vector<EffectKind> kinds_for(const Design& d, const ModelSpec& spec, const Candidate& c, bool with_generic) {
  std::vector<EffectKind> kinds;
  for (EffectKind k : effects_for(c.name))
    if (applicable(d, spec, k, c.name)) kinds.push_back(k);
  if ((kinds.empty() || with_generic) && c.kind == "column")
    for (EffectKind k : generic_effects(c.categorical))
      if (applicable(d, spec, k, c.name)) kinds.push_back(k);
  return kinds;
}

std::string sign_text(const Step& s, const std::string& var) {
  if (s.params.size() != 1) return "";
  const Param& p = s.params[0];
  const double t = p.se > 0 ? std::abs(p.value) / p.se : 0;
  return std::string("mu ") + (p.value > 0 ? "increases" : "decreases") + " with " + var + " (" + fmt(t, 3) +
         " SE from zero)";
}

// Why noise_ratio = 1.25: under grouped cross-validation even the true model
// predicts a held-out row with its own parameter error, so its held-out RMS is
// sigma sqrt(1 + p_eff/n_train) and more for a held-out back-tension block
// (extrapolation of the bending line); the null synthetic sets of Chapter 7
// (true model = base model) show the ratio a correct model reaches.
void conclude(LoopResult& r, const LoopOptions& o, const std::vector<CandidateResult>& rank) {
  const double rms = r.cv.back().rms;
  std::ostringstream c;
  if (!r.bending.empty() && r.bending.find("NO rotating") != std::string::npos)
    c << "This data set has no rotating-pin rows for some pin(s); the bending force there is assumed (" << r.bending
      << "), so every friction coefficient below depends on that choice. ";
  if (r.steps.empty()) c << "The loop added no effect to the base model. ";
  else {
    c << "The loop added " << r.steps.size() << " effect(s): ";
    for (size_t k = 0; k < r.steps.size(); ++k)
      c << (k ? "; " : "") << r.steps[k].variable << " (" << r.steps[k].effect << ")";
    c << ". ";
  }
  const NoiseFloor& n = r.noise;
  if (!std::isfinite(n.sigma_N)) {
    c << "The replicate noise could not be estimated (no test with 4 or more rows), so whether the remaining "
         "held-out error of " << fmt(rms, 4) << " N is noise is unknown.";
    r.at_noise = false;
  } else if (n.exact) {
    c << "The rows lie exactly on lines within each test (no replicate noise: sampled fits, not measurements), so the "
         "remaining held-out error of " << fmt(rms, 4) << " N is model error, not noise.";
    r.at_noise = false;
  } else {
    r.ratio = rms / n.sigma_N;
    r.at_noise = r.ratio <= o.noise_ratio;
    c << "The remaining held-out error is " << fmt(rms, 4) << " N against a replicate noise of " << fmt(n.sigma_N, 4)
      << " N (ratio " << fmt(r.ratio, 3) << "; at the noise level means <= " << fmt(o.noise_ratio) << "): ";
    c << (r.at_noise ? "the model explains the data to the noise level." : "structure remains unexplained.");
  }
  if (!r.at_noise) {
    for (const auto& k : rank)
      if (k.significant || k.decision == "undecided" || k.decision.rfind("significant", 0) == 0)
        r.remaining.push_back(k.name + " (" + k.decision + ", p " + fmt(k.p_value, 3) +
                              (is_identity(k.name) ? ", between-test sd " + fmt(k.sd_between, 3) + " N"
                                                   : ", CV reduction " + fmt(k.cv_reduction, 3)) + ")");
    if (r.remaining.empty())
      for (size_t k = 0; k < rank.size() && k < 3; ++k)
        r.remaining.push_back(rank[k].name + " (" + rank[k].decision + ", p " + fmt(rank[k].p_value, 3) + ")");
    if (!r.remaining.empty()) {
      c << " Strongest remaining candidates: ";
      for (size_t k = 0; k < r.remaining.size() && k < 4; ++k) c << (k ? "; " : "") << r.remaining[k];
      c << ".";
    }
  }
  r.conclusion = c.str();
}

void progress(const LoopOptions& o, const std::string& msg) {
  if (o.progress) std::cerr << "[loop] " << msg << std::endl;
}

}  // namespace

LoopResult run_loop(const Design& d, const LoopOptions& o) {
  LoopResult res;
  res.base_model = base_model_text(o.bending_linear);
  res.bending = d.bending_label;
  res.maps = d.maps->label();
  res.noise = replicate_noise(d);
  res.folds = make_folds(d, o.cv, o.folds);
  res.cv_mode = res.folds.mode;
  const double sigma = res.noise.exact || !std::isfinite(res.noise.sigma_N) ? 0.0 : res.noise.sigma_N;
  ModelSpec spec;
  spec.bending_linear = o.bending_linear;
  progress(o, "base model: cross-validation (" + std::to_string(d.rows.size()) + " rows)");
  CvResult cur = cross_validate(d, spec, res.folds);
  res.cv.push_back(cur);
  Fit cur_fit = fit_model(d, spec);
  JointFit cur_joint = fit_joint(d, spec);
  std::vector<std::string> used_vars;
  std::vector<CandidateResult> last_rank;
  for (int step = 0; step < o.max_steps; ++step) {
    progress(o, "round " + std::to_string(step + 1) + ": ranking candidates (held-out RMS " + fmt(cur.rms, 4) + " N)");
    const auto cands = make_candidates(d, cur.pred);
    if (step == 0) res.candidates = cands;
    const auto rank = rank_candidates(cands, cur.resid, res.folds, o.permutations, o.seed + 1000003ULL * step, o.alpha);
    res.rankings.push_back(rank);
    last_rank = rank;
    const double thr = o.alpha / std::max<size_t>(1, rank.size());
    bool accepted = false;
    for (const auto& c : rank) {
      if (!c.significant) break;
      if (is_identity(c.name)) continue;
      const Candidate* cand = nullptr;
      for (const auto& k : cands)
        if (k.name == c.name) cand = &k;
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
      for (int pass = 0; pass < 2 && !std::isfinite(best); ++pass) {  // library first, then generic
        std::vector<EffectKind> kinds = kinds_for(d, spec, *cand, pass == 1);
        if (pass == 1) {  // only the generic ones not tried yet
          std::vector<EffectKind> lib = kinds_for(d, spec, *cand, false);
          kinds.erase(std::remove_if(kinds.begin(), kinds.end(),
                                     [&](EffectKind k) { return std::find(lib.begin(), lib.end(), k) != lib.end(); }),
                      kinds.end());
        }
        for (EffectKind k : kinds) {
          progress(o, "  " + c.name + ": trying " + effect_name(k));
          ModelSpec t = with_effect(d, spec, k, c.name);
          if (k == EffectKind::categorical) {
            std::vector<std::string> names;
            d.levels(c.name, &names);
            t.effects.back().n_levels = static_cast<int>(names.size());
          }
          CvResult cv = cross_validate(d, t, res.folds);
          const JointFit jf = fit_joint(d, t);
          const double pf = f_test(cur_joint, jf);
          const double gain = std::sqrt(std::max(0.0, cur.rms * cur.rms - cv.rms * cv.rms));
          const bool big = gain >= o.min_effect * sigma;
          s.tried.push_back({effect_name(k) + " (F-test p " + fmt(pf, 3) + (big ? "" : ", below the minimum effect") +
                                 ")",
                             cv.rms});
          if (pf <= thr && big && cv.rms < best && cv.rms < cur.rms)
            best = cv.rms, best_spec = t, best_cv = cv, best_joint = jf, s.effect = effect_name(k),
            s.meaning = effect_meaning(k), s.p_value = pf;
        }
      }
      if (!std::isfinite(best)) {
        res.screened.push_back(c.name + " (round " + std::to_string(step + 1) + ", p_perm " + fmt(c.p_value, 3) +
                               "; no effect passed the F test, lowered the held-out error and reached the minimum "
                               "effect " + fmt(o.min_effect) + " sigma)");
        continue;
      }
      const Fit f = fit_model(d, best_spec);
      s.params = new_params(cur_fit, f);
      s.rms_after = best_cv.rms;
      s.max_after = best_cv.max_abs;
      if (s.effect.rfind("generic", 0) == 0) s.sign = sign_text(s, c.name);
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
    if (accepted) continue;
    bool any_sig = false;
    for (const auto& c : rank) any_sig = any_sig || (c.significant && !is_identity(c.name));
    std::ostringstream m;
    if (!any_sig) {
      m << "no candidate significant at the Bonferroni threshold p <= " << fmt(thr, 3) << " (alpha " << fmt(o.alpha)
        << " / " << rank.size() << " candidates) with a positive cross-validated error reduction";
      if (!rank.empty()) m << "; smallest p: " << rank.front().name << " p = " << fmt(rank.front().p_value, 3);
    } else {
      m << "significant candidates remain, but no effect for them passed the F test at p <= " << fmt(thr, 3)
        << ", lowered the held-out error and reached the minimum effect (see screened)";
    }
    res.stopped_because = m.str();
    break;
  }
  if (res.stopped_because.empty()) res.stopped_because = "maximum number of steps (" + std::to_string(o.max_steps) + ")";
  res.final_fit = cur_fit;
  conclude(res, o, last_rank);
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
  o << "{\n  \"conclusion\": " << jstr(r.conclusion) << ",\n  \"bending\": " << jstr(r.bending)
    << ",\n  \"noise_N\": " << jnum(r.noise.sigma_N) << ",\n  \"heldout_rms_N\": " << jnum(r.cv.back().rms)
    << ",\n  \"ratio_to_noise\": " << jnum(r.ratio) << ",\n  \"at_noise_level\": " << (r.at_noise ? "true" : "false")
    << ",\n  \"base_model\": " << jstr(r.base_model) << ",\n  \"maps\": " << jstr(r.maps)
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
    o << "}" << (s.sign.empty() ? "" : ", \"sign\": " + jstr(s.sign)) << "}";
  }
  o << (r.steps.empty() ? "" : "\n  ") << "],\n  \"remaining\": [";
  for (size_t i = 0; i < r.remaining.size(); ++i) o << (i ? ", " : "") << jstr(r.remaining[i]);
  o << "],\n  \"screened_not_confirmed\": [";
  for (size_t i = 0; i < r.screened.size(); ++i) o << (i ? ", " : "") << jstr(r.screened[i]);
  o << "],\n  \"stopped_because\": " << jstr(r.stopped_because) << "\n}\n";
  return o.str();
}

}  // namespace drawbend::loop
