// The loop's conclusion in words; see conclusion.hpp.
#include "loop/conclusion.hpp"

#include <cmath>
#include <sstream>

#include "core/csv.hpp"
#include "loop/effects.hpp"

namespace drawbend::loop {

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
    int nu = 0;
    for (const auto& s : r.steps) nu += s.cls == "undeclared variable";
    c << "The loop added " << r.steps.size() << " effect(s) (" << nu << " of undeclared variables, "
      << r.steps.size() - nu << " adjusting the base model's own terms): ";
    for (size_t k = 0; k < r.steps.size(); ++k)
      c << (k ? "; " : "") << r.steps[k].variable << " (" << r.steps[k].effect << ", " << r.steps[k].channel << ")";
    c << ". ";
    for (const auto& s : r.steps)
      if (s.cls != "undeclared variable") r.base_terms.push_back(s.variable + " -> " + s.effect);
    r.undeclared = nu;
    if (!r.base_terms.empty())
      c << "The " << r.base_terms.size() << " term(s) on the model's own inputs are base-model mismatch (the base "
        << "model misfits in its own terms), not undeclared effects. ";
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
    if (r.at_noise) c << "the model explains the data to the noise level.";
  }
  // Remaining structure: in columns of the data (undeclared variables) or only
  // in the model's own inputs and the between-test scatter (base-model mismatch).
  bool column_left = false;
  for (const auto& k : rank)
    if (k.significant || k.decision == "undecided" || k.decision.rfind("significant", 0) == 0) {
      if (k.kind == "column" || k.kind == "pair") column_left = true;
      else r.base_mismatch.push_back(k.name + " (" + k.decision + ", p " + fmt(k.p_value, 3) + ")");
    }
  // With no column left, the remainder is called base-model mismatch only when
  // no column of the data reduces the held-out residual more than the best of
  // the model's own inputs does: a column that explains more (CV reduction)
  // but misses the threshold is named, and an undeclared variable is not
  // ruled out (a test-level effect in a few tests can do that).
  const CandidateResult* col = nullptr;  // the column with the largest CV reduction
  double base_cv = 0;                    // the largest CV reduction of the model's own inputs that remain
  for (const auto& k : rank) {
    if ((k.kind == "column" || k.kind == "pair") && (!col || k.cv_reduction > col->cv_reduction)) col = &k;
    if (k.kind != "column" && k.kind != "pair" && !is_identity(k.name) &&
        (k.significant || k.decision == "undecided" || k.decision.rfind("significant", 0) == 0))
      base_cv = std::max(base_cv, k.cv_reduction);
  }
  const bool column_beats_base = col && col->cv_reduction > base_cv && col->cv_reduction > 0;
  if (std::isfinite(r.ratio) && !r.at_noise) {
    if (column_left) c << "structure remains unexplained.";
    else if (column_beats_base)
      c << "structure remains unexplained: no column of the data is significant at the threshold, but "
        << col->name << " (p " << fmt(col->p_value, 3) << ") reduces the held-out residual more (CV reduction "
        << fmt(col->cv_reduction, 3) << ") than any of the model's own inputs (" << fmt(base_cv, 3)
        << "), so an undeclared variable is not ruled out.";
    else if (!r.base_mismatch.empty())
      c << "the rest is base-model mismatch (the model's own inputs or the scatter between tests), not an undeclared "
           "variable: no column of the data remains significant.";
    else c << "no candidate remains significant; the rest is base-model mismatch the screen cannot localise.";
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

}  // namespace drawbend::loop
