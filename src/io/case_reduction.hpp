#pragma once
// A study's own reduction of a run, kept by the run itself, so that a case is a
// file-level job (`drawbend run` on any machine) whose run folder holds what
// the study needs bit for bit.
//
// A deck names it in [output]:
//   reduce = { kind = "block_slide", tool = "floor", step = "slide" }
//   reduce = { kind = "strip_draw", tool = "die", step = "draw", ramp = 0.01 }
//   reduce = { kind = "cup_draw", tool = "punch", step = "draw", holder = "lower_die", every = 75 }
//   reduce = { kind = "earing_cup", tool = "punch", step = "draw", stroke = 45, every = 200 }
// and io::run_case feeds it every cycle, then writes <out>/reduction.csv:
// rows `quantity, x, y, value`, every number as the shortest text that reads
// back as the same double (fmt_shortest), so a reader gets the in-memory bits.
//
// Kinds (the builders that write them: sim/block_case, sim/strip_draw_case):
// - block_slide: over the last third of `step` (step time >= 2/3 of its
//   duration), the sums of the tool's force F_x, F_y and |F_z| [N] each cycle;
//   rows mu_x = sum F_x / sum |F_z|, mu_y likewise; at the end over the tool's
//   contact nodes p_min, p_max [MPa] and v_mean [mm/s] (mean slip speed);
//   cycles.
// - strip_draw: the probe is the tool's contact node nearest (current x, y) the
//   centre of the mesh's reference x-y extent when `step` begins (the first on
//   ties); over `step`: its slip speed every 20th cycle (rows `trace`, x = time
//   since the step began [s], value [mm/s]); ramp_v_max, its largest slip speed
//   while the step time is below `ramp` [s]; over the last third, mu = mean
//   |F_x| / mean |F_z| of the tool, the probe's v_mean, v_std, v_min, v_max;
//   at the end p_min, p_max, p_mean over the tool's contact nodes and rows
//   `pressure` (x, y = the node's reference position [mm]); cycles.
// - cup_draw (sim/cup_case; a quarter model, forces times 4): every `every`-th
//   cycle of `step` (by the run's cycle count) a row `curve` (x = the punch
//   `tool`'s travel since the step began [mm], value = -4 F_z [N]) and the
//   clamping force die_force = 4 |F_z| of the `holder` tool; at the end
//   size_rd, size_td (twice the largest x on y = 0, y on x = 0 of node set
//   "rim"), kinetic_ratio, hourglass_ratio (over the internal energy),
//   added_mass_ratio, die_lift (the holder's offset z), cycles, and per element
//   rows `centroid` (x, y, value = z [mm]) and `state` (x = plastic strain,
//   y = von Mises stress [MPa]).
// - earing_cup (chapter v1-earing-benchmark; a quarter model, forces times
//   4; io/earing_reduction.cpp): over `step`, with the punch `tool`'s travel d
//   since the step began [mm]: every `every`-th cycle a row `curve` (x = d,
//   value = -4 F_z [N]); the hourglass work of every element summed over the
//   cycles; the largest kinetic / internal energy once d > stroke / 10; at the
//   first cycle of each tenth of `stroke` (and at the end if the last tenth
//   was not reached) a row `hourglass` (x = d, value = its number) and per
//   element rows `hg_work` (x = radius, y = z of the element's centre [mm],
//   value = the work so far [mJ]) and `hg_stored` (x, y, value: the energy in
//   its hourglass springs by mode, xi*eta in plane, twist, xi*eta*zeta [mJ]).
//   At the end cycles, kinetic_ratio, max_kinetic_ratio, hourglass_ratio,
//   balance_error, added_mass_ratio, and per node a row `node` (x, y,
//   value = z: its current position [mm]).
// The order of every sum is the order of the cycles and of the contact nodes:
// deterministic for any thread count.  A restarted run cannot keep a reduction
// (its sums began before the checkpoint): run_case refuses one.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "fe/solver.hpp"
#include "io/deck.hpp"

namespace drawbend::io {

/// One row of reduction.csv: a scalar (x, y NaN) or a point of a series or map.
struct ReducedValue {
  std::string quantity;
  double x = NAN, y = NAN, value = NAN;
};

/// The accumulator of one kind.
class CaseReduction {
 public:
  virtual ~CaseReduction() = default;
  /// After every cycle (the solver's on_cycle).
  virtual void cycle(const fe::Solver& s, const fe::Progress& p) = 0;
  /// At the end of the run: the rows of reduction.csv.
  virtual std::vector<ReducedValue> finish(const fe::Solver& s) const = 0;
};

/// The kinds known: block_slide, strip_draw, cup_draw, earing_cup.
const std::vector<std::string>& reduction_kinds();

/// Where a reduction reads: the index of the step named `r.step` and of the
/// last contact pair on `r.tool` (InputError naming output.reduce.* if either
/// is missing).  In io/reduction_place.cpp, apart from the reductions, so the
/// deck reader checks a deck without the solver.
struct ReductionPlace {
  int step = -1, pair = -1;
};
ReductionPlace reduction_place(const ReductionSpec& r, const fe::Model& m);

/// The deck reader's check of `[output] reduce`: its kind is known and its
/// tool and step exist (InputError otherwise).
void check_reduction(const ReductionSpec& r, const fe::Model& m);
/// The earing_cup accumulator (io/earing_reduction.cpp).
std::unique_ptr<CaseReduction> make_earing_reduction(const ReductionSpec& r, const fe::Model& m);
/// The accumulator for `r` on `m`; throws InputError naming a tool without a
/// contact pair or an unknown step.
std::unique_ptr<CaseReduction> make_reduction(const ReductionSpec& r, const fe::Model& m);

/// File name in a run folder.
inline constexpr const char* kReductionFile = "reduction.csv";
void write_reduction(const std::string& path, const std::string& what, const std::vector<ReducedValue>& rows);
/// The rows of a reduction.csv, bit for bit as written; throws InputError naming the file on a bad row.
std::vector<ReducedValue> read_reduction(const std::string& path);
/// The value of scalar `quantity`; throws InputError naming the file if absent.
double reduced(const std::vector<ReducedValue>& rows, const std::string& quantity, const std::string& path);

}  // namespace drawbend::io
