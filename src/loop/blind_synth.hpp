#pragma once
// A second synthetic generator for the loop, written without reading the
// loop's effect library (issue 50, item 5; protocol:
// chapters/ch7-closing-the-loop/heldout_protocol.md).  Everything is drawn
// from the seed: nothing here is chosen to match a form the loop knows.
//
// Design (drawn per set): pins 12.7, 25.4, 42 mm; directions {0, 90},
// {0, 45, 90}, {0, 30, 60, 90} or {0, 22.5, 45, 67.5, 90} deg; speeds either
// 3 levels or continuous (log-uniform 5-120 mm/s per test); 1 or 2
// lubricants; 8-30 fixed-pin tests per pin (at least 2 per cell) and 3
// rotating-pin tests, 6-25 rows each; back tension stepped over the pin's
// range in a shuffled order along the sliding distance; rows in run order
// (as a lab sends them), lab-style test ids.
// Base truth (null sets are exactly this plus noise): bending F_B = b0 + b1 F
// per pin (Table 5.3 lines, jittered 5 %); friction by the rope formula
// F (exp(mu pi/2) - 1) with mu = RD/TD ellipse (mu_RD 0.07-0.12, mu_TD/mu_RD
// 0.8-1.05), a factor per lubricant and per speed level (cell constants).
// Columns beyond the required ones (decoys unless the planted effect uses
// them): test_order, operator, coil, yield_MPa (per coil), lot, tool_temp_C,
// thickness_mm, humidity_pct (per row), lube_film_g_m2 (few levels), die_set,
// cycle_count (strokes on that pin so far, per row), and, each with
// probability 0.7, strip_id (one per test), date, timestamp (one per row),
// comment (long free text, mostly empty).
//
// Classes and what a planted effect of each draws:
//   level        a few-level variable (direction_deg, lube_film_g_m2, die_set,
//                operator) with a per-level pattern: a mid-level peak, one
//                level apart, or random levels;
//   smooth       a row-level or continuous variable (sliding distance, speed
//                when continuous, cycle_count, test_order, humidity) through a
//                shape: linear, log, saturating, step, threshold, periodic,
//                sigmoid, bump, U;
//   interaction  a shape of a variable acting in one cell only (one pin, one
//                direction, one lubricant or one speed level);
//   bending      thickness (F_B ~ t^2) or the coil's yield stress (F_B ~
//                sigma_y) on the bending force, alone or with friction;
//   test-level   coil, lot, tool temperature or thickness per test, on friction;
//   null         nothing.
// Channels (not bending): friction multiplicative mu (1 + a g), friction
// additive mu + a g, or an extra drag a g >= 0 on the outlet force (all rows).  The size a is
// set so that the effect's RMS on the outlet force over all rows is k times
// the noise sd, k uniform in [2.5, 6].
#include <cstdint>
#include <string>
#include <vector>

#include "loop/measured.hpp"

namespace drawbend::loop {

struct BlindOptions {
  std::string cls = "random";  ///< one of blind_classes(), or "random"
  double noise_N = 3;
  std::uint64_t seed = 1;
};

struct BlindTruth {
  std::string cls, variable, shape, channel, cell, law;
  std::vector<std::string> aliases;  ///< columns the design confounds exactly with the variable
  double k = 0;             ///< drawn effect RMS / noise sd
  double effect_rms_N = 0;  ///< the effect's RMS on the outlet force, all rows (N)
  /// The fewest tests that carry 90 % of the planted effect's sum of squares
  /// on the outlet force (effect_support): an effect carried by one test
  /// cannot be told from the data to belong to any one column, since every
  /// numeric test-level column singles that test out.
  int support_tests = 0;
  double noise_N = 0;
  std::uint64_t seed = 0;
};

/// The share of the planted effect's sum of squares that BlindTruth::support_tests counts.
inline constexpr double kSupportShare = 0.9;

/// The fewest tests whose rows carry `share` of the sum of squares of y - y0
/// (the planted effect per row; test_of_row: each row's test index).
int effect_support(const std::vector<double>& y, const std::vector<double>& y0, const std::vector<int>& test_of_row,
                   double share = kSupportShare);

/// level, smooth, interaction, bending, test-level, null.
const std::vector<std::string>& blind_classes();

/// One data set (throws std::invalid_argument on an unknown class).
Dataset synthesize_blind(const BlindOptions& o, BlindTruth& truth);
std::string blind_truth_json(const BlindTruth& t);

}  // namespace drawbend::loop
