#pragma once
// What a case will cost before it runs: the CPU time and memory a job asks
// for (sim::JobNeeds for the Slurm executor) and what `drawbend plan` lists.
//
// Model: CPU seconds = elements x predicted cycles x ns_per_element_cycle(kind)
//                      x material_factor(material).
// The predicted cycles are the deck's own estimate (io::CostEstimate: end time
// / initial stable step with mass scaling), a lower bound, since the step
// shrinks as elements deform; the constant carries that shrinkage and the
// contact, output and history work per element-cycle, and so depends on the
// kind of case (the deck's [output] reduce kind; none: a draw-bend case).  The
// material factor is the cost of the sheet's update against von Mises with
// isotropic hardening (j2, 1): the deck's [material] type.
// Calibration (docs/cluster.md): the quick tier's runs of every kind, by the
// CPU time each run measured on its one thread (io::RunSummary::cpu_seconds),
// 2026-12-02, AMD EPYC Zen 4.  A material's factor is the median, over the
// case kinds where it and j2 both ran, of the ratio of their kinds' median
// ns per element-cycle (the same meshes and tools, another material); a
// kind's constant is then the median over its runs of ns per element-cycle
// / material factor.  A job asks for kTimeFactor x the prediction (at least
// kMinMinutes) so that a slower node or a busier file system does not end a
// good run in TIMEOUT; memory is the deck's estimate x 2 plus the process's
// fixed part.
#include <string>
#include <vector>

#include "io/deck.hpp"
#include "sim/executor.hpp"

namespace drawbend::sim {

/// Calibrated CPU nanoseconds per element-cycle of a case kind (see the header):
/// "" (draw-bend), block_slide, strip_draw, cup_draw, earing_cup; another kind: the largest.
double ns_per_element_cycle(const std::string& kind);
/// Calibrated cost of the sheet's material update against j2 (see the header): a [material] type
/// (elastic, j2, j2_combined, hill48, yld2004); another or none: the largest.
double material_factor(const std::string& material);
/// The material types material_factor knows, in the order `drawbend plan` lists them.
const std::vector<std::string>& costed_materials();
inline constexpr double kTimeFactor = 4;
inline constexpr double kMinMinutes = 5;
inline constexpr double kFixedMemoryMb = 120;

struct CasePrediction {
  std::string name;
  std::string kind;  ///< the deck's [output] reduce kind ("": draw-bend)
  std::string material;  ///< the deck's [material] type (io::CostEstimate::material)
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
