#pragma once
// Independent cases of a chapter run side by side.
//
// The draw-bend meshes of the default tier have 400-900 elements: too few for
// the element loop's OpenMP threads to pay (measured: 2 threads, 400 elements,
// same wall time at twice the CPU).  A chapter's cases are independent, so
// the pool runs whole cases concurrently instead, `jobs` at a time, and gives
// each case hardware_threads / jobs OpenMP threads (at least one).
//
// Results do not depend on the pool: every case is deterministic whatever its
// thread count (fixed-order nodal sums), and results come back in the order
// the cases were given.  An exception in one case is rethrown after all
// running cases have finished (the first by case order).
//
// jobs: DRAWBEND_JOBS from the environment if set (1 = one case at a time),
// otherwise the number of hardware threads; set_case_threads() caps both.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "sim/drawbend_case.hpp"

namespace drawbend::sim {

/// Concurrent cases: DRAWBEND_JOBS, else the pool's threads (>= 1).
int default_case_jobs();

/// The threads the pool may use in all, cases side by side times each one's
/// OpenMP threads: n > 0 caps them at n (`model-loop --threads N`), also
/// against DRAWBEND_JOBS; 0, the default, is the hardware threads.
void set_case_threads(int n);

/// Run f(0..n-1), `jobs` at a time (at most the pool's threads), largest
/// `cost` first (cost may be empty).  Each call sees omp_get_max_threads() =
/// max(1, the pool's threads / the cases side by side).
void run_cases(std::size_t n, const std::function<void(std::size_t)>& f, const std::vector<double>& cost = {},
               int jobs = default_case_jobs());

/// One draw-bend case and the directory it runs in.
struct CaseJob {
  DrawBendSpec spec;
  std::string dir;
};

/// run_drawbend for every job, concurrently; a line on stdout as each case
/// starts and ends (with its wall time, or the run it was read from when
/// run_drawbend found it under `runs_from`).  Results in job order.
std::vector<DrawBendResult> run_drawbend_all(const std::vector<CaseJob>& jobs, bool reuse,
                                             const std::vector<std::string>& runs_from = {});

}  // namespace drawbend::sim
