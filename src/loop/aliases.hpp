#pragma once
// Collinear naming (issue 50): columns that explain the same structure as a
// step's variable.
//
// A test-level alias (test_order, operator, date: all functions of the run
// order) can win a step instead of the true column: the screen permutes a
// row-level column (cycle_count) within tests only, so its between-test part,
// the bulk of a drift, is never tested, and the column often fails the screen
// or ranks below the aliases; only the strongest `contenders` are given forms.
// So once the loop has chosen a step on a column x, the columns that explain
// the same structure are given their forms as well, and the one whose kept
// form predicts held-out data best names the step (the same rule as between
// the contenders).  "Explain the same structure": the step's effect on the
// held-out prediction, e = pred_after - pred_before, centred per block (the
// screen's blocks), is grouped by the column's values (explained_share), and
// the columns with the largest share are tried.  Trying them adds no step: it
// only decides which column names a step already confirmed, so it cannot add
// a false alarm on a null set.
#include <string>
#include <utility>
#include <vector>

#include "loop/candidates.hpp"

namespace drawbend::loop {

/// Share of the block-centred e explained by the groups of y: 1 - SS within
/// groups / SS total.  Groups: y's levels (categorical with at most
/// kAliasMaxLevels levels), its distinct values (numeric with at most 8), else
/// 8 quantile bins of its rows (ties kept in one bin).  Rows with e or y
/// missing are skipped; 0 when y has too many levels, fewer than 2 groups, or
/// e is constant.
double explained_share(const std::vector<double>& e, const std::vector<int>& block, const Candidate& y);

struct AliasColumn {
  std::string name;
  double share = 0;
};

constexpr int kAliasMaxLevels = 12;  ///< a categorical column with more levels is an identity, not an alias
constexpr double kAliasShare = 0.2;  ///< explained share to be tried as an alias (a test-level column unrelated to e explains about 7 / (tests - 1), ~0.1, by its 8 bins alone)
constexpr int kAliasMax = 3;         ///< aliases tried per step, the largest shares

/// The columns of the data (kind "column", not an identity, not a function of
/// a model input, not `x`, not in `skip`) whose explained share of e is at
/// least `min_share`, largest first (name breaks ties), at most `max`.
std::vector<AliasColumn> alias_columns(const std::vector<Candidate>& cands, const std::vector<double>& e,
                                       const std::vector<int>& block, const std::string& x,
                                       const std::vector<std::string>& skip, double min_share = kAliasShare,
                                       int max = kAliasMax);

/// RMS difference of two models' held-out predictions over the rows both
/// predict [N] (NaN when none), summed in row order.  A column whose step
/// predicts within LoopOptions::min_effect x the noise (RMS) of the chosen
/// step's makes the same effect at the loop's own resolution: added after the
/// chosen step, it could change the held-out predictions by about that much at
/// most, below the smallest held-out gain a step must reach.  The loop lists
/// such columns under Step::same_effect_as when the paired test of their
/// errors still prefers the step (two forms that predict almost alike have a
/// tiny standard error of their MSE difference).
double prediction_rms_diff(const std::vector<double>& a, const std::vector<double>& b);

/// A model's held-out predictions within kSameModelShare x the RMS of
/// another's (prediction_rms_diff) are the same model in another coding: a
/// step of a run-order column at a shift change and a categorical column of
/// the shifts, or a column and its renamed copy.  Their held-out errors
/// differ by rounding only.
constexpr double kSameModelShare = 1e-6;

struct FormTrial;
/// Does candidate form `a` (a candidate's best passed form) take the round's
/// step from the best so far, `held` (its held-out result) with `held_q`
/// parameters (FormTrial::q: searched ones counted)?  By the lower held-out
/// RMS; but when the two are the same model (kSameModelShare), by fewer
/// parameters, a threshold or bump searched for it counted (the simpler
/// description of the same fit), and on a tie of those the one held.
bool takes_the_step(const FormTrial& a, const CvResult& held, int held_q);

struct Step;
/// The columns of `kept` (column -> its kept form's held-out result), the
/// step's own skipped: those within one standard error of the MSE difference
/// from the step's kept form `best` (mse_diff_se) go to s.aliased_with; the
/// others whose predictions lie within min_effect_N (RMS) of best's go to
/// s.same_effect_as (none when min_effect_N is NaN: no usable noise); their
/// names, in that order, to s.alike_names.
void name_alikes(Step& s, const std::vector<std::pair<std::string, CvResult>>& kept, const CvResult& best,
                 const Folds& f, double min_effect_N);

}  // namespace drawbend::loop
