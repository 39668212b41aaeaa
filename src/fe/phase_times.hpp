#pragma once
// Where a cycle's time goes, for `make bench` (bench/bench_phases.cpp): the
// wall time of the time loop's phases, accumulated by fe::Solver when it is
// handed a PhaseTimes (Solver::time_phases), and the time spent in the
// material updates inside the element kernel, counted in time-stamp-counter
// ticks (the kernel cannot call a clock: its per-ISA objects may define no
// code outside their namespace, build.isa_symbols).
//
// Off by default (a null pointer): a run that is not timed pays one branch per
// phase.  Timing changes no result: it only reads clocks.
#include <cstdint>

namespace drawbend::fe {

/// Accumulated wall time per phase [s] over `cycles` cycles.
struct PhaseTimes {
  double kernel = 0;    ///< the element loop (gather, geometry, material, forces, scatter)
  double nodes = 0;     ///< node passes: nodal sums, loads, integration, constraints, energies, positions, next dt
  double contact = 0;   ///< contact and friction (areas, node-to-surface, totals)
  double other = 0;     ///< tools, the caller's per-cycle callback
  /// Ticks of the time-stamp counter inside the material updates (part of
  /// `kernel`); meaningful on one thread (two threads' ticks add up).
  std::uint64_t material_ticks = 0;
  long cycles = 0;
};

/// Seconds per time-stamp-counter tick, calibrated once against the steady
/// clock (about 20 ms the first time).  0 where the counter is not read
/// (not x86-64): material_ticks then stays 0.
double seconds_per_tick();

}  // namespace drawbend::fe
