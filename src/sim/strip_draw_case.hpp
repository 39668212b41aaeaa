#pragma once
// The strip-draw friction test of Chapter 3 (Sec. 3.3, Fig. 3.2): a builder
// that makes the case deck (a typed io::CaseSpec) from a few physical
// parameters, and a runner that draws the strip and reduces the run to
// mu = (F1 - F2) / F_N and the slip speed of a probe node under the die.  `drawbend strip-deck` writes the same
// deck for `drawbend run`.
//
// The model: a strip section (length x width x thickness, from the origin) on
// a fixed flat support (z = 0), pressed by a force-driven flat die on its top
// face, then drawn along x by velocities on both ends.  Two steps:
//   1. "press": the die force ramps to p x length x width over `force_ramp`,
//      with damping; the ends held along x (xmin) and y (ymin);
//   2. "draw":  both ends move along x, the speed ramped to `speed` over
//      `speed_ramp`, for speed_ramp + max(slide / speed, 2 speed_ramp).
// The die's friction is the Stribeck law of Table 3.1 (Eqs. 3.1-3.2) updated
// every `interval` cycles unless `friction` names another law; the support is
// frictionless.  Units: mm, N, MPa, s, t/mm^3.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/case_spec.hpp"
#include "io/deck.hpp"

namespace drawbend::sim {

struct StripDrawSpec {
  std::string name = "strip_draw";  ///< the case name (and its run folder's name)
  double length = 4.0, width = 2.0;  ///< the strip section under the die [mm]
  double thickness = 1.04;           ///< [mm]
  int nx = 8, ny = 4, nz = 4;        ///< elements along, across, through
  double pressure = 10.0;            ///< die pressure: die force / (length x width) [MPa]
  double speed = 8.0;                ///< drawing speed [mm/s]
  double slide = 0.4;                ///< drawn distance after the speed ramp (at least 2 ramps' time) [mm]
  double speed_ramp = 0.01;          ///< [s]
  double force_ramp = 0.02;          ///< die force ramp of the press step [s]
  double press_time = 0.05;          ///< [s]
  double press_damping = 200.0;      ///< mass-proportional damping of the press step [1/s]
  /// Time step [s]; 0: strip_draw_time_step(speed).
  double time_step = 0;
  /// Die mass [t]; 0: the mass that puts the die on its contact springs at
  /// omega dt = 0.5 (strip_draw_die_mass).
  double die_mass = 0;
  std::string hardening;             ///< hardening-curve CSV (plastic strain, true stress [MPa])
  std::string stribeck_table;        ///< Stribeck parameters (Table 3.1 format) for the default law
  int interval = 100;                ///< Stribeck update interval [cycles]
  /// Friction of the die, e.g. io::coulomb_friction(0.1) (io/case_spec.hpp);
  /// none: the Stribeck law on `stribeck_table` with `interval`.
  std::optional<io::FrictionSpec> friction;
};

/// The spec with the data files of this tree: the RD hardening curve of
/// AA5754-O and Table 3.1's Stribeck parameters.
StripDrawSpec default_strip_draw_spec(const std::string& data_dir);

/// The time step of a draw at speed v [mm/s]: 1e-5 s below 4 mm/s, 5e-7 s
/// above 40 mm/s, 2.5e-6 s between.  Seconds per case while the contact
/// dynamics settle; the fastest case needs less mass scaling, as in the
/// thesis (Sec. 3.3.3: case 5 ran with mass scaling 10 instead of 1000 "to
/// avoid possible dynamic effects").
double strip_draw_time_step(double v);

/// Duration of the draw step [s].
double strip_draw_duration(const StripDrawSpec& s);

/// The case deck, typed (io/case_spec.hpp); throws InputError naming a bad field.
io::CaseSpec strip_draw_case(const StripDrawSpec& s);
/// The deck's text: io::to_toml(strip_draw_case(s)).
std::string strip_draw_deck_text(const StripDrawSpec& s);
/// The deck parsed (file names in it are absolute).
io::Deck strip_draw_deck(const StripDrawSpec& s);

/// One strip draw, reduced.
struct StripDrawResult {
  double mu = 0;                     ///< mean |F_t| / mean |F_n| on the die over the last third
  double p_mean = 0, p_spread = 0;   ///< pressure under the die at the end [MPa]; (max - min) / p
  double v_mean = 0, v_std = 0, v_min = 0, v_max = 0;  ///< probe slip speed over the last third [mm/s]
  double ramp_v_max = 0;             ///< largest probe slip speed while the speed ramps up [mm/s]
  long cycles = 0;
  std::vector<std::pair<double, double>> trace;         ///< (time in the draw step [s], probe slip speed [mm/s]), every 20 cycles
  std::map<std::pair<double, double>, double> die_map;  ///< die pressure [MPa] at the end, by reference (x, y) [mm]
};

/// Build the deck and draw in memory (no files written), with the reduction a
/// run folder keeps (io/case_reduction.hpp, kind strip_draw; the probe is the
/// die contact node nearest the centre of the die): the same bits as run_strip_draw_job.
StripDrawResult run_strip_draw(const StripDrawSpec& s);
/// The result of a finished run folder of `s` (its reduction.csv; p_spread
/// needs s.pressure); InputError naming the file if absent.
StripDrawResult read_strip_draw_run(const StripDrawSpec& s, const std::string& dir);
/// The case as a file-level job (sim/deck_job.hpp): deck.toml in `dir`, `drawbend
/// run` through the executor (reused with `reuse` if the deck is unchanged), then read_strip_draw_run.
StripDrawResult run_strip_draw_job(const StripDrawSpec& s, const std::string& dir, bool reuse = false);
/// run_strip_draw_job for every spec through the case pool (sim/case_pool.hpp),
/// in spec order, each in `runs`/<its name> (names must differ).
std::vector<StripDrawResult> run_strip_draws(const std::vector<StripDrawSpec>& specs, const std::string& runs,
                                             bool reuse = false);

}  // namespace drawbend::sim
