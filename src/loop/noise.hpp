#pragma once
// The replicate noise of a data set, from the scatter within tests.
//
// Within every test (>= 4 rows) the outlet force is fitted by least squares on
// a line in the back tension and, with 6 or more rows, a quadratic in the run
// position (rows in time_s order, else sliding distance, else file order);
// with 8 or more rows a quadratic in the back tension and a cubic in the run
// position:
//   sigma^2 = sum_tests |e|^2 / sum_tests (n_t - rank_t).
// For white noise this is unbiased; the polynomial in run position absorbs slow
// within-test structure (depletion along the sliding distance, drift) so that
// it is not mistaken for noise.  Structure that varies between tests (pin,
// batch, direction, speed) never enters.  Units: N.
//
// With `values` (one per row, NaN: the row is skipped) the same scatter is
// measured on those values in place of the outlet force: the loop's opt-in
// model floor (LoopOptions::model_noise) measures it on the current model's
// held-out residual after every step.  A within-test effect of a row-level
// column (a bump in the sliding distance, a load-cell temperature that changes
// from row to row) that no polynomial in the run position follows inflates
// the data's floor (up to 5 x the true noise on development sets,
// heldout_record.md); what the model explains of it leaves the residual's.
#include <cmath>
#include <string>
#include <vector>

#include "loop/model.hpp"

namespace drawbend::loop {

struct NoiseFloor {
  double sigma_N = std::nan("");  ///< replicate noise sd [N] (NaN: no test with >= 4 rows)
  int tests = 0, rows = 0;        ///< tests and rows used
  double dof = 0;                 ///< degrees of freedom, sum of (n_t - rank_t)
  std::string order;              ///< run order used
  bool exact = false;             ///< rows lie exactly on lines (sigma below 1e-6 of the mean force)
};

NoiseFloor replicate_noise(const Design& d, const std::vector<double>* values = nullptr);

}  // namespace drawbend::loop
