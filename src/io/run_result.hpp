#pragma once
// The answer of a run, kept in the run folder: <out>/result.toml.
//
// Every completed run writes result.toml (run_case calls write_run_result at
// its end).  It always holds:
//   [run]       the case, its deck, simulated time, cycles;
//   [[contact]] per contact pair: the friction law, its clamp counts (the
//               evaluations a tabulated mu(p, v) law clamped to its domain,
//               friction/surface_law.hpp) with their share of all evaluations,
//               and the share of the contact area outside the law's domain at
//               the end of the run (pressure, speed);
// and, when the deck is a draw-bend case (it records the history signals
// outlet_force_N and back_tension_N of core/run_output.hpp and has a step named
// "draw", as the draw-bend builder's decks do):
//   [drawbend]  F_X, F_Y (mean of the last third of the draw step), F_Y - F_X,
//               F_B with its source, the friction force F_Y - F_X - F_B and mu
//               by Eq. (2.3) (90 deg wrap), each on the full strip and on the
//               half model, the mean contact pressure and Eq. (2.2)'s.
//
// Basis.  A deck that fixes the y displacement of the node set "ymin" in every
// step models half the strip (symmetry plane y = 0): full-strip forces are
// twice the model's.  Otherwise the model is the whole strip (factor 1).
// Signs.  F_X = -back_tension_N (the load pulls the inlet along -x) and
// F_Y = -outlet_force_N (the outlet grip pulls along -z): both positive in
// tension, as a test measures them.
//
// F_B.  Given (ResultOptions::bending_force, on ResultOptions::basis), else
// for a frictionless pin contact F_Y - F_X of this run, else Swift's estimate
// Eq. (2.1) with ResultOptions::yield_stress (0: Table 5.1, RD, as
// `drawbend-deck --run` always did).  `drawbend run` and `drawbend-deck --run`
// print the same lines (print_drawbend_answer) from the same numbers.
// Units: N, MPa, mm, s.
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "fe/solver.hpp"
#include "io/deck.hpp"

namespace drawbend::io {

inline constexpr const char* kResultFile = "result.toml";

/// How a draw-bend run's answer is reduced and shown.
struct ResultOptions {
  std::string basis = "full";  ///< basis of bending_force and of the printed lines: "full" or "half"
  double bending_force = 0;    ///< F_B [N] on `basis` (0: this run if frictionless, else Swift)
  double yield_stress = 0;     ///< [MPa] of Swift's estimate (0: Table 5.1, RD)
};

/// The draw step's forces of a history table, in the deck's signals (half model
/// for the builder's decks) with tension positive [N].
struct DrawForces {
  double F_back = 0;            ///< F_X: -back_tension_N at the end of the draw
  double F_out = 0;             ///< F_Y: mean of -outlet_force_N over the last third of the draw
  double F_out_std = 0;         ///< its standard deviation over that third
  double F_out_regression = 0;  ///< F_Y of a linear fit of the last quarter, read at its end
  std::size_t samples = 0;      ///< draw-step rows
};
/// Throws InputError naming the file when the draw step has fewer than 12 rows.
DrawForces draw_forces(const CsvTable& history);

/// True when `deck` records outlet_force_N and back_tension_N and has a "draw" step.
bool is_drawbend_deck(const Deck& deck);
/// 2 when the deck models half the strip (the "ymin" set held in y in every step), else 1.
double full_strip_factor(const fe::Model& m);

/// One line per history column that needs it: what a force column is, its
/// basis and sign; written as comments at the top of history.csv.
std::vector<std::string> history_notes(const Deck& deck);

/// The draw-bend answer on both bases.
struct DrawBendAnswer {
  double factor = 2;          ///< full strip / model
  double F_X = 0, F_Y = 0, F_Y_std = 0, F_B = 0;  ///< on the model (half strip when factor = 2) [N]
  std::string F_B_source;     ///< "given", "frictionless run" or "Swift, Eq. (2.1), yield stress ... MPa"
  bool frictionless = false;  ///< the pin contact has no friction law
  double mu = 0;              ///< Eq. (2.3); NaN when not defined
  std::string mu_note;        ///< why mu is not defined ("" when it is)
  double pin_radius = 0, full_width = 0, thickness = 0;  ///< [mm]
  double mean_pressure = 0;   ///< area-weighted over the pin's contact nodes at the end [MPa]
  double eq22_pressure = 0;   ///< Eq. (2.2) from F_X, F_Y [MPa]
};
/// Throws InputError when the draw step is too short (draw_forces).
DrawBendAnswer drawbend_answer(const Deck& deck, const fe::Solver& s, const CsvTable& history,
                               const ResultOptions& opt);
/// The console lines of `drawbend-deck --run` on opt.basis.
void print_drawbend_answer(const DrawBendAnswer& a, const std::string& basis, std::ostream& out);

/// Write <out_dir>/result.toml (and print the draw-bend answer to `log`);
/// called by run_case once the history is saved.
void write_run_result(const Deck& deck, const fe::Solver& s, const std::string& out_dir, const ResultOptions& opt,
                      std::ostream& log);

}  // namespace drawbend::io
