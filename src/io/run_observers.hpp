#pragma once
// The outputs of `drawbend run` as observers of the solver's progress: after
// every cycle io::run_case (io/run_case.cpp) calls, in this order,
//   follow_step    a new step restarts the history and field clocks at its start
//   History        history.csv: a row every history interval (the deck's [output])
//   Fields         fields_<k>.vtu and the contact maps: fields_per_step a step
//   Progress       the console's progress line, every progress_every_s wall seconds
//   signal_stop    SIGINT/SIGTERM: a checkpoint at this cycle boundary, then stop
//   Checkpoints    checkpoint.bin every N cycles or T simulated seconds (halt_after_cycles)
// Each reads the run's shared record (Run) and writes only its own output;
// a stop is the exception Halt, which run_case turns into a halted summary.
// A new output is one more observer here and one more call in run_case.
#include <chrono>
#include <ostream>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "fe/solver.hpp"
#include "io/deck.hpp"
#include "io/run_case.hpp"
#include "io/run_checkpoint.hpp"

namespace drawbend::io::observe {

/// Thrown by an observer to stop the run after this cycle (r.halted follows).
struct Halt {};

/// What the observers share: the case, the solver, the checkpointed run state
/// (output clocks, snapshot list) and the summary being filled.
struct Run {
  Run(Deck& d, const RunOptions& o, fe::Solver& s, std::ostream& l) : deck(d), opt(o), solver(s), log(l) {}
  Deck& deck;
  const RunOptions& opt;
  fe::Solver& solver;
  std::ostream& log;
  double total = 0;          ///< simulated time of all steps [s]
  RunState rs;
  RunSummary r;
  std::string checkpoint_path;  ///< <out>/checkpoint.bin
  bool printed = false;      ///< a progress line is open on the console
};

/// A new step: its history and field clocks restart at the step's start.
void follow_step(Run& run, const fe::Progress& p);

/// history.csv: the run's columns (core/run_output.hpp) and the deck's signals.
class History {
 public:
  explicit History(Run& run);
  void operator()(const fe::Progress& p);
  /// The rows so far, into the run state (for a checkpoint).
  void keep(Run& run) const { run.rs.history_rows = table_.rows(); }
  void save() const;  ///< <out>/history.csv

 private:
  Run& run_;
  std::vector<int> elements_;  ///< per signal: the tracked element of a "strain" signal
  CsvWriter table_;
};

/// fields_<k>.vtu and contact_<k>_<pair>.csv at each snapshot time and at each step's end.
class Fields {
 public:
  explicit Fields(Run& run) : run_(run) {}
  void snapshot();
  void operator()(const fe::Progress& p);

 private:
  Run& run_;
};

/// The progress line: percent, time, dt, step, cycle and the wall time left.
class Progress {
 public:
  explicit Progress(Run& run);
  void operator()(const fe::Progress& p);

 private:
  Run& run_;
  std::chrono::steady_clock::time_point last_, start_;  ///< the time left comes from the cycles done in this run
  long cycle0_;
};

/// A SIGINT/SIGTERM seen in opt.stop: checkpoint, record the signal, Halt.
void signal_stop(Run& run, const History& history, const fe::Progress& p);

/// checkpoint.bin by cycles or by simulated time; Halt after halt_after_cycles.
class Checkpoints {
 public:
  explicit Checkpoints(Run& run);
  void operator()(const History& history, const fe::Progress& p);

 private:
  Run& run_;
  double next_time_;
};

}  // namespace drawbend::io::observe
