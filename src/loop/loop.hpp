#pragma once
// The loop: fit the base model, predict every sample, screen the held-out
// residuals against every candidate variable, give the strongest significant
// candidates their best form, add the best, re-screen, and iterate until no
// candidate is significant at the Bonferroni threshold alpha / (number of
// tests: candidates with the same levels on the same rows share one,
// screen_same.cpp; each pair family is one).  In detail (issue 50):
//   screen     every candidate is probed by a family of probes (its levels, a
//              step or smooth shape, a term scaled with dF/dmu, and its effect
//              within each group of the model's inputs: pin, speed, direction,
//              lubricant, and, opt-in, confined to one group of one of them), one
//              permutation test of the family's maximum, so
//              the multiplicity of the family is inside the candidate's p
//              (candidates.hpp);
//   forms      each of the `contenders` strongest significant candidates gets
//              every applicable form (library physics, generic shapes, the
//              bending channel, per-group forms, forms confined to the
//              screen's strongest one-group cell), each gated by the
//              nested-model F test (bending and friction refitted jointly),
//              a lower held-out error and the minimum effect; the simplest
//              form within one standard error of the best is kept (forms.hpp);
//              the candidate whose form predicts held-out data best is added;
//   far        (--far-ratio, default 2) a round with no step while the held-out RMS is above
//              far_ratio x the measured replicate noise gives the candidates
//              with the largest held-out gain (up to 3; after the first, those
//              with at least half its gain) their forms, significant or not;
//              its step must take at least far_share of the excess MSE over
//              the noise (the data show something is missing; the screen may
//              lack the power to say which column in a cell of few tests);
//   aliases    the columns that explain the same structure as the chosen
//              column's effect (aliases.hpp) are given their forms too, so a
//              run-order alias (test_order, operator) does not name a step
//              that a row-level column explains better on held-out data;
//              columns the held-out data cannot tell apart are reported;
//   pairs      a pair of columns (screen_pairs.cpp) that is the round's best
//              step must beat its own columns: each is given the
//              single-column forms, and one whose best form is within one
//              standard error of the pair's takes the step (pair_first.hpp);
//   channels   an effect acts on mu, on the bending force (F_B + c_pin z,
//              fitted with the bending lines on the rotating-pin rows), or
//              both; which, is decided by the held-out data through the forms;
//   backfit    after the forward search an effect no longer needed given the
//              others (F test given all others above the threshold, or no
//              held-out loss without it) is removed and the search resumes, so
//              an early nuisance term can give way to a later variable;
//   report     steps are listed undeclared variables (columns of the data)
//              first, then base-model terms (effects on the model's own
//              inputs: pin, pressure, speed, direction, back tension), each
//              class by its contribution (held-out MSE lost without it), not
//              by the order found.  Base-model terms added and remaining
//              structure only in the model's inputs are reported as
//              base-model mismatch, apart from undeclared variables (issue 50
//              item 4: base_model_terms and undeclared_effects in
//              loop_summary.json).
// A significant variable that no form explains is listed as screened.  The
// final held-out error is compared with the replicate noise (noise.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "loop/candidates.hpp"
#include "loop/model.hpp"
#include "loop/noise.hpp"

