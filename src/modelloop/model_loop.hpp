#pragma once
// The model-level loop: candidate modelling effects are tested by re-running
// the finite-element draw-bend model (rotating = frictionless pin) and
// comparing its bending force F_B = 2 (F_Y - F_X) (full strip, N) with
// measured values.
//
// Held-out protocol: the points on the `fit pin` train, the points on every
// other pin are held out.  A candidate is a family of members (e.g. split
// combined hardening with beta = 0.3, 0.6); the member with the smallest RMS
// relative error on the fit pin is chosen without looking at the held-out
// pins, then run on them.  The candidate is accepted into the model only if
// the held-out RMS relative error falls by more than `min_gain` (absolute,
// e.g. 0.03 = 3 percentage points).  Candidates are tried in the given order
// (greedy): an accepted candidate is the base of the next one.
//
// The held-out pins above choose the model (a candidate is accepted on
// them), so their errors are not blind.  The honest split
// (run_model_loop_blind) runs the whole loop once per pin with that pin left
// out: members chosen on the remaining pin nearest the fit pin, candidates
// accepted on the other remaining pins, and only then the fold's final model
// run on the left-out pin.  Each pin's blind error comes from the fold that
// never saw it.  With three pins every fold fits on one pin and chooses on
// one.
//
// Files: fb_points.cpp (the measured points in, a points table out),
// selection.cpp (the loop and its folds), catalogue.cpp (the named
// candidates, one table row each), material_edits.* (how a candidate edits a
// spec's material).
//
// Every FE run goes through the case pool (sim/case_pool.hpp) and runs in
// run_root/fb_<hash of the deck text>: identical decks are one run, and with
// `reuse` a finished run is read back instead of rerun.
// Forces N (full strip in points and results, half model in the decks),
// lengths mm.
#include <functional>
#include <string>
#include <vector>

#include "material/hardening_curve.hpp"
#include "sim/drawbend_case.hpp"

