#pragma once
// The draw-bend model of Chapters 2-5: a builder that makes the case deck (a
// typed io::CaseSpec, written with io::to_toml) from a few physical
// parameters, runs it with the solver, and reduces the run to the thesis's
// quantities.  The deck is written next to the results, so a reader
// can rerun or edit it with `drawbend run` without recompiling.
//
// The model (Secs. 2.2, 3.4, 4.2): the top half of the strip by symmetry
// (y = 0 plane), thickness 1.04 mm, a pin of diameter D with a 90 deg wrap,
// and the thesis's three steps:
//   1. "bend":    the outlet end moves on a circle and bends the straight
//                 strip round the pin; the inlet end slides along the strip
//                 under the back tension so that the strip is drawn in, not
//                 stretched (bend_inlet_slides, the default), or is clamped
//                 (Sec. 4.2; the decks before issue 51), which stretches the
//                 strip by ~1.3 % on the way;
//   2. "tension": back tension ramped on the inlet end (held from step 1 if
//                 it slides), outlet held, with dynamic relaxation so that
//                 step 3 starts quiet;
//   3. "draw":    the outlet end moves at `speed` while the inlet end follows
//                 under constant back tension, over `draw_length`.
// Forces are half-model forces [N]; lengths mm, pressure MPa, time s.
#include <string>
#include <vector>

#include "analysis/new_method.hpp"
#include "core/csv.hpp"
#include "core/run_output.hpp"
#include "io/case_spec.hpp"
#include "io/run_result.hpp"

namespace drawbend::sim {

using run_output::Signal;  // the history signals of a draw-bend run

struct DrawBendSpec {
  std::string name = "drawbend";
  double pin_diameter = 12.7;   ///< D [mm]
  double thickness = 1.04;      ///< t [mm]
  double width = 12.7;          ///< modelled (half) width [mm]
  double back_tension = 756.2;  ///< F_X on the half model [N]
  double speed = 100.0;         ///< outlet speed in step 3 [mm/s]
  double draw_length = 0;       ///< slide in step 3 [mm]; 0: 1.5 wrap lengths + 6 mm (Sec. 2.3.2)
  /// Friction of the pin contact, e.g. io::coulomb_friction(0.1) (io/case_spec.hpp);
  /// none: frictionless (the rotating pin).  The case's description names it with io::friction_text.
  std::optional<io::FrictionSpec> friction;
  double element_length = 0.5;  ///< along the strip in the refined zone [mm]
  int across = 2;               ///< elements across the half width
  int through = 4;              ///< elements through the thickness
  double mass_scaling = 1e4;    ///< uniform density factor
  double penalty = 0.1;         ///< contact penalty scale
  std::string hardening;        ///< hardening-curve CSV (plastic strain, true stress)
  /// The material (sim/material_choice.hpp): empty = isotropic J2 on `hardening`; a TOML inline
  /// table of [material] keys, or a TOML file with a [material] table.
  std::string material;
  std::string strip_direction = "rd";  ///< the strip's axis is RD ("rd") or TD ("td")
  int snapshots = 4;            ///< contact maps / VTU snapshots in the draw step
  /// Step 1 with the inlet end sliding along the strip (x) under the back
  /// tension, ramped over the first half of the step, which lasts 3 times as
  /// long as the clamped one.  true (the default of every chapter's decks
  /// since issue 51): the strip is drawn in, not stretched, the inlet leg
  /// stays elastic until it bends, and F_B on the 42 mm pin is within 3 % of
  /// beam theory (verification drawbend_prestretch.*).  false (the decks
  /// before issue 51, kept for reproduction; Sec. 4.2 says the inlet end was
  /// fixed while the strip was bent "loosely"): the inlet end is clamped, and
  /// the outlet end's circle about (a, a), which keeps the strip's length only
  /// at its end, needs up to 1.1 mm more strip on the way (2.3 % of the outlet
  /// part at 30 deg on the 42 mm pin): the whole strip is stretched
  /// plastically by about 1.3 % (0.65 % thinner) before the test, which
  /// hardens the material that later enters the bend (the source of the F_B
  /// excess over beam theory, largest where the bending strain is smallest).
  /// Sliding free of tension, or at the clamped step's pace, leaves the strip
  /// loose on the pin and it snaps taut later, which yields the inlet leg
  /// instead (docs/issue51-large-pin.md).
  bool bend_inlet_slides = true;
  /// The strip's free edge (the set ymax) held in y in every step: plane
  /// strain across the width, the width condition of plane-strain beam
  /// theory (analysis::bend_unbend's default constraint) and of 2-D
  /// plane-strain codes.  false (the default): the edge is free, as on the
  /// real strip, and F_B lies below plane strain by the edges' relaxation (on
  /// the 42 mm pin 3.9 % with 2 elements across, 5.9 % with 4 or 8;
  /// docs/issue51-large-pin.md).
  bool plane_strain_width = false;
};

/// Mid-surface wrap length (D/2 + t/2) * pi/2 [mm].
double wrap_length(const DrawBendSpec& s);
/// The slide of step 3 [mm].
double draw_length(const DrawBendSpec& s);

/// The case deck for the spec, typed (io/case_spec.hpp); throws InputError naming a bad field.
io::CaseSpec drawbend_case(const DrawBendSpec& s);
/// The deck's text: io::to_toml(drawbend_case(s)).
std::string deck_text(const DrawBendSpec& s);

/// One node of the pin contact map [MPa, mm, mm^2].
struct MapNode {
  double angle_deg = 0;  ///< position round the pin from the inlet tangent point (0) to the outlet one (90)
  double y = 0;          ///< reference position across the width, 0 = strip centre (symmetry plane)
  double pressure = 0;
  double area = 0;
};

struct DrawBendResult {
  DrawBendSpec spec;
  std::string dir;                      ///< run directory (deck, history, maps, VTU)
  double F_back = 0;                    ///< F_X: applied back tension [N]
  double F_out = 0;                     ///< F_Y: outlet tension, mean of the last third of step 3 [N]
  double F_out_regression = 0;          ///< F_Y from a linear regression of the last 25 % at its end [N]
  double F_out_std = 0;                 ///< standard deviation over the last third [N]
  std::vector<MapNode> map;             ///< contact map at the end of step 3
  std::string map_file;                 ///< the solver's contact-map CSV it was read from
  double balance_error = 0, hourglass_ratio = 0, kinetic_ratio = 0, max_penetration = 0;
  double wall_seconds = 0;
  long cycles = 0;
  CsvTable history;                     ///< the run's history.csv