namespace drawbend::loop {

struct LoopOptions {
  std::string cv = "auto";
  int folds = 5;
  int permutations = 20000;  ///< cap of the sequential permutation test
  std::uint64_t seed = 20261121;
  double alpha = 0.05;
  int max_steps = 6;
  bool bending_linear = true;
  /// Minimum effect: a step must lower the held-out error by at least this
  /// fraction of the replicate noise, sqrt(rms_before^2 - rms_after^2) >=
  /// min_effect sigma, so that huge data sets do not accept steps far below
  /// what any single test can see.
  double min_effect = 0.2;
  /// The held-out error is "at the noise level" when RMS / sigma <= this (see
  /// loop.cpp: at_noise_limit for the reason).
  double noise_ratio = 1.25;
  /// Opt-in (`--noise-floor model`; off until a paired check decides,
  /// heldout_record.md): after every step the replicate noise is measured again
  /// on the current model's held-out residual (replicate_noise with values),
  /// and the floor (the minimum effect, the far-from-noise rule, the
  /// conclusion) is the smaller of that and the data's own.
  bool model_noise = false;
  bool progress = false;  ///< print progress to stderr
  /// Significant candidates given their best form per round (the best of them is added).
  int contenders = 3;
  /// When a round gives no step and the held-out RMS is above far_ratio x the
  /// measured replicate noise (never when the noise is not measured), the
  /// `far_contenders` candidates with the largest positive held-out gain are given
  /// their forms, significant or not, and the best is added as any step (its
  /// forms' gates unchanged; Step::far_note says so).  The data then show that
  /// something is missing; the permutation screen, there to keep a null data
  /// set without a step, can lack the power to say which column when the
  /// effect lives in a cell of a dozen tests (heldout_record.md, h50-far).
  /// On by default (`--far-ratio 2`: the goal's own line, detected = held-out
  /// RMS within 2 x the noise; 0 turns it off).  Checked in this form on 240
  /// fresh sets against a paired bar written before the run (heldout_record.md,
  /// h50-fardef2): 9 effect sets gained and none lost of 200 (wild 95 -> 104
  /// of 120, generator 1 unchanged), 0 alarms of 40 null sets, 1.17 x elapsed;
  /// earlier forms: +4, +1, +3 and +1 of 80 (h50-far, h50-fardefault,
  /// h50-farsimple), never a set lost or an alarm.  Without the screen's family-wise
  /// protection such a step must
  /// also explain the main part of what is missing: its held-out MSE gain at
  /// least far_share of the excess MSE over the noise, rms^2 - sigma^2 (a
  /// decoy picking up a little structure takes a few per cent of it).
  double far_ratio = 2.0;
  double far_share = 0.5;
  /// Candidates the rule gives their forms, by held-out gain, at most
  /// far_contenders; one after the first only when its gain is at least
  /// far_gain_share x the first's (each costs its forms, 0.5-1.9 s a form on
  /// an 889-row set: three for every round made the rule's check run 1.40 x
  /// main's CPU, heldout_record.md h50-far; a gain half the best's is not a
  /// contender for the same structure).
  int far_contenders = 3;
  double far_gain_share = 0.5;
  /// The far rule's step has at most this many parameters (its forms with
  /// more fail a gate).  The screen has not vouched for the column, and a
  /// many-parameter form (a 5-dof smooth per direction: 25) absorbs structure
  /// that is not the column's: on the development sets 4 of the 6 far steps
  /// above 9 parameters were decoys, and each made every later form slower
  /// (one check set 262 s against 0.5 s; heldout_record.md, h50-farsimple).
  /// 9: a 3-dof smooth per group of a three-group input (pin, speed).
  int far_max_params = 9;
  /// Opt-in (--cell-probes; development, not yet scored on enough data): the
  /// screen's one-cell sub-probes and the forms confined to one cell.
  bool cell_probes = false;
  /// The forms of a column that changes how mu depends on the pressure or
  /// the speed (--product-forms): its slope, step, 3-dof smooth or levels
  /// times the centred nominal pressure or log speed (forms.cpp
  /// FormPlans::products), never kept by the one-SE rule in place of a
  /// better form that is not a product (choose_form).  On by default since
  /// h50-ssguard (heldout_record.md); an opt-in before (h50-products and
  /// h50-prodtie: their checks gained more sets than they lost, but none met
  /// its bar).
  bool product_forms = true;
  /// Per-input probes of test-level variables pooled over the cells as well
  /// (screen_probe.hpp: centred_by).  On by default since 2026-12-02 (turn 8):
  /// development seeds 52100000/55100000 (tuning) 30/40 -> 30/40 and 29 -> 30,
  /// 52300000/55300000 (check) 34 -> 34 and 27 -> 28, nulls 0/32 before and after.
  bool pooled_inputs = true;
  /// Pairwise probes between numeric columns of the data (screen_pairs.cpp):
  /// an effect of two columns together (a product, or a crossover with no main
  /// effect), one permutation family per scheme (issue 50, h50-pairs).
  bool pair_probes = true;
  /// Threads of the screen (candidates screened at once; the same results for any count).
  int threads = 1;
};

struct Step {
  std::string variable, effect, meaning;
  double p_value = 1;        ///< nested-model F test of the effect given all the others (joint fit)
  double p_permutation = 1;  ///< the candidate's blocked permutation test
  double threshold = 0;      ///< alpha / number of tests (Bonferroni; tests_in), for both
  double rms_before = 0, rms_after = 0, max_before = 0, max_after = 0;
  std::vector<Param> params;                 ///< of the effect, from the full-data refit
  std::vector<std::pair<std::string, double>> tried;  ///< effect -> held-out RMS
  std::string sign;  ///< generic effects: direction of the effect in words
  std::string cls;      ///< "undeclared variable" (a column of the data) or "base model" (the model's inputs)
  std::string channel;  ///< friction, bending or both
  std::string probe;    ///< the screen's probe with the largest statistic
  std::string meaning_note;  ///< "confounded with <input>" for a column that is a function of a model input
  /// Other columns whose kept form predicts held-out data as well as this
  /// step's (within one standard error of the difference): the data cannot
  /// tell them apart (aliases.hpp), "name (held-out RMS x N)".
  std::vector<std::string> aliased_with;
  /// Other columns whose kept form's held-out predictions lie within
  /// LoopOptions::min_effect x the noise (RMS) of this step's, though the
  /// paired test prefers this step's (prediction_rms_diff, aliases.hpp):
  /// "name (held-out RMS x N; predictions within y N RMS of the step's, the
  /// minimum effect z N)".
  std::vector<std::string> same_effect_as;
  /// The column names of aliased_with, then of same_effect_as, as given (a
  /// user's column may have " (" in its name, so they are not parsed back).
  std::vector<std::string> alike_names;
  /// A pair step (screen_pairs.cpp): its two columns (empty: one variable).
  std::vector<std::string> columns;
  /// A pair was the round's best step (pair_first.hpp): why it kept the step
  /// over its own columns, or why one of them took it (empty: no pair).
  std::string pair_note;
  /// Taken by the far-from-noise rule (LoopOptions::far_ratio): why (empty: by the screen).
  std::string far_note;
  double contribution = 0;  ///< held-out MSE lost when this effect alone is removed [N^2]
  std::vector<Effect> added;  ///< the effects of the step (bending_tension: the flag)
};

struct LoopResult {
  std::string base_model, cv_mode, maps;
  std::vector<Step> steps;
  std::string stopped_because;
  std::vector<std::string> screened;     ///< passed the permutation screen only, not confirmed by a model test
  std::vector<std::vector<CandidateResult>> rankings;  ///< one per analysis round
  std::vector<Candidate> candidates;                   ///< values at the base model
  std::vector<CvResult> cv;                            ///< base, then after each step
  Fit final_fit;
  Folds folds;
  NoiseFloor noise;
  /// With LoopOptions::model_noise and a floor lowered by it: the data's own
  /// replicate noise [N] (noise.sigma_N is then the final floor); else NaN.
  double noise_data_N = std::nan("");
  double ratio = std::nan("");  ///< final held-out RMS / replicate noise
  bool at_noise = false;
  std::vector<std::string> remaining;  ///< strongest remaining candidates when not at the noise level
  std::vector<std::string> removed;    ///< effects removed by backfitting
  /// Remaining significant structure in the model's own inputs (base-model
  /// mismatch), reported apart from undeclared variables.
  std::vector<std::string> base_mismatch;
  /// Base-model mismatch the loop corrected (issue 50 item 4): the steps of
  /// class "base model" (effects on the model's own inputs: pin, pressure,
  /// speed, direction, back tension, lubricant, or a column that is a function
  /// of one), "variable -> effect"; not undeclared effects.
  std::vector<std::string> base_terms;
  /// Extra columns the measured forces determine (response_columns.hpp), not
  /// screened: "name (variance left by the forces f)".
  std::vector<std::string> response_columns;
  int undeclared = 0;  ///< steps of class "undeclared variable"
  std::string conclusion;              ///< plain-language conclusion (loop.md opens with it)
  std::string bending;                 ///< bending-force label (every output)
};

std::string base_model_text(bool bending_linear);

LoopResult run_loop(const Design& d, const LoopOptions& o);

/// loop_summary.json text (deterministic formatting).
std::string summary_json(const LoopResult& r);

}  // namespace drawbend::loop
