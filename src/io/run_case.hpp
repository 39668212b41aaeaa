#pragma once
// Running a case deck: the solver plus its outputs and the console display.
//   <out>/history.csv          time, step, energies, dt, and the deck's signals
//   <out>/contact_<pair>_<k>.csv  contact map per slave node at each snapshot
//   <out>/fields_<k>.vtu, tool_<name>_<k>.vtp, <out>/fields.pvd   ParaView snapshots (sheet and tools)
//   <out>/summary.csv           end-of-run invariants (energy balance, ratios, added mass)
//   <out>/result.toml           the run's answer: forces, F_B, mu, friction-law clamps (io/run_result.hpp)
#include <csignal>
#include <iosfwd>
#include <string>

#include "fe/solver.hpp"
#include "io/deck.hpp"
#include "io/run_result.hpp"
#include "io/vtu.hpp"

namespace drawbend::io {

struct RunOptions {
  std::string out_dir = "out";
  bool quiet = false;      ///< no progress line
  double progress_every_s = 1.0;  ///< wall seconds between progress lines (> 0)
  int threads = 0;         ///< 0: the deck's or OpenMP's default
  /// Checkpoints to <out_dir>/checkpoint.bin every this much simulated time [s]
  /// or every this many cycles (0: none).
  double checkpoint_every_s = 0;
  long checkpoint_every_cycles = 0;
  std::string restart;     ///< checkpoint to continue from ("": start afresh)
  /// Stop right after the first checkpoint at or beyond this cycle (0: never),
  /// as an interruption would; for testing restarts.
  long halt_after_cycles = 0;
  /// Set (to the signal number) by a SIGINT/SIGTERM handler: the run writes
  /// <out_dir>/checkpoint.bin at the next cycle boundary, says how to continue
  /// and returns with RunSummary::interrupted set.  nullptr: not watched.
  const volatile std::sig_atomic_t* stop = nullptr;
  /// How result.toml reduces a draw-bend run (io/run_result.hpp).
  ResultOptions result;
};

/// Parse a --checkpoint-every value: "500" (cycles) or "2e-3s" (simulated seconds).
void parse_checkpoint_every(const std::string& spec, RunOptions& opt);

struct RunSummary {
  double time = 0;
  long cycles = 0;
  double energy_balance_error = 0;  ///< |KE + IE + HG + damping - W| / largest term
  double hourglass_ratio = 0;       ///< HG / IE
  double kinetic_ratio = 0;         ///< KE / IE at the end
  double added_mass_ratio = 0;      ///< added / physical mass
  double max_penetration = 0;       ///< [mm]
  double wall_seconds = 0;
  /// CPU time of the run's thread [s] when it ran on one thread (NaN otherwise:
  /// OpenMP's other threads are not counted); run.log's "cpu:" line, which
  /// `drawbend plan` prefers to wall x threads on a machine shared with others.
  double cpu_seconds = NAN;
  bool halted = false;              ///< stopped by halt_after_cycles (no final outputs)
  std::string checkpoint;           ///< last checkpoint written ("" if none)
  int interrupted = 0;              ///< the signal that stopped the run (0: none)
};

/// Write the contact map of every pair: position in global and tool
/// coordinates (cylinder/torus: angle about the axis [deg] and axial position;
/// plane: in-plane coordinates), pressure, area, forces, slip speed.
/// Files: contact_<snapshot>_<pair>.csv in `dir` (core/run_output.hpp).
void write_contact_maps(const fe::Solver& s, const std::string& dir, int snapshot);
/// Write a VTU snapshot of the sheet (io/frames.cpp; the fields in data/cases/README.md):
/// displacement, velocity, contact pressure, friction traction, slip rate,
/// accumulated slip, stick/slip status, local mu, sheet thickness (points);
/// stress, von Mises stress, plastic strain, log strain, sheet thickness and its
/// ratio, back stress and the material axes where the material has them (cells).
void write_fields(const fe::Solver& s, const std::string& path, VtkFormat format = VtkFormat::zlib);
/// Each tool's surfaces at the current time (io/tool_mesh.hpp) into
/// `dir`/tool_frame_name(tool, snapshot).
void write_tool_frames(const fe::Solver& s, const std::string& dir, int snapshot, VtkFormat format = VtkFormat::zlib);
std::string tool_frame_name(const std::string& tool, int snapshot);

RunSummary run_case(Deck& deck, const RunOptions& opt, std::ostream& log);

}  // namespace drawbend::io
