#pragma once
// Case decks: TOML files that describe a complete explicit analysis, so that a
// case changes without recompiling.  The format is documented in
// data/cases/README.md; every key is checked (a typo is an error, not
// silently ignored) and every message names the file, the line and the key.
#include <cstdint>
#include <string>
#include <vector>

#include "fe/model.hpp"

namespace drawbend::io {

/// The most OpenMP threads a deck's [numerics] threads or any command's
/// --threads may ask for.  More is an input error: libgomp could not create
/// them (100,000 on a model whose loops fork ended in a segmentation fault,
/// 2026-11-29), and no machine this runs on has more hardware threads.
inline constexpr int kMaxThreads = 1024;

/// What to record while a case runs.
struct HistorySignal {
  std::string name;     ///< column name
  std::string kind;     ///< "reaction", "applied" (node set) or "tool_force", "tool_offset" (tool)
  std::string target;   ///< node set or tool name
  int component = 0;    ///< 0, 1, 2 = x, y, z
  /// kind "strain": the element whose reference centroid is nearest `point`
  /// [mm]; component 0 = logarithmic strain along the element's reference x
  /// edges, 1 = equivalent plastic strain.
  fe::Vec3 point{0, 0, 0};
  /// Factor applied to the recorded value (e.g. -2 for a tension-positive
  /// full-strip force of a half model); 1 by default, finite and nonzero.
  double scale = 1;
};

/// A study's own reduction of the run, kept every cycle and written to
/// reduction.csv (io/case_reduction.hpp); kind "" = none.
struct ReductionSpec {
  std::string kind;  ///< "block_slide", "strip_draw", "cup_draw" or "earing_cup"
  std::string tool;  ///< the tool whose force (and contact pair) it reduces
  std::string step;  ///< the step it reduces
  double ramp = 0;   ///< strip_draw: the speed ramp of the step [s]
  std::string holder;  ///< cup_draw: the force-driven blank holder tool
  int every = 1;       ///< cup_draw, earing_cup: a curve point every this many cycles
  double stroke = 0;   ///< earing_cup: the punch stroke [mm] (its tenths are the snapshots)
};

struct OutputSpec {
  double history_interval = 0;  ///< [s]; 0: 200 samples per step
  int fields_per_step = 1;      ///< VTU snapshots per step (>= 1: at least the end of each step)
  bool vtk_ascii = false;       ///< vtk_format = "ascii": text VTU (default "binary": appended, zlib-compressed)
  std::vector<HistorySignal> history;
  ReductionSpec reduce;
};

/// Limits a deck can raise in [limits] (data/cases/README.md): every run has a
/// finite, predicted cost before it starts (deck_limits.hpp).
struct RunLimits {
  double max_cycles = 1e8;        ///< predicted cycles (end time / stable step)
  double max_memory_mb = 4096;    ///< predicted memory of the mesh and solver state [MB]
  double max_mass_factor = 1e9;   ///< (physical + added mass) / physical mass; a warning above 1 % of it
  double max_output_mb = 10240;   ///< predicted history.csv and field frames [MB] (10 GB)
};

/// The up-front estimate of a run (deck_limits.cpp).
struct CostEstimate {
  double stable_dt = 0;    ///< initial stable step with mass scaling [s] (0: not estimated)
  double cycles = 0;       ///< end time / stable_dt (a lower bound: the step shrinks as elements deform)
  double memory_mb = 0;    ///< mesh and solver state [MB]
  double mass_factor = 1;  ///< (physical + added mass) / physical mass
  double output_mb = 0;    ///< history.csv and the .vtu field frames [MB] (deck_limits.cpp)
  std::string material;    ///< the sheet's [material] type (j2, j2_combined, hill48, yld2004, elastic): its update's cost
};

struct Deck {
  std::string path;
  std::uint64_t hash = 0;  ///< FNV-1a of the deck's text (checkpoints must match it)
  fe::Model model;
  OutputSpec output;
  int threads = 0;  ///< 0: OpenMP default
  RunLimits limits;
  CostEstimate cost;
  /// Doubtful but valid values, "file:line: key: ..." (printed by run_case).
  std::vector<std::string> warnings;
};

/// Read and validate a deck; throws drawbend::InputError with file:line: key: message.
Deck read_deck(const std::string& path);
/// The same from a string (path used in messages and for relative file names).
Deck parse_deck(const std::string& text, const std::string& path);

}  // namespace drawbend::io
