#pragma once
// Checkpoint files of `drawbend run`: the solver's full state (fe/checkpoint.cpp)
// plus what the run itself carries between cycles (history rows so far, next
// output times, snapshot list), tied to the deck by its hash.  Written
// atomically (temporary file, then rename): an interrupted write leaves the
// previous checkpoint intact.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "fe/solver.hpp"

namespace drawbend::io {

struct RunState {
  std::vector<std::vector<std::string>> history_rows;
  double next_hist = 0, next_field = 0;
  int current_step = -1, snap = 0;
  std::vector<std::pair<double, std::string>> snapshots;  ///< (time, .vtu file)
};

void write_checkpoint(const std::string& path, std::uint64_t deck_hash, const fe::Solver& s, const RunState& r);
/// Restores the solver and returns the run state; throws InputError if the
/// file is not a checkpoint of this deck.
RunState read_checkpoint(const std::string& path, std::uint64_t deck_hash, fe::Solver& s);

}  // namespace drawbend::io
