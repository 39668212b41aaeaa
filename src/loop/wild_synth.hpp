#pragma once
// Generator 2 of the held-out study ("wild"; issue 50, item 5; protocol:
// chapters/ch7-closing-the-loop/heldout_protocol_v2_wild.md).  Written without
// opening the loop's effect library (effects*, effect_rules*, candidates*,
// screen*, forms*, loop.cpp) or generator 1's effect drawing: it plants one
// effect per set drawn from its own family, of kinds a tribology lab meets
// and a loop author may not have imagined.  Everything is drawn from the seed
// (own uniform and normal draws on std::mt19937_64, so the same seed gives the
// same file with any standard library).
//
// Design (drawn per set): pins 12.7, 25.4, 42 mm with Table 5.3 bending lines
// jittered 5 %; directions {0, 90}, {0, 45, 90}, {0, 30, 60, 90} or
// {0, 15, 45, 75, 90} deg; speeds 3 levels of {5, 10, 20, 40, 80, 160} mm/s
// or continuous (log-uniform 4-150 mm/s per test); 1-3 lubricants;
// 7-22 fixed-pin tests per pin (at least 2 per cell) and 3 rotating-pin tests,
// 5-20 rows each, back tension stepped over the pin's range in a shuffled
// order along the sliding distance; rows in run order.
// Base truth (null sets are exactly this plus noise): bending F_B = b0 + b1 F
// per pin; friction by the rope formula F (exp(mu pi/2) - 1) with mu on the
// RD/TD ellipse times a factor per lubricant and per speed level.
// Columns beyond the required ones, always all written (decoys unless the
// planted effect uses one): run_no, operator (shifts follow run_no),
// sheet_batch, batch_rp02_MPa (per batch: an exact alias), blank_thickness_um
// (micrometres, per test, batch-correlated), surface_grade (ordinal R1-R4 read
// off ra_strip_um with error: correlated), ra_strip_um, pre_strain_pct (few
// levels), fixture, clean_method, pin_temp_F (Fahrenheit, warms with run_no),
// oil_age_days (days since the bath change, empty for a few tests),
// pin_travel_m (per row: sliding on this pin since its last polish),
// load_cell_temp_C (per row, drifts over the day); each with probability 0.7
// strip_id, date, clock and remark.
//
// Classes (wild_classes()):
//   level        a few-level carrier (batch, grade, pre-strain, fixture,
//                cleaning, operator, direction with >= 3 levels) with a
//                per-level pattern: random levels, one level apart, mid-level
//                peak or monotone-then-flat (ordinal carriers);
//   smooth       a row-level numeric carrier (sliding distance: wear-in,
//                pin travel, load-cell temperature, continuous speed) through
//                a shape: linear, log, power, exp-saturation, exp-decay, step,
//                hinge, plateau, bump, U, sinusoid;
//   interaction  a carrier's shape or level pattern acting in one cell only
//                (one pin, direction, lubricant, speed level or speed band);
//   channel      effects outside friction or on the base's own dependences:
//                bending (thickness^q, proof stress, pre-strain), outlet
//                offset (load-cell temperature, fixture), back-tension gain
//                error (the recorded back tension is off by a carrier's
//                factor), a pressure law mu ~ shape(p), a speed law on
//                continuous speeds, or a carrier changing the mu(p) or mu(v)
//                slope;
//   test-level   a per-test numeric carrier (thickness, strip roughness, pin
//                temperature, oil age with missing values, run number, proof
//                stress) through a shape;
//   null         nothing.
// Channels: mu_mult mu (1 + a g), mu_add mu + 0.1 a g, bend F_B (1 + a g),
// offset F_out + 100 a g N, bt_gain (true back tension F (1 + 0.1 a g)),
// mu_pslope mu (1 + a g (p / p_mean - 1)), mu_vslope mu (1 + a g ln(v / v_geo)).
// g is centred over the rows it acts on (within the cell for interactions), so
// no base constant can absorb it; a is set so that the effect's RMS on the
// outlet force over all rows is k x the noise sd, k uniform in [2.5, 6].
// Aliases: the carrier, every column whose row partition equals the
// carrier's with at most 12 groups, and every numeric column that is a
// strictly monotone function of a numeric carrier (the same quantity in other
// units); for the pressure law, the loop's pressure names (avg_pressure_MPa,
// pin, pin_diameter_mm, inv_R_per_mm, back_tension_N; as synth.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "loop/blind_synth.hpp"  // BlindTruth: the truth record both generators share
#include "loop/measured.hpp"

namespace drawbend::loop {

struct WildOptions {
  std::string cls = "random";  ///< one of wild_classes(), or "random"
  double noise_N = 3;
  std::uint64_t seed = 1;
};

/// level, smooth, interaction, channel, test-level, null.
const std::vector<std::string>& wild_classes();

/// One data set (throws std::invalid_argument on an unknown class).
Dataset synthesize_wild(const WildOptions& o, BlindTruth& truth);
/// The truth as JSON ("generator": "wild").
std::string wild_truth_json(const BlindTruth& t);

}  // namespace drawbend::loop
