// A pair step must beat its own columns; see pair_first.hpp.
#include "loop/pair_first.hpp"

#include <sstream>

#include "core/csv.hpp"
#include "loop/forms.hpp"

namespace drawbend::loop {

PairVerdict pair_or_member(const std::string& pair, const CvResult& pair_best, const std::vector<PairMember>& members,
                           const Folds& f) {
  PairVerdict v;
  const double mse_pair = pair_best.rms * pair_best.rms;
  std::vector<double> diff(members.size()), se(members.size());
  for (size_t k = 0; k < members.size(); ++k) {
    const PairMember& m = members[k];
    if (!m.passed) continue;
    diff[k] = m.best.rms * m.best.rms - mse_pair;
    se[k] = mse_diff_se(m.best, pair_best, f);
    if (diff[k] <= se[k] && (v.member < 0 || m.best.rms < members[v.member].best.rms)) v.member = static_cast<int>(k);
  }
  std::ostringstream n;
  const auto column = [&](size_t k) {
    const PairMember& m = members[k];
    std::ostringstream c;
    c << m.name << (m.significant ? "" : " (not significant in the screen on its own)");
    if (!m.passed) c << ": no form passed the F test, lowered the held-out error and reached the minimum effect";
    else
      c << ": best form's held-out RMS " << fmt(m.best.rms, 4) << " N, MSE difference " << fmt(diff[k], 3)
        << " N^2 against one standard error " << fmt(se[k], 3) << " N^2";
    return c.str();
  };
  if (v.member >= 0) {
    n << members[v.member].name << " took the step from the pair " << pair << " (pair's best form: held-out RMS "
      << fmt(pair_best.rms, 4) << " N): one column is simpler than a pair, and its best form predicts held-out data "
      << (diff[v.member] < 0 ? "better than" : "within one standard error of") << " the pair's ("
      << column(v.member) << ")";
  } else {
    n << "the pair " << pair << " (best form's held-out RMS " << fmt(pair_best.rms, 4)
      << " N) kept the step over each of its own columns, none within one standard error of it (";
    for (size_t k = 0; k < members.size(); ++k) n << (k ? "; " : "") << column(k);
    n << ")";
  }
  v.note = n.str();
  return v;
}

}  // namespace drawbend::loop
