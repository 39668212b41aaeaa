#pragma once
// make bench: where one cycle's time goes, per phase, on 1 or 2 threads
// (bench_phases.cpp; the timers are fe/phase_times.hpp).
#include <string>

#include "core/csv.hpp"
#include "fe/model.hpp"

/// ns per element-cycle of each phase.  `kernel` is the element loop without
/// its material updates; `total` is the sum of the five.
struct PhaseSplit {
  double kernel = 0, material = 0, nodes = 0, contact = 0, other = 0, total = 0;
};

/// Runs `cycles` cycles of `m` on `threads` threads (then restores the OpenMP
/// thread count) with the phase timers on, prints the split as one line and
/// appends rows "<name>.<phase>" (elements, threads, ns per element-cycle) to
/// `w`.  The timers cost a little (a clock
/// read per phase, a counter read per element block), so the headline
/// figures come from untimed runs, not from this one.  On more than one
/// thread the material ticks add up the threads' CPU time, not wall time, so
/// there the element loop is reported whole (kernel with material 0): the
/// split then shows which phase keeps two threads from halving the time.
PhaseSplit bench_phases(const std::string& name, const drawbend::fe::Model& m, long cycles, drawbend::CsvWriter& w,
                        int threads = 1);
