// The loop; see loop.hpp.
#include "loop/loop.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "core/csv.hpp"
#include "loop/aliases.hpp"
#include "loop/conclusion.hpp"
#include "loop/fit_memo.hpp"
#include "loop/forms.hpp"
#include "loop/pair_first.hpp"
#include "loop/response_columns.hpp"

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

std::string sign_text(const Step& s, const std::string& var) {
  if (s.params.size() != 1) return "";
  const Param& p = s.params[0];
  const double t = p.se > 0 ? std::abs(p.value) / p.se : 0;
  for (const Effect& e : s.added)  // a bump or step (form_bumps.cpp): higher or lower near or above it, not a trend
    if ((e.bump_width > 0 || e.step) && e.kind == EffectKind::generic_smooth)
      return std::string("mu ") + (p.value > 0 ? "higher" : "lower") + (e.step ? " above " : " near ") + var + " = " +
             fmt(e.step ? e.step_at : e.bump_centre, 6) + " (" + fmt(t, 3) + " SE from zero)";
  return std::string("mu ") + (p.value > 0 ? "increases" : "decreases") + " with " + var + " (" + fmt(t, 3) +
         " SE from zero)";
}

void progress(const LoopOptions& o, const std::string& msg) {
  if (o.progress) std::cerr << "[loop] " << msg << std::endl;
}

// What the screen knows of the current model: the model's inputs as groups,
// and dF/dmu per fixed-pin row = Theta (F_back + F_fric) = Theta (pred - F_back - F_B) + Theta F_back.
ScreenContext screen_context(const Design& d, const Fit& fit, const std::vector<double>& pred) {
  ScreenContext c;
  for (const std::string by : {"pin", "speed_mm_s", "direction_deg", "lubricant"}) {
    int n = 0;
    std::vector<int> g = d.groups(by, &n);
    if (n >= 2) c.modifiers.push_back({by, std::move(g)});
  }
  c.mu_weight.assign(d.rows.size(), 0.0);
  for (size_t i = 0; i < d.rows.size(); ++i) {
    const Row& r = d.rows[i];
    if (r.rotating || !std::isfinite(pred[i])) continue;
    const double bend = fit.b0[r.pin] + fit.b1[r.pin] * r.fback + (fit.bend_extra.empty() ? 0.0 : fit.bend_extra[i]);
    const double w = kWrapRad * (pred[i] - bend);
    c.mu_weight[i] = std::isfinite(w) ? w : 0.0;
  }
  return c;
}

// Is the model input (or a name of it: the pin as diameter or 1/R) significant in this round?
bool input_significant(const std::vector<CandidateResult>& rank, const std::string& input) {
  for (const auto& c : rank) {
    const bool same = input == "pin" ? (c.name == "pin" || c.name == "pin_diameter_mm" || c.name == "inv_R_per_mm")
                                     : c.name == input;
    if (same && c.significant) return true;
  }
  return false;
}

// The model without step s's effects.
ModelSpec without(const ModelSpec& spec, const Step& s, bool bending_linear) {
  ModelSpec t = spec;
  t.effects.clear();
  for (const auto& e : spec.effects) {
    bool mine = false;
    for (const auto& m : s.added) mine = mine || (m.kind == e.kind && m.variable == e.variable && m.by == e.by && m.cell == e.cell && m.cell_offset == e.cell_offset &&
                            m.bend_scaled == e.bend_scaled && m.times == e.times && m.level_basis == e.level_basis &&
                            m.bump_centre == e.bump_centre && m.bump_width == e.bump_width && m.step == e.step &&
                            m.step_at == e.step_at);
    if (!mine) t.effects.push_back(e);
  }
  for (const auto& m : s.added)
    if (m.kind == EffectKind::bending_tension) t.bending_linear = bending_linear;
  return t;
}


// The strongest few significant candidates of a round, each given its best
// form: the one whose form predicts held-out data best so far, and the kept
// forms' held-out results of the undeclared columns.
struct RoundChoice {
  Step best_step;
  FormTrial best_form;
  CvResult best_cv;  // the best passed form's held-out result (best_step's variable)
  int best_q = 0;    // that form's parameters, searched ones counted (FormTrial::q)
  bool found = false;
  std::vector<std::pair<std::string, CvResult>> kept;  // column -> its kept form's held-out result
};