namespace drawbend::modelloop {

using sim::DrawBendResult;
using sim::DrawBendSpec;

/// One measured bending force (full strip).
struct FbPoint {
  double pin_mm = 0;
  double back_tension_N = 0;  ///< F_X, full strip [N]
  double bending_N = 0;       ///< measured F_B, full strip [N]
  std::string where;          ///< file:line it came from
};

/// Read `pin_diameter_mm,back_tension_N,bending_force_N` (full strip) rows;
/// every bad cell is reported as file:line: column (InputError).
std::vector<FbPoint> read_fb_points(const std::string& csv_path);

/// One member of a candidate family: a label and how it changes the spec.
struct CandidateMember {
  std::string label;
  std::function<void(DrawBendSpec&)> apply;
};

struct ModelCandidate {
  std::string name;  ///< short id, e.g. "split_kinematic"
  std::string what;  ///< one line for tables
  std::vector<CandidateMember> members;  ///< >= 1; more than one: chosen on the fit pin
};

struct PointResult {
  FbPoint measured;
  double predicted_N = 0;  ///< F_B of the model, full strip [N]
  double predicted_sd_N = 0;  ///< 2 x the std of F_Y over the last third of the draw (full strip) [N]
  bool held_out = false;
  std::string run_dir;
  double wall_s = 0;
  double rel_error() const { return (predicted_N - measured.bending_N) / measured.bending_N; }
};

struct ModelEval {
  std::string model;  ///< labels of the accepted effects ("isotropic" for none)
  std::vector<PointResult> points;
  double fit_rms = 0, held_rms = 0, held_max = 0;  ///< relative errors (fractions)
};

struct StepRecord {
  std::string candidate, what, member, decision;  ///< decision: "accepted" or "rejected: ..."
  std::vector<std::pair<std::string, double>> member_fit_rms;  ///< each member's fit-pin RMS
  ModelEval eval;  ///< the chosen member on all points
  DrawBendSpec spec;  ///< the model with the chosen member applied (its material as a TOML inline table)
};

struct ModelLoopConfig {
  double fit_pin = 12.7;   ///< the training pin [mm]
  double min_gain = 0.03;  ///< required fall of the held-out RMS relative error
  std::string run_root;    ///< where run directories go
  bool reuse = true;
  /// Folders of runs made before (another chapter's runs/): a case whose deck
  /// is one of theirs but for the name is read there (sim::find_same_run).
  std::vector<std::string> runs_from;
};

struct ModelLoopResult {
  ModelEval baseline, final_model;
  DrawBendSpec final_spec;  ///< the base with every accepted candidate applied
  std::vector<StepRecord> steps;
  int runs = 0;            ///< distinct FE runs asked for
  double run_wall_s = 0;   ///< sum of the runs' wall times (single-thread CPU) [s]
};

/// Run specs through the case pool, each in run_root/fb_<hash of its deck
/// text> (the spec's name is set to "fb"); identical decks run once.  Results
/// in spec order.  `wall_s`, if given, gets the sum of the new runs' wall times.
std::vector<DrawBendResult> run_cached(std::vector<DrawBendSpec> specs, const std::string& run_root, bool reuse,
                                       double* wall_s = nullptr, const std::vector<std::string>& runs_from = {});

/// The spec for one point: `base` at the point's pin with half the back tension.
DrawBendSpec spec_for_point(const DrawBendSpec& base, const FbPoint& p);

/// Run the loop (see the top of this file).
ModelLoopResult run_model_loop(const DrawBendSpec& base, const std::vector<FbPoint>& points,
                               const std::vector<ModelCandidate>& candidates, const ModelLoopConfig& cfg);

/// One fold of the leave-one-pin-out split.
struct BlindFold {
  double pin_mm = 0;                 ///< the pin left out
  double fit_pin_mm = 0;             ///< the fold's fit pin (members chosen here)
  std::vector<double> select_pins;   ///< the fold's selection pins (candidates accepted here)
  std::string model;                 ///< the fold's final model
  std::vector<std::string> decisions;  ///< "candidate (member): decision", in order
  /// The left-out pin's points: the isotropic model and the fold's final
  /// model (predicted without the fold having seen them).
  std::vector<PointResult> baseline, final_model;
};

struct BlindLoopResult {
  ModelLoopResult in_sample;     ///< the loop on every pin (cfg.fit_pin fits, the rest choose)
  std::vector<BlindFold> folds;  ///< one per distinct pin, in the order of the points
  int runs = 0;                  ///< distinct FE runs over the in-sample loop and every fold
  double run_wall_s = 0;
};

/// The candidate list of a loop whose members are chosen on `fit_pin` [mm]
/// (a candidate whose grid was itself chosen on a pin, e.g. by beam theory,
/// must be chosen again on the fold's fit pin, or the fold has seen the pin
/// it leaves out).
using CandidatesFor = std::function<std::vector<ModelCandidate>(double fit_pin)>;

/// The in-sample loop and the leave-one-pin-out folds (see the top of this
/// file), sharing one set of runs: a deck run in one fold is read in the
/// others.  InputError with fewer than 3 distinct pins.
BlindLoopResult run_model_loop_blind(const DrawBendSpec& base, const std::vector<FbPoint>& points,
                                     const CandidatesFor& candidates_for, const ModelLoopConfig& cfg);

/// Named candidates for the command line and the chapter:
///   split:B1/B2/...   split combined hardening, kinematic fraction beta (fitted on the fit pin)
///   chaboche:X1/X2...[@G1/G2...] one Armstrong-Frederick back stress saturating at X (MPa), rate
///                     gamma G (default 300), every (X, G) pair a member,
///                     carved out of the flow curve (R = sigma - X, its non-decreasing envelope)
///   voce              the published Voce flow curve (data/materials/aa5754_o_voce_hou2020.toml)
///   hill48            the published Hill'48 r-values (data/materials/aa5754_o_hill48_hou2020.toml)
///   offset            Swift refitted with Table 5.1's 0.2 % offset yield stress at eps_p = 0.002
///                     (data/thesis/table_5_1.csv RD row): the flow curve below 1 % strain; the
///                     shipped RD table's own reading since issue 51, so now an analytic copy of it
///   ms:X              mass scaling X (numerical check)
///   across:N          N elements across the half width (numerical check)
/// Throws InputError for anything else.
ModelCandidate named_candidate(const std::string& name, const std::string& data_dir);

/// The isotropic part of the chaboche candidate: R_i = sigma_i - X_sat (1 -
/// exp(-gamma eps_i)) on the curve's strain grid, then its non-decreasing
/// lower envelope (the solver needs H >= 0).  Monotonic tension follows R + X
/// = sigma where the envelope does not cut, and lies below it at small strain
/// where it does (a lower elastic limit).  InputError if R(0) <= 0.
std::vector<double> carved_isotropic_part(const material::HardeningCurve& c, double x_sat, double gamma);

/// Write a points table (pin, back tension, measured, predicted, error, role).
void save_eval_csv(const ModelEval& e, const std::string& path);

}  // namespace drawbend::modelloop
