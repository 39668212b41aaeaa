#pragma once
// The loop's conclusion in words (loop.cpp): what was added, whether the
// remaining held-out error is at the replicate noise, and whether what
// remains lies in columns of the data (undeclared) or only in the model's
// own inputs (base-model mismatch, issue 50 item 4).  Ended above the noise
// with no column significant, the rest is called base-model mismatch only
// when no column reduces the held-out residual more than the model's own
// inputs do; otherwise the strongest column is named and an undeclared
// variable is said not to be ruled out (tests/unit/test_loop_conclusion.cpp).
#include <vector>

#include "loop/candidates.hpp"
#include "loop/loop.hpp"

namespace drawbend::loop {

/// Writes r.conclusion and sets r.ratio, r.at_noise, r.undeclared,
/// r.base_terms, r.base_mismatch and r.remaining from the final round's
/// screen `rank`.
void conclude(LoopResult& r, const LoopOptions& o, const std::vector<CandidateResult>& rank);

}  // namespace drawbend::loop