// A candidate given every form: its step, the trials, the kept form (-1: none
// passed) and the best passed form (-1: none).
struct Considered {
  Step s;
  std::vector<FormTrial> trials;
  int keep = -1, best = -1;
};

// The search's state: the current model, its fits and the steps found so far.
struct LoopSearch {
  LoopSearch(const Design& d, const LoopOptions& o, LoopResult& res, double sigma)
      : d(d), o(o), res(res), sigma_data(sigma), sigma(sigma), memo(d, res.folds) {
    spec.bending_linear = o.bending_linear;
    base_cv = memo.cv(spec);
    cur = base_cv;
    cur_fit = memo.fit(spec);
    cur_joint = memo.joint(spec);
  }

  const Design& d;
  const LoopOptions& o;
  LoopResult& res;
  const double sigma_data;  // the data's replicate noise (0: none usable)
  double sigma;             // the floor: sigma_data, or with o.model_noise the smaller of it and refloor()'s
  FitMemo memo;
  TrialCache trials_done;  // the forms' fits, by their arithmetic (forms.hpp)
  ModelSpec spec;
  CvResult base_cv, cur;
  Fit cur_fit;
  JointFit cur_joint;
  std::vector<CandidateResult> last_rank;
  std::vector<Step> steps;
  std::vector<ResponseColumn> excluded;  // columns computed from the measured forces: not screened
  int round = 0, backfits = 0;
  bool far_mode = false;  // forms given by the far rule (LoopOptions::far_max_params)

  void forward();
  bool forward_round();
  std::vector<CandidateResult> screen(const std::vector<Candidate>& cands, const std::vector<Candidate>& pairs);
  std::vector<std::string> give_forms(const std::vector<CandidateResult>& rank, const std::vector<Candidate>& cands,
                                      double thr, RoundChoice& ch);
  Considered evaluate(const CandidateResult& c, const Candidate& cand, double thr);
  void consider(const CandidateResult& c, const Candidate& cand, bool screened, double thr, RoundChoice& ch);
  void pair_first(const std::vector<CandidateResult>& rank, const std::vector<Candidate>& cands, double thr,
                  RoundChoice& ch);
  std::vector<std::string> give_forms_by_gain(const std::vector<CandidateResult>& rank,
                                             const std::vector<Candidate>& cands, double thr, RoundChoice& ch);
  void give_aliases(const std::vector<CandidateResult>& rank, const std::vector<Candidate>& cands,
                    const std::vector<std::string>& given, double thr, RoundChoice& ch);
  std::string no_step_reason(const std::vector<CandidateResult>& rank, double thr) const;
  void add_step(RoundChoice& ch);
  void refloor();
  bool backfit();
  void order_steps();
  void cv_by_step();
};

// Forward: re-screen the residual of the current model after every step.
void LoopSearch::forward() {
  bool stopped = false;
  while (static_cast<int>(steps.size()) < o.max_steps) {
    if (!forward_round()) {
      stopped = true;
      break;
    }
  }
  if (!stopped) res.stopped_because = "maximum number of steps (" + std::to_string(o.max_steps) + ")";
}

