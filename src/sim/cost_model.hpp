#pragma once
// What a case will cost before it runs: the CPU time and memory a job asks
// for (sim::JobNeeds for the Slurm executor) and what `drawbend plan` lists.
//
// Model: CPU seconds = elements x predicted cycles x kNsPerElementCycle.  The
// predicted cycles are the deck's own estimate (io::CostEstimate: end time /
// initial stable step with mass scaling), a lower bound, since the step shrinks
// as elements deform; the constant carries that shrinkage and the contact,
// output and history work per element-cycle.  It was calibrated on the quick
// tier's draw-bend runs of `make test` (36 runs, 2026-12-01, AMD EPYC Zen 4,
// 2 cores: at 700 ns the prediction was 2.76 x the measured CPU time
// (median; 1.74 to 3.66), so 700 / 2.76 = 254, rounded to 250; docs/cluster.md).  A job asks for kTimeFactor x the prediction (at
// least kMinMinutes) so that a slower node or a busier file system does not
// end a good run in TIMEOUT; memory is the deck's estimate x 2 plus the
// process's fixed part.
#include <string>
#include <vector>

#include "io/deck.hpp"
#include "sim/executor.hpp"

namespace drawbend::sim {

inline constexpr double kNsPerElementCycle = 250;  ///< calibrated, see the header
inline constexpr double kTimeFactor = 4;
inline constexpr double kMinMinutes = 5;
inline constexpr double kFixedMemoryMb = 120;

struct CasePrediction {
  std::string name;
  double elements = 0, cycles = 0;
  double cpu_seconds = 0;  ///< on one core
  double memory_mb = 0;
};

CasePrediction predict_case(const io::Deck& d);

/// The job's request on `cores` cores (wall time ~ cpu / cores at best).
JobNeeds job_needs(const CasePrediction& p, int cores);

/// Makespan [s] of `cpu_seconds` cases on `nodes` nodes of `cores` cores, one
/// case per node at a time on all its cores (a draw-bend case scales to about
/// 2 threads), largest first: the order of sim::run_cases.
double makespan_seconds(std::vector<double> cpu_seconds, int nodes, int cores, double parallel_efficiency = 0.8);

}  // namespace drawbend::sim
