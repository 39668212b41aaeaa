#pragma once
// Chapter 8: closing the loop at the model level (issue 23).  Shared types of
// the chapter's steps.  Forces full strip [N] unless "half"; lengths mm.
#include <string>
#include <vector>

#include "sim/drawbend_case.hpp"
#include "sim/model_loop.hpp"
#include "study/chapter.hpp"
#include "study/thesis_data.hpp"

namespace ch8 {

using drawbend::study::Chapter;

struct Config {
  drawbend::sim::DrawBendSpec base;  ///< quick-tier mesh from sim/fe_options (mass scaling at 100 mm/s)
  int run_fe = 1, reuse_runs = 0;
  int full_study = 0;      ///< 1: the full tier's candidates, slopes and numerical studies
  double fit_pin = 12.7;   ///< the training pin [mm]
  double min_gain = 0.03;  ///< required fall of the held-out RMS relative error
  std::string candidates;  ///< comma-separated candidate names; empty: the tier's list
  int numerics = -1;       ///< 1/0: run the numerical studies or not; -1: with --full-study
};

struct Inputs {
  std::vector<drawbend::study::FitEntry> bending;  ///< Table 5.3
  std::vector<double> pins;                        ///< 12.7, 25.4, 42
  std::vector<double> fback;                       ///< Table 5.13, full strip [N], per pin
  drawbend::sim::DrawBendSpec base;                ///< Sec. 5.7.1 conditions on the chapter's mesh
  double thickness = 1.04;
  double measured(double pin, double fback) const;  ///< Table 5.3 fit [N]
};

Inputs load_inputs(Chapter& c, const Config& cfg);
/// The bending-force loop: before/after per pin, figure, checks.  Returns the final model.
drawbend::sim::ModelLoopResult bending_force_loop(Chapter& c, const Inputs& in, const Config& cfg);
/// F_B against back tension on the fit pin (slope check).
void tension_slope(Chapter& c, const Inputs& in, const Config& cfg, const drawbend::sim::ModelLoopResult& loop);
/// Full tier: mass scaling on every pin, elements across on the 25.4 and 42 mm pins.
void numerical_convergence(Chapter& c, const Inputs& in, const Config& cfg);

}  // namespace ch8