// One round: screen, give the strongest candidates (and the chosen column's
// aliases) their forms, add the best; false (and why) when none is added.
bool LoopSearch::forward_round() {
  progress(o, "round " + std::to_string(round + 1) + ": ranking candidates (held-out RMS " + fmt(cur.rms, 4) + " N)");
  auto cands = make_candidates(d, cur.pred);
  // Columns computed from the measured forces are not screened (response_columns.hpp).
  for (const auto& rc : excluded)
    cands.erase(std::remove_if(cands.begin(), cands.end(), [&](const Candidate& c) { return c.name == rc.name; }),
                cands.end());
  if (round == 0) res.candidates = cands;
  // Pairs of numeric columns, screened as families (screen_pairs.cpp); the
  // forms find a pair among the candidates.
  const std::vector<Candidate> pairs = o.pair_probes ? pair_candidates(cands) : std::vector<Candidate>{};
  const auto rank = screen(cands, pairs);
  cands.insert(cands.end(), pairs.begin(), pairs.end());
  const double thr = o.alpha / std::max<size_t>(1, tests_in(rank));  // as rank_candidates
  // The strongest few significant candidates are each given their best form;
  // the one whose form predicts held-out data best is added (the rank order
  // of the screen does not decide between them).
  RoundChoice ch;
  const std::vector<std::string> given = give_forms(rank, cands, thr, ch);
  pair_first(rank, cands, thr, ch);
  if (ch.found && ch.best_step.cls == "undeclared variable") give_aliases(rank, cands, given, thr, ch);
  // Far from the noise with no step: the strongest candidates by held-out gain.
  if (!ch.found && o.far_ratio > 0 && sigma > 0 && cur.rms > o.far_ratio * sigma) {
    far_mode = true;
    const std::vector<std::string> far = give_forms_by_gain(rank, cands, thr, ch);
    if (ch.found && ch.best_step.cls == "undeclared variable") give_aliases(rank, cands, far, thr, ch);
    far_mode = false;
    const double excess = cur.rms * cur.rms - sigma * sigma,
                 gain = ch.found ? cur.rms * cur.rms - ch.best_form.cv.rms * ch.best_form.cv.rms : 0.0;
    if (ch.found && gain >= o.far_share * excess)
      ch.best_step.far_note = "no candidate passed the permutation screen and its forms, while the held-out RMS " +
                              fmt(cur.rms, 4) + " N was " + fmt(cur.rms / sigma, 3) + " x the replicate noise (above " +
                              fmt(o.far_ratio) + " x): the " + std::to_string(far.size()) + (far.size() == 1 ? " candidate" : " candidates") + " "
                              "with the largest held-out gain (after the first, those with at least " + fmt(100 * o.far_gain_share) +
                              " % of its gain) were given their forms; this one's passed the F test, "
                              "lowered the held-out error, reached the minimum effect, has at most " + std::to_string(o.far_max_params) +
                              " parameters, and took " +
                              fmt(100 * gain / excess, 3) + " % of the excess MSE over the noise (at least " +
                              fmt(100 * o.far_share) + " % asked)";
    else if (ch.found) {
      progress(o, "far-from-noise rule: " + ch.best_step.variable + " takes " + fmt(100 * gain / excess, 3) +
                      " % of the excess over the noise, below " + fmt(100 * o.far_share) + " %: no step");
      ch = RoundChoice{};
    }
  }
  ++round;
  if (!ch.found) {
    res.stopped_because = no_step_reason(rank, thr);
    return false;
  }
  add_step(ch);
  return true;
}

// The screen of the current residual (rank_candidates), kept in the result.
std::vector<CandidateResult> LoopSearch::screen(const std::vector<Candidate>& cands,
                                                const std::vector<Candidate>& pairs) {
  ScreenContext ctx = screen_context(d, cur_fit, cur.pred);
  ctx.one_cell = o.cell_probes;
  ctx.pooled_inputs = o.pooled_inputs;
  ctx.threads = o.threads;
  const auto rank =
      rank_candidates(cands, cur.resid, res.folds, o.permutations, o.seed + 1000003ULL * round, o.alpha, &ctx, &pairs);
  res.rankings.push_back(rank);
  last_rank = rank;
  return rank;
}

// The significant candidates, strongest first, up to o.contenders, given their
// forms; the names given.
std::vector<std::string> LoopSearch::give_forms(const std::vector<CandidateResult>& rank,
                                                const std::vector<Candidate>& cands, double thr, RoundChoice& ch) {
  std::vector<std::string> given, tests;  // candidates given their forms this round; their tests (one per contender)
  for (const auto& c : rank) {
    if (!c.significant) break;
    const bool counted = std::find(tests.begin(), tests.end(), test_of(c)) != tests.end();
    if (is_identity(c.name) || (!counted && static_cast<int>(tests.size()) >= o.contenders)) continue;
    const Candidate* cand = nullptr;
    for (const auto& k : cands)
      if (k.name == c.name) cand = &k;
    if (!cand) throw std::logic_error("loop: ranked column '" + c.name + "' is not a candidate");
    // A column that is a function of a model input is left to that input
    // when the input is significant itself: the data cannot tell them apart,
    // and the input needs no undeclared variable.
    if (!cand->confounded_with.empty() && input_significant(rank, cand->confounded_with)) continue;
    if (!counted) tests.push_back(test_of(c));
    given.push_back(c.name);
    consider(c, *cand, true, thr, ch);
  }
  return given;
}

