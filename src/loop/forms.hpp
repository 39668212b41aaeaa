#pragma once
// The forms an effect may take, compared by held-out data (issue 50).
//
// For a confirmed candidate variable the loop tries every applicable form:
//   library    the physical effects effects_for() names for it (pressure_mu,
//              stribeck, depletion, direction, pin surface, drift, ...);
//   generic    for a column of the data (not one of the model's inputs):
//              categorical: group factor, group factor per pin / speed /
//              direction / lubricant group; numeric: linear, saturating tanh,
//              logarithmic (positive columns), saturating exponential (lambda
//              on a grid), a step (threshold on a grid of quantiles), levels
//              (3-8 distinct values; 3 or 4: also levels per pin / speed /
//              direction / lubricant group, as a categorical column), linear
//              per pin / speed / direction / lubricant group, a smooth of any
//              shape (natural cubic spline,
//              3, 5 or 8 dof, and 3 or 5 dof per group of those inputs;
//              and, where the screen's strongest probe is per a model input,
//              a slope, a 3- or 5-dof smooth or the levels in one group only:
//              the group its one-group sub-probe points at, else the group
//              with the largest mean squared held-out residual; for a
//              continuous speed or direction also below / at and above a
//              threshold at its quartiles, 3 dof), the
//              force channel (an extra force on every row, rotating included,
//              fitted jointly: linear per pin, levels (3 or 4 values: also
//              per pin), a 3-dof smooth overall and per pin; levels and the
//              smooth also times the pin's relative bending force, a change of
//              the bending force itself), the bending channel (F_B + c_pin z) alone
//              or with a linear friction term ("both"), and (more than 8 values,
//              form_bumps.cpp) a local Gaussian bump of the column on mu and on the
//              force channel (newtons and scaled), overall and in the one-cell
//              forms' cell, its centre and width scanned on the held-out residual
//              (bump.hpp) and counted by the F test (q + 2).  A numeric model input
//              the base model does not use (speed when continuous) gets the
//              generic forms too.
// A numeric column with empty cells gets these forms with the empty rows at
// the column's mean (Design::values).  No per-level form (group factor, per
// group, force-channel levels, one-cell levels) for a column whose levels
// average fewer than two rows (levels_replicated, candidates.hpp).
// Each form is added to the current model and must pass three gates as before:
// the nested-model F test at the Bonferroni threshold, a lower held-out RMS,
// and the minimum effect.  Among the forms that pass, the one kept is the
// SIMPLEST (fewest added parameters) whose held-out mean squared error is
// within one standard error of the best form's (the standard error of the
// difference of the two, from the per-test sums of squared held-out residuals);
// so the library's physical forms are members of the family, not a gate before it.
// Between variables (loop.cpp), the step goes to the variable whose best passed
// form predicts held-out data best; it keeps that variable's kept form.
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "loop/candidates.hpp"
#include "loop/model.hpp"

namespace drawbend::loop {

struct FormTrial {
  ModelSpec spec;
  CvResult cv;
  JointFit joint;
  double p_value = 1;  ///< nested-model F test against the current model
  int q = 0;           ///< parameters added, extra_searched included
  std::string name, meaning, channel;  ///< channel: friction, bending or both
  bool passed = false;
  /// A form with parameters searched on a grid beyond those fitted: a
  /// product (Effect::times), a bump (Effect::bump_width) or a step
  /// (Effect::step): choose_form's guard.
  bool searched = false;
  int extra_searched = 0;  ///< searched parameters counted by the F test and in q (a bump: centre and width, 2; a step: 1)
  /// The joint fit, p_value and q made.  A form whose held-out error alone
  /// fails its gates cannot pass whatever its F test, so try_forms leaves
  /// them until complete_trials (a kept form's candidate, whose trials are
  /// all listed with their F tests): the same values, made only when read.
  bool tested = false;
};

/// Cross-validations and joint fits already made by try_forms in one run of
/// the loop (the same data and folds), by the model's arithmetic: a form
/// whose model computes the same as one tried before reuses its results
/// instead of repeating them bit for bit (a library effect that reads no
/// column of its own, e.g. pressure_mu named by avg_pressure_MPa and again by
/// inv_R_per_mm; drift and generic_linear of one column).
struct TrialCache {
  std::map<std::string, CvResult> cv;
  std::map<std::string, JointFit> joint;
};

/// Nested-model F test on the joint fits (bending and friction together);
/// extra_q: parameters of b searched on a grid (a bump's centre and width),
/// counted as fitted ones (q = b.p - a.p + extra_q, residual dof n - b.p - extra_q).
double f_test(const JointFit& a, const JointFit& b, int extra_q = 0);

/// The searched parameters of a step's effects: a bump's centre and width (2
/// each), which the F test counts (extra_q) as try_forms did when the step was
/// added (FormTrial::extra_searched): backfitting's and the report's F tests.
int searched_params(const std::vector<Effect>& added);

/// The model s with effect k on `variable` added (depletion and the saturating
/// exponential get their length on a grid by the full-data fit), its shape
/// times the centred model-input quantity `times` when that is not empty
/// (Effect::times; the grid is searched with the multiplier on).
ModelSpec with_effect(const Design& d, const ModelSpec& s, EffectKind k, const std::string& variable,
                      const std::string& by = "", const std::string& times = "");

/// Every applicable form for candidate c, each cross-validated, and F-tested
/// when its held-out error passes the gates (the others: FormTrial::tested).
/// cell_by / cell_group (the screen's strongest one-group probe, -1: none)
/// add the forms confined to that one group of a model input.  cache (may be
/// null): the results of earlier calls on the same data and folds.  max_q >=
/// 0: forms adding more friction parameters than that are not fitted (the
/// far rule's simple forms, LoopOptions::far_max_params).  products: the
/// forms of a column that changes mu's pressure or speed slope
/// (LoopOptions::product_forms).  probe_input: the model input of the
/// screen's strongest probe when it is a per-input one (the one-cell forms in
/// its worst-fitted group and its split cells); cv_input, used when
/// probe_input is empty: that of the probe with the largest held-out gain
/// (the one-cell forms in its worst-fitted group).
std::vector<FormTrial> try_forms(const Design& d, const Folds& folds, const ModelSpec& spec, const Candidate& c,
                                 const CvResult& cur, const JointFit& cur_joint, double threshold, double min_gain_N,
                                 const std::function<void(const std::string&)>& progress,
                                 const std::string& cell_by = "", int cell_group = -1, TrialCache* cache = nullptr,
                                 const std::string& probe_input = "", int max_q = -1, bool products = false,
                                 const std::string& cv_input = "");

/// The trials try_forms left untested (FormTrial::tested) given their joint
/// fits, F tests and q, as try_forms would have made them (passed unchanged:
/// their held-out error failed a gate).
void complete_trials(const Design& d, std::vector<FormTrial>& trials, const JointFit& cur_joint,
                     TrialCache* cache = nullptr);

/// Index of the form kept (simplest within one standard error of the best
/// among those passed; a searched form, a product or a bump, only when the
/// best is a searched one too: its parameter count understates what was
/// searched for it), -1 when none passed.
int choose_form(const std::vector<FormTrial>& t, const Folds& f);

/// Standard error of the difference of two held-out mean squared errors, from
/// per-test sums (rows finite in both).
double mse_diff_se(const CvResult& a, const CvResult& b, const Folds& f);

}  // namespace drawbend::loop
