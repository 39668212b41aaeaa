#pragma once
// What a case will cost before it runs: the CPU time and memory a job asks
// for (sim::JobNeeds for the Slurm executor) and what `drawbend plan` lists.
//
// Model: CPU seconds = elements x predicted cycles x ns_per_element_cycle(kind).
// The predicted cycles are the deck's own estimate (io::CostEstimate: end time
// / initial stable step with mass scaling), a lower bound, since the step
// shrinks as elements deform; the constant carries that shrinkage and the
// contact, output and history work per element-cycle, and so depends on the
// kind of case (the deck's [output] reduce kind; none: a draw-bend case).
// Calibration (docs/cluster.md): the quick tier's runs of every kind, by the
// CPU time each run measured on its one thread (io::RunSummary::cpu_seconds),
// 2026-12-02, AMD EPYC Zen 4: each constant is the old one (250 ns) over the
// median ratio predicted / measured of its kind.  A job asks for kTimeFactor
// x the prediction (at least kMinMinutes) so that a slower node, a costlier
// material than the kind's median (Hill'48, Yld2004-18p cups) or a busier file
// system does not end a good run in TIMEOUT; memory is the deck's estimate x
// 2 plus the process's fixed part.
#include <string>
#include <vector>

#include "io/deck.hpp"
#include "sim/executor.hpp"

namespace drawbend::sim {

/// Calibrated CPU nanoseconds per element-cycle of a case kind (see the header):
/// "" (draw-bend), block_slide, strip_draw, cup_draw, earing_cup; another kind: the largest.
double ns_per_element_cycle(const std::string& kind);
inline constexpr double kTimeFactor = 4;
inline constexpr double kMinMinutes = 5;
inline constexpr double kFixedMemoryMb = 120;

struct CasePrediction {
  std::string name;
  std::string kind;  ///< the deck's [output] reduce kind ("": draw-bend)
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
