#pragma once
// A pair step must beat its own columns (issue 50 item 3, h50-pairfirst).
//
// The pairwise probes (screen_pairs.cpp) make a pair's product orthogonal to
// the LINEAR main effects of its two columns only, so a curved main effect of
// one column (a decay, a saturation, a bump) can make the pair family
// significant, and the pair's forms (a slope of the product per group, a
// smooth of it) can then predict held-out data nearly as well as, or a little
// better than, that column's own forms.  Issue 50 item 3 keeps the simplest
// form within one standard error of the best; one column is simpler than a
// pair of columns.  So when a round's best step is a pair, each of its two
// columns is given the single-column form family (the same forms, gates and
// threshold as any column: the nested F test at the round's Bonferroni
// threshold, a lower held-out error, the minimum effect), and a column takes
// the step when its best passed form's held-out mean squared error is within
// one standard error of the pair's best passed form's (mse_diff_se: the
// standard error of the difference of the two held-out MSEs from the per-test
// sums, as the forms' own one-SE rule); of two such columns, the one with the
// lower held-out RMS.  A column need not have been significant in the screen
// on its own: the pair's significance involves it, and its form passes the
// same gates as every step (as a column named through the aliases does).
#include <string>
#include <vector>

#include "loop/candidates.hpp"

namespace drawbend::loop {

/// One column of the pair, given its single-column forms.
struct PairMember {
  std::string name;
  bool passed = false;       ///< some form of the column passed the gates
  CvResult best;             ///< its best passed form's held-out result (when passed)
  bool significant = false;  ///< significant in the round's screen on its own (for the note only)
};

struct PairVerdict {
  int member = -1;   ///< index of the column that takes the step; -1: the pair keeps it
  std::string note;  ///< why, in words (loop.md, loop_summary.json "pair_decision")
};

/// The pair `pair` (its best passed form's held-out result pair_best) against
/// its columns: the rule above.
PairVerdict pair_or_member(const std::string& pair, const CvResult& pair_best, const std::vector<PairMember>& members,
                           const Folds& f);

}  // namespace drawbend::loop
