#pragma once
// make bench: the closing table and the issue-22 goals, checked (bench_summary.cpp).
#include <string>
#include <vector>

#include "bench_phases.hpp"

/// One timed case: ns per element-cycle on 1 and 2 threads (0: not run) and
/// its per-phase split on one thread.
struct CaseResult {
  std::string name;
  long elements = 0;
  double ns1 = 0, ns2 = 0;
  double forked = 0;    ///< share of the kept 2-thread run's cycles whose element loop forked (0 to 1)
  double capacity = 0;  ///< the host's capacity for 2 threads right after (bench_host.hpp; 0: not measured)
  PhaseSplit split;
};

/// Prints the cases as a Markdown table (the one docs/performance-log.md carries)
/// and one line per goal of issue 22 with "ok" or "FAIL": the 1,600-element
/// bar on one thread (100 ns with the AVX-512 kernel, 160 ns otherwise), the
/// strip on one thread (120 ns), the 2-thread speed-up at 8,000 elements and
/// more (1.8x; the line also gives the share of cycles forked and the host's
/// capacity for 2 threads, bench_host.hpp).  The goals inform; they do not
/// set the exit status (timings on a shared machine are noisy).
void print_summary(const std::string& cpu, const std::string& isa, int width, const std::vector<CaseResult>& cases);