// The far-from-noise rule (LoopOptions::far_ratio): the candidates with the
// largest positive held-out gain, up to o.far_contenders (after the first, only
// those with at least o.far_gain_share of its gain), significant or not
// (identities and pair families excluded, a column left to a significant model
// input it is a function of, as in give_forms), given their forms; the names given.
std::vector<std::string> LoopSearch::give_forms_by_gain(const std::vector<CandidateResult>& rank,
                                                        const std::vector<Candidate>& cands, double thr,
                                                        RoundChoice& ch) {
  std::vector<const CandidateResult*> by_gain;
  for (const auto& c : rank)
    if (!is_identity(c.name) && c.kind != "pair" && c.cv_reduction > 0) by_gain.push_back(&c);
  std::stable_sort(by_gain.begin(), by_gain.end(),
                   [](const CandidateResult* a, const CandidateResult* b) { return a->cv_reduction > b->cv_reduction; });
  std::vector<std::string> given, tests;  // as in give_forms
  double first_gain = 0;  // the gain of the first candidate given its forms
  for (const CandidateResult* c : by_gain) {
    const bool counted = std::find(tests.begin(), tests.end(), test_of(*c)) != tests.end();
    if (!counted && static_cast<int>(tests.size()) >= o.far_contenders) continue;
    if (!given.empty() && c->cv_reduction < o.far_gain_share * first_gain) break;
    const Candidate* cand = nullptr;
    for (const auto& k : cands)
      if (k.name == c->name) cand = &k;
    if (!cand) continue;
    if (!cand->confounded_with.empty() && input_significant(rank, cand->confounded_with)) continue;
    if (given.empty()) first_gain = c->cv_reduction;
    if (!counted) tests.push_back(test_of(*c));
    given.push_back(c->name);
    consider(*c, *cand, false, thr, ch);
  }
  return given;
}

// Candidate c given every form.
Considered LoopSearch::evaluate(const CandidateResult& c, const Candidate& cand, double thr) {
  const auto prog = [&](const std::string& m) { progress(o, m); };
  Considered r;
  r.trials = try_forms(d, res.folds, spec, cand, cur, cur_joint, thr, o.min_effect * sigma, prog, c.cell_by,
                       c.cell_group, &trials_done, c.probe_input, far_mode ? o.far_max_params : -1,
                       o.product_forms, c.cv_probe_input);
  // The far rule's steps: simple forms only (LoopOptions::far_max_params).
  // try_forms skips a plan before fitting by the friction parameters it adds;
  // the joint fit's own parameters (a bending channel's) are known only after
  // it, in q: so the cap is applied again here.
  if (far_mode)
    for (auto& t : r.trials)
      if (t.q > o.far_max_params) t.passed = false;
  r.keep = choose_form(r.trials, res.folds);
  if (r.keep >= 0) complete_trials(d, r.trials, cur_joint, &trials_done);  // all listed with their F tests
  Step& s = r.s;
  s.variable = c.name;
  s.p_permutation = c.p_value;
  s.threshold = thr;
  s.probe = c.probe;
  s.cls = (cand.kind == "column" || cand.kind == "pair") && cand.confounded_with.empty() ? "undeclared variable"
                                                                                          : "base model";
  if (!cand.confounded_with.empty()) s.meaning_note = "confounded with " + cand.confounded_with;
  if (cand.kind == "pair") {
    s.columns = cand.pair;
    s.meaning_note = "two columns together: the product of the centred " + cand.pair[0] + " and " + cand.pair[1];
  }
  for (size_t k = 0; k < r.trials.size(); ++k) {
    const FormTrial& t = r.trials[k];
    s.tried.push_back({t.name + " (F-test p " + fmt(t.p_value, 3) + ", " + std::to_string(t.q) + " parameters" +
                           (t.extra_searched > 0 ? " (" + std::to_string(t.extra_searched) + " of them searched)" : "") +
                           (t.passed ? "" : ", failed a gate") + ")",
                       t.cv.rms});
    if (t.passed && (r.best < 0 || t.cv.rms < r.trials[r.best].cv.rms)) r.best = static_cast<int>(k);
  }
  return r;
}

