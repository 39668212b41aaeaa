#pragma once
// make bench: where one cycle's time goes, per phase, on one thread
// (bench_phases.cpp; the timers are fe/phase_times.hpp).
#include <string>

#include "core/csv.hpp"
#include "fe/model.hpp"

/// ns per element-cycle of each phase.  `kernel` is the element loop without
/// its material updates; `total` is the sum of the five.
struct PhaseSplit {
  double kernel = 0, material = 0, nodes = 0, contact = 0, other = 0, total = 0;
};

/// Runs `cycles` cycles of `m` on one thread with the phase timers on, prints
/// the split as one line and appends rows "<name>.<phase>" (elements, 1
/// thread, ns per element-cycle) to `w`.  The timers cost a little
/// (a clock read per phase, a counter read per element block), so the
/// headline figures come from untimed runs, not from this one.
PhaseSplit bench_phases(const std::string& name, const drawbend::fe::Model& m, long cycles, drawbend::CsvWriter& w);
