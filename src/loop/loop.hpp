#pragma once
// The loop: fit the base model, predict every sample, analyse the held-out
// residuals against every candidate variable, trace the top significant
// candidate to a library effect, add it if the effect passes a nested-model F
// test (bending and friction refitted jointly, so the uncertainty of the
// bending lines is part of the null) and lowers the held-out error, and iterate
// until no candidate is significant at the Bonferroni threshold
// alpha / (number of candidates).  A significant variable that no library
// effect explains gets a generic effect (categorical: group factor; numeric:
// linear and saturating) with its size, SE and sign.  The final held-out error
// is compared with the replicate noise (noise.hpp).
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
  bool progress = false;  ///< print progress to stderr
};

struct Step {
  std::string variable, effect, meaning;
  double p_value = 1;        ///< nested-model F test of the added effect (joint fit)
  double p_permutation = 1;  ///< the candidate's blocked permutation test
  double threshold = 0;      ///< alpha / number of candidates (Bonferroni), for both
  double rms_before = 0, rms_after = 0, max_before = 0, max_after = 0;
  std::vector<Param> params;                 ///< of the effect, from the full-data refit
  std::vector<std::pair<std::string, double>> tried;  ///< effect -> held-out RMS
  std::string sign;  ///< generic effects: direction of the effect in words
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
  double ratio = std::nan("");  ///< final held-out RMS / replicate noise
  bool at_noise = false;
  std::vector<std::string> remaining;  ///< strongest remaining candidates when not at the noise level
  std::string conclusion;              ///< plain-language conclusion (loop.md opens with it)
  std::string bending;                 ///< bending-force label (every output)
};

std::string base_model_text(bool bending_linear);

LoopResult run_loop(const Design& d, const LoopOptions& o);

/// loop_summary.json text (deterministic formatting).
std::string summary_json(const LoopResult& r);

}  // namespace drawbend::loop