// Candidate c given every form; the best kept form over the candidates wins.
void LoopSearch::consider(const CandidateResult& c, const Candidate& cand, bool screened, double thr,
                          RoundChoice& ch) {
  Considered r = evaluate(c, cand, thr);
  if (r.keep < 0) {
    if (screened)
      res.screened.push_back(c.name + " (round " + std::to_string(round + 1) + ", p_perm " + fmt(c.p_value, 3) +
                             ", probe " + c.probe + "; no form passed the F test, lowered the held-out error and "
                             "reached the minimum effect " + fmt(o.min_effect) + " sigma)");
    return;
  }
  if (r.s.cls == "undeclared variable") ch.kept.push_back({c.name, r.trials[r.keep].cv});
  // Candidates compete by their best form's held-out error, not by the kept
  // (simplest within one standard error) form's: the one-SE rule chooses a
  // form within a variable, and must not hand the step to another variable
  // whose few-parameter form is only nearly as good (the same model: fewer parameters, takes_the_step).
  const FormTrial& b = r.trials[r.best];
  if (!ch.found || takes_the_step(b, ch.best_cv, ch.best_q)) {
    ch.best_form = r.trials[r.keep];
    ch.best_cv = b.cv;
    ch.best_q = b.q;
    ch.best_step = std::move(r.s);
    ch.found = true;
  }
}

// A pair step must beat its own columns (pair_first.hpp): each column of the
// round's best pair is given the single-column forms, and a column whose best
// form is within one standard error of the pair's takes the step.  The
// decision, either way, is noted on the step.
void LoopSearch::pair_first(const std::vector<CandidateResult>& rank, const std::vector<Candidate>& cands, double thr,
                            RoundChoice& ch) {
  if (!ch.found || ch.best_step.columns.size() != 2 || !ch.best_step.pair_note.empty()) return;
  std::vector<PairMember> members;
  std::vector<Considered> tried;
  for (const auto& name : ch.best_step.columns) {
    CandidateResult cr;
    cr.name = name;
    for (const auto& k : rank)
      if (k.name == name) cr = k;
    for (const auto& k : cands)
      if (k.name == name) {
        progress(o, "pair " + ch.best_step.variable + ": its column " + name + " alone");
        tried.push_back(evaluate(cr, k, thr));
        PairMember m;
        m.name = name;
        m.significant = cr.significant;
        m.passed = tried.back().best >= 0;
        if (m.passed) m.best = tried.back().trials[tried.back().best].cv;
        members.push_back(std::move(m));
        break;
      }
  }
  const PairVerdict v = pair_or_member(ch.best_step.variable, ch.best_cv, members, res.folds);
  if (v.member < 0) {
    ch.best_step.pair_note = v.note;
    return;
  }
  Considered& r = tried[v.member];
  r.s.pair_note = v.note;
  bool listed = false;
  for (const auto& [name, cv] : ch.kept) listed = listed || name == r.s.variable;
  if (!listed && r.s.cls == "undeclared variable") ch.kept.push_back({r.s.variable, r.trials[r.keep].cv});
  ch.best_form = r.trials[r.keep];
  ch.best_cv = r.trials[r.best].cv;
  ch.best_q = r.trials[r.best].q;
  ch.best_step = std::move(r.s);
}

