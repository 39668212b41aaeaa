#pragma once
// Chapter 8: closing the loop at the model level (issue 23).  Shared types of
// the chapter's steps.  Forces full strip [N] unless "half"; lengths mm.
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/bending_work.hpp"
#include "core/csv.hpp"
#include "sim/drawbend_case.hpp"
#include "modelloop/model_loop.hpp"
#include "study/chapter.hpp"
#include "study/thesis_data.hpp"

namespace ch8 {

using drawbend::study::Chapter;

struct Config {
  drawbend::sim::DrawBendSpec base;  ///< quick-tier mesh from sim/fe_options (mass scaling at 100 mm/s)
  bool run_fe = true, reuse_runs = false;
  /// Comma-separated folders of runs made before this chapter (Chapter 5's
  /// runs/ in the build: its baselines are this chapter's); a case whose deck
  /// is one of theirs but for the name is read there, not rerun.
  std::string runs_from;
  std::vector<std::string> run_folders() const {
    std::vector<std::string> out;
    for (auto& f : drawbend::split_csv_line(runs_from))
      if (!f.empty()) out.push_back(std::move(f));
    return out;
  }
  bool full_study = false;  ///< the full tier's candidates, slopes and numerical studies
  double fit_pin = 12.7;    ///< the training pin [mm]
  double min_gain = 0.03;   ///< required fall of the held-out RMS relative error
  std::string candidates;   ///< comma-separated candidate names; empty: the tier's list
  bool cup = true;                ///< the cup loop and attribution (step 6)
  std::string numerics = "auto";  ///< the numerical studies: true, false, or auto (= full_study)
  std::string next = "auto";      ///< Voce and Hill'48 after the back stress: true, false, or auto (= full_study)

  /// Whether step 3 (the numerical studies) runs; throws std::invalid_argument
  /// naming --numerics on a value other than true/false/auto (or 1/0/-1).
  bool run_numerics() const { return tri_state(numerics, "--numerics"); }
  /// Whether the tier's list goes on after the back stress with Voce and
  /// Hill'48 (std::invalid_argument naming --next-candidates as above).
  bool run_next() const { return tri_state(next, "--next-candidates"); }

 private:
  bool tri_state(const std::string& v, const char* option) const {
    if (v == "true" || v == "1") return true;
    if (v == "false" || v == "0") return false;
    if (v == "auto" || v == "-1") return full_study;
    throw std::invalid_argument(std::string(option) + ": expected true, false or auto, found '" + v + "'");
  }
};

struct Inputs {
  std::vector<drawbend::study::FitEntry> bending;  ///< Table 5.3
  std::vector<double> pins;                        ///< 12.7, 25.4, 42
  std::vector<double> fback;                       ///< Table 5.13, full strip [N], per pin
  drawbend::sim::DrawBendSpec base;                ///< Sec. 5.7.1 conditions on the chapter's mesh
  double thickness = 1.04;
  double measured(double pin, double fback) const;  ///< Table 5.3 fit [N]
};

/// One beam-theory model and its F_B per pin (full strip, N).
struct BeamModel {
  std::string label;
  drawbend::analysis::BendMaterial mat;
  std::vector<double> fb;
  bool thinning = false;  ///< the section thins as the strip stretches (BendCase::thinning)
};
/// One member of the Armstrong-Frederick grid and its F_B per pin.
struct GridMember {
  double x_sat = 0, gamma = 0;  ///< MPa, -
  std::vector<double> fb;       ///< beam theory, plane strain, per pin of Inputs::pins (full strip, N)
};
/// Beam theory's trace of the residual (ch8_beam_trace.cpp).
struct BeamTrace {
  std::vector<BeamModel> models;  ///< isotropic plane strain, plane stress, Hosford 8, isotropic plane strain thinning, AF chosen, AF in-sample
  BeamModel best_fit, best_all;   ///< the Armstrong-Frederick member chosen on the fit pin; best on all pins
  BeamModel best_slow;            ///< the member chosen on the fit pin among gamma <= 30 (slow back stresses)
  double chosen_x = 0, chosen_gamma = 0;  ///< best_fit's X_sat [MPa] and gamma
  /// Per pin of Inputs::pins: (X_sat [MPa], gamma) of the member chosen on that pin alone.
  std::vector<std::pair<double, double>> af_on_pin;
  double slope_meas = 0;                  ///< Table 5.3's slope on the fit pin
  double slope_lo = 0, slope_hi = 0;      ///< the members' range of dF_B/dF_back on the fit pin over Table 5.3's range
  int members = 0;
  std::vector<GridMember> grid;           ///< every member of the grid (those with an elastic range left)
};

Inputs load_inputs(Chapter& c, const Config& cfg);
/// A relative error as a signed percentage with one decimal ("+10.6").
inline std::string pct(double x) { return (x >= 0 ? "+" : "") + drawbend::fmt_fixed(100 * x, 1); }
/// The bending-force loop: before/after per pin, figure, checks, and the
/// leave-one-pin-out blind errors (each pin's error from the fold that never
/// saw it).  Returns the in-sample final model.
/// `trace` leads the tier's chaboche candidate: the beam's choice on the fit
/// pin and its neighbours in X_sat, chosen again by the FE.
drawbend::modelloop::ModelLoopResult bending_force_loop(Chapter& c, const Inputs& in, const Config& cfg,
                                                  const BeamTrace& trace);
/// Isotropic in plane strain and plane stress, Hosford a = 8, and the
/// Armstrong-Frederick grid chosen on the fit pin (milliseconds per point).
BeamTrace beam_trace(Chapter& c, const Inputs& in, const Config& cfg);
/// The trace's table and values; `loop` (may be null) adds the FE rows.
void save_beam_trace(Chapter& c, const Inputs& in, const BeamTrace& t, const drawbend::modelloop::ModelLoopResult* loop);
/// F_B against back tension on the fit pin (slope check).
void tension_slope(Chapter& c, const Inputs& in, const Config& cfg, const drawbend::modelloop::ModelLoopResult& loop);
/// Issue 51 item 4: whether one force on a fold's fit pin identifies the back
/// stress.  Per fold, the grid members that fit its fit pin as well as the
/// beam can tell (band: the FE-vs-beam difference there), their range on the
/// pin the fold left out, where the fold's member sits, and the verdict
/// (ch8_identify.cpp).
void identification(Chapter& c, const Inputs& in, const BeamTrace& t, const drawbend::modelloop::BlindLoopResult& b);
/// Full tier: mass scaling on every pin, elements across on the 25.4 and 42 mm pins.
void numerical_convergence(Chapter& c, const Inputs& in, const Config& cfg);
/// The cup (Sec. 6.6): punch-force loop and the 2 x 2 attribution at 21 mm.
void cup_loop(Chapter& c, const Config& cfg, const drawbend::modelloop::ModelLoopResult& bending);

}  // namespace ch8