  /// F_Y - F_X [N]: the bending force on a frictionless pin.
  double tension_rise() const { return F_out - F_back; }
  /// The map as the new method needs it (nodal pressure and area, half model).
  analysis::PressureMap pressure_map(const std::string& label) const;
  /// A history signal over the draw step: (time since the draw began [s],
  /// sign x value), e.g. draw_series(Signal::outlet_force, -1) for F_Y [N].
  std::vector<std::pair<double, double>> draw_series(run_output::Signal column, double sign = 1) const;
  /// Average contact pressure over the nodes in contact [MPa] (area weighted).
  double mean_pressure() const;
  /// Outside-surface strain at a point of the wrap against the slide in the
  /// draw [mm]: for each slide s, the strain of the section that is at
  /// `fraction` of the wrap then (0.5 = mid-wrap, 1 = the exit tangent).
  /// Sections start at x = Lw/2 - k h after step 1, where the wrap holds
  /// x = 0 (entry) to Lw (exit), so section k is at fraction f after a slide
  /// k h + (f - 1/2) Lw (Sec. 2.3.2).
  std::vector<std::pair<double, double>> wrap_strain(double fraction) const;
  /// Slide [mm] after which that strain stays within `band` (relative) of
  /// its last value: the "steady strain condition" of Sec. 2.3.2.  NaN
  /// without strain sections.
  double steady_strain_slide(double band, double fraction) const;
};

/// A finished run of the same case under one of `roots` (each a folder of run
/// directories, such as another chapter's runs/): a directory whose deck.toml
/// is, byte for byte, the deck of `s` under that directory's own case name,
/// with a summary (written last, so the run completed).  The first such
/// directory by root, then by name; "" if none.  Unreadable roots are skipped.
std::string find_same_run(const DrawBendSpec& s, const std::vector<std::string>& roots);

/// Write the deck to `dir`/deck.toml, run it (one line of progress per step
/// unless quiet) and reduce it.  With `reuse`, a run whose directory already
/// holds the identical deck and a complete summary is read, not rerun.
/// Otherwise, if find_same_run(s, runs_from) finds the case already run
/// elsewhere (a chapter that ran before this one in the same build: RUNS_FROM
/// in chapters/CMakeLists.txt), that run is read in place (the result's dir is
/// its directory) and nothing is written to `dir`: every case is
/// deterministic, so a second run would give the same bits.
/// `result`: how the run's result.toml states F_B and which basis it prints (io/run_result.hpp).
DrawBendResult run_drawbend(const DrawBendSpec& s, const std::string& dir, bool reuse = false, bool quiet = true,
                            const std::vector<std::string>& runs_from = {}, const io::ResultOptions& result = {});

}  // namespace drawbend::sim