// Collinear naming (aliases.hpp): the columns explaining the same
// structure as the chosen column's effect are given their forms too.
void LoopSearch::give_aliases(const std::vector<CandidateResult>& rank, const std::vector<Candidate>& cands,
                              const std::vector<std::string>& given, double thr, RoundChoice& ch) {
  std::vector<double> e(d.rows.size());
  for (size_t i = 0; i < e.size(); ++i) e[i] = ch.best_form.cv.pred[i] - cur.pred[i];
  std::vector<std::string> skip = given;
  for (const auto& m : spec.effects) skip.push_back(m.variable);
  for (const auto& a : alias_columns(cands, e, res.folds.block, ch.best_step.variable, skip)) {
    progress(o, "alias of " + ch.best_step.variable + ": " + a.name + " (explained share " + fmt(a.share, 3) + ")");
    CandidateResult cr;
    cr.name = a.name;
    for (const auto& k : rank)
      if (k.name == a.name) cr = k;
    for (const auto& k : cands)
      if (k.name == a.name) consider(cr, k, false, thr, ch);
  }
  pair_first(rank, cands, thr, ch);  // an alias that is a pair must beat its own columns too
  // Columns the held-out data cannot tell from the winner's, or that make the same effect (aliases.hpp).
  name_alikes(ch.best_step, ch.kept, ch.best_form.cv, res.folds, sigma > 0 ? o.min_effect * sigma : NAN);
}

// Why the round added no step.
std::string LoopSearch::no_step_reason(const std::vector<CandidateResult>& rank, double thr) const {
  bool any_sig = false;
  for (const auto& c : rank) any_sig = any_sig || (c.significant && !is_identity(c.name));
  std::ostringstream m;
  if (!any_sig) {
    m << "no candidate significant at the Bonferroni threshold p <= " << fmt(thr, 3) << " (alpha "
      << fmt(o.alpha) << " / " << tests_in(rank) << " tests) with a positive cross-validated error reduction";
    if (!rank.empty()) m << "; smallest p: " << rank.front().name << " p = " << fmt(rank.front().p_value, 3);
  } else {
    m << "significant candidates remain, but no effect for them passed the F test at p <= " << fmt(thr, 3)
      << ", lowered the held-out error and reached the minimum effect (see screened)";
  }
  return m.str();
}

// The round's winner becomes the current model.
void LoopSearch::add_step(RoundChoice& ch) {
  const FormTrial& best_form = ch.best_form;
  Step& s = ch.best_step;
  s.effect = best_form.name;
  s.meaning = best_form.meaning;
  s.channel = best_form.channel;
  s.p_value = best_form.p_value;
  s.rms_before = cur.rms;
  s.max_before = cur.max_abs;
  for (size_t k = spec.effects.size(); k < best_form.spec.effects.size(); ++k) s.added.push_back(best_form.spec.effects[k]);
  if (best_form.spec.bending_linear != spec.bending_linear) { Effect bt; bt.kind = EffectKind::bending_tension; s.added.push_back(bt); }
  spec = best_form.spec;
  cur = best_form.cv;
  cur_joint = best_form.joint;
  memo.remember(spec, cur, cur_joint);
  cur_fit = memo.fit(spec);
  s.rms_after = cur.rms;
  s.max_after = cur.max_abs;
  steps.push_back(s);
  refloor();
}

// The model floor (LoopOptions::model_noise): the replicate noise measured
// again on the current model's held-out residual, the floor the smaller of
// it and the data's own.  Off, or without a usable data floor: unchanged.
void LoopSearch::refloor() {
  if (!o.model_noise || !(sigma_data > 0)) return;
  const NoiseFloor m = replicate_noise(d, &cur.resid);
  sigma = std::isfinite(m.sigma_N) && m.sigma_N > 0 ? std::min(sigma_data, m.sigma_N) : sigma_data;
  progress(o, "noise floor " + fmt(sigma, 4) + " N (the data's " + fmt(sigma_data, 4) + " N)");
}

