#pragma once
// The loop: fit the base model, predict every sample, analyse the held-out
// residuals against every candidate variable, trace the top significant
// candidate to a library effect, add it if the effect passes a nested-model F
// test (bending and friction refitted jointly, so the uncertainty of the
// bending lines is part of the null) and lowers the held-out error, and iterate
// until no candidate is significant at the Bonferroni threshold
// alpha / (number of candidates), or no library effect explains it.
#include <cstdint>
#include <string>
#include <vector>

#include "loop/candidates.hpp"
#include "loop/model.hpp"

namespace drawbend::loop {

struct LoopOptions {
  std::string cv = "auto";
  int folds = 5;
  int permutations = 999;
  std::uint64_t seed = 20261121;
  double alpha = 0.05;
  int max_steps = 6;
  bool bending_linear = true;
};

struct Step {
  std::string variable, effect, meaning;
  double p_value = 1;        ///< nested-model F test of the added effect (joint fit)
  double p_permutation = 1;  ///< the candidate's blocked permutation test
  double threshold = 0;      ///< alpha / number of candidates (Bonferroni), for both
  double rms_before = 0, rms_after = 0, max_before = 0, max_after = 0;
  std::vector<Param> params;                 ///< of the effect, from the full-data refit
  std::vector<std::pair<std::string, double>> tried;  ///< effect -> held-out RMS
};

struct LoopResult {
  std::string base_model, cv_mode, maps;
  std::vector<Step> steps;
  std::string stopped_because;
  std::vector<std::string> unexplained;  ///< significant variables no library effect explains (F-test confirmed)
  std::vector<std::string> screened;     ///< passed the permutation screen only, not confirmed by a model test
  std::vector<std::vector<CandidateResult>> rankings;  ///< one per analysis round
  std::vector<Candidate> candidates;                   ///< values at the base model
  std::vector<CvResult> cv;                            ///< base, then after each step
  Fit final_fit;
  Folds folds;
};

std::string base_model_text(bool bending_linear);

LoopResult run_loop(const Design& d, const LoopOptions& o);

/// loop_summary.json text (deterministic formatting).
std::string summary_json(const LoopResult& r);

}  // namespace drawbend::loop
