#pragma once
// When a loop of the solver forks into OpenMP threads: from its modelled cost,
// not from a fixed item count.
//
// A parallel region costs a fork, a join and a barrier.  On an idle machine
// that is a few microseconds; on a shared one (this project's 2-core machine
// runs several jobs at once) the join waits for a worker that may have been
// descheduled, and a loop of 765 nodes forked every cycle made a run 26 times
// slower in wall time on 2 threads than on 1 (issue 22).  So a loop forks
// only when the time two threads save on it, work x (1 - 1/threads), exceeds
// kForkNs, a deliberately pessimistic fork cost.  The work is modelled as
// items x the loop's cost per item (constants below, measured on an AVX2 and
// an AVX-512 machine with `make bench`; a rough figure is enough: it only has
// to tell a 50-microsecond loop from a millisecond one).
//
// A loop that runs in a cycle whose element loop has already forked pays
// less: libgomp's threads spin for a while (GOMP_SPINCOUNT, 300,000 by
// default) after a region before they sleep, so its fork finds them awake,
// and a late worker has already delayed that cycle.  Such a loop forks when
// it saves kHotForkNs (`after_fork`).
//
// What that gives (2 threads): the element loop forks from about 800
// elements; the node pass (nodal sums and integration) from about 2,500
// nodes when the element loop forked in that cycle (the 8,000-element bar,
// the 4,800-element strip), else from 25,000; contact from about 3,300
// contact nodes.  A model below these sizes runs serially, so it is never
// slower on 2 threads than on 1.  Results never depend on the decision: every
// parallel loop writes its own items and every total is summed in a fixed order.
#include <atomic>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace drawbend::fe::parallel {

/// Modelled cost of one item [ns] of each parallel loop of the solver.
inline constexpr double kElementNs = 250;      ///< element kernel, per element (J2, one thread)
inline constexpr double kNodePassNs = 8;       ///< nodal sum of the corner forces and integration, per node
inline constexpr double kContactNodeNs = 60;   ///< penetration, penalty and friction, per contact node
/// Pessimistic cost of one parallel region [ns] (fork, join, a late worker).
inline constexpr double kForkNs = 100000;
/// The same for a region in a cycle whose element loop forked (threads awake).
inline constexpr double kHotForkNs = 10000;

/// Override of the model, for tests that must run every loop in parallel
/// (determinism across thread counts) or none.
enum class Mode { model, always, never };
inline std::atomic<Mode>& mode() {
  static std::atomic<Mode> m{Mode::model};
  return m;
}

/// The threads a parallel region would get.
inline int threads() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

/// Whether a loop of `items` items costing `ns_per_item` each should fork;
/// `after_fork`: the element loop of this cycle has forked.
inline bool worth_forking(long items, double ns_per_item, bool after_fork = false) {
  const int threads = parallel::threads();
  if (threads < 2) return false;
  switch (mode().load(std::memory_order_relaxed)) {
    case Mode::always: return true;
    case Mode::never: return false;
    case Mode::model: break;
  }
  return static_cast<double>(items) * ns_per_item * (1.0 - 1.0 / threads) > (after_fork ? kHotForkNs : kForkNs);
}

}  // namespace drawbend::fe::parallel