// Backfitting: an effect that is no longer needed given the others (its F
// test given all the others above the threshold, or the held-out error no
// worse without it) is removed, the weakest first, and the forward search
// resumes; so an early nuisance term can give way to a later variable.
// A removal that raises the held-out error by more than one standard error
// is never made.  False: nothing removed.
bool LoopSearch::backfit() {
  const double thr = o.alpha / std::max<size_t>(1, res.candidates.size());
  int drop = -1;
  double worst = -1;
  for (size_t j = 0; j < steps.size(); ++j) {
    const ModelSpec t = without(spec, steps[j], o.bending_linear);
    const double p = f_test(memo.joint(t), cur_joint, searched_params(steps[j].added));
    const CvResult cv = memo.cv(t);
    // Never a removal that costs held-out error beyond one standard error of
    // the difference: the F test is on the joint fit, the held-out error on
    // the fits the model predicts with (a force channel's bending lines are
    // refitted once, not jointly), and a redundant alias can carry the fit.
    const bool costs = cv.rms * cv.rms - cur.rms * cur.rms > mse_diff_se(cv, cur, res.folds);
    if ((p > thr || cv.rms <= cur.rms) && !costs && p > worst) worst = p, drop = static_cast<int>(j);
  }
  if (drop < 0) return false;
  progress(o, "backfitting: " + steps[drop].variable + " removed (p " + fmt(worst, 3) + " given the others)");
  res.removed.push_back(steps[drop].variable + " (" + steps[drop].effect + "; F test p " + fmt(worst, 3) +
                        " given the later effects)");
  spec = without(spec, steps[drop], o.bending_linear);
  steps.erase(steps.begin() + drop);
  cur = memo.cv(spec);
  cur_fit = memo.fit(spec);
  cur_joint = memo.joint(spec);
  refloor();
  return true;
}

// Report order: undeclared variables first, then base-model terms, each by its
// contribution (held-out MSE lost when it alone is removed), not by the order found.
void LoopSearch::order_steps() {
  for (auto& s : steps) {
    const ModelSpec t = without(spec, s, o.bending_linear);
    const CvResult cv = memo.cv(t);
    s.contribution = cv.rms * cv.rms - cur.rms * cur.rms;
    s.p_value = f_test(memo.joint(t), cur_joint, searched_params(s.added));
    s.params = new_params(memo.fit(t), cur_fit);
    if (s.effect.rfind("generic", 0) == 0)
      s.sign = sign_text(s, s.variable);
  }
  std::stable_sort(steps.begin(), steps.end(), [](const Step& a, const Step& b) {
    if (a.cls != b.cls) return a.cls == "undeclared variable";
    return a.contribution > b.contribution;
  });
}

// The held-out errors of the base model and after each step in report order.
void LoopSearch::cv_by_step() {
  ModelSpec t;
  t.bending_linear = o.bending_linear;
  CvResult prev = base_cv;
  res.cv.push_back(base_cv);
  for (auto& s : steps) {
    for (const auto& e : s.added)
      if (e.kind == EffectKind::bending_tension) t.bending_linear = true;
      else t.effects.push_back(e);
    const CvResult cv = &s == &steps.back() ? cur : memo.cv(t);
    s.rms_before = prev.rms, s.max_before = prev.max_abs;
    s.rms_after = cv.rms, s.max_after = cv.max_abs;
    res.cv.push_back(cv);
    prev = cv;
  }
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
  progress(o, "base model: cross-validation (" + std::to_string(d.rows.size()) + " rows)");
  LoopSearch s(d, o, res, sigma);
  s.excluded = response_columns(*d.data);
  for (const auto& rc : s.excluded)
    res.response_columns.push_back(rc.name + " (variance left by the forces " + fmt(rc.fraction, 2) + ")");
  for (;;) {  // forward, then backfitting (at most twice) and forward again
    s.forward();
    if (s.steps.empty() || s.backfits >= 2) break;
    ++s.backfits;
    if (!s.backfit()) break;
  }
  if (!s.steps.empty()) {
    s.order_steps();
    s.cv_by_step();
  } else {
    res.cv.push_back(s.cur);
  }
  res.steps = s.steps;
  res.final_fit = s.cur_fit;
  if (res.final_fit.has_force)  // fit_model: the lines fitted together with the force channel
    res.bending += "; with the force channel, each line refitted with it and friction to the pin's fixed and rotating rows";
  if (s.sigma < s.sigma_data) res.noise_data_N = s.sigma_data, res.noise.sigma_N = s.sigma;  // the model floor
  conclude(res, o, s.last_rank);
  return res;
}

}  // namespace drawbend::loop
