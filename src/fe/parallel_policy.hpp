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
// it saves kHotForkNs (`after_fork`).  Run serially after a forked element
// loop, the node pass also costs more than on one thread: half the corner
// forces it sums were written by the other core and come from its cache.
// Forked, each thread sums mostly the nodes of its own elements.  Measured
// (Zen 4, 2026-11-29, 2 threads, kHotForkNs 2,000 against 10,000 before):
// bar 1,600 (serial node pass before) 49-56 ns per element-cycle against
// 62-67 in 4 alternations, its node pass 10-12 ns in 3 of them (27 in the
// fourth) against 15-18 (about 16 on one thread); the draw-bend deck
// (`drawbend drawbend-deck --draw-length 4`) with 12 elements across (1,488
// elements, 2,080 nodes) 4.6-5.4 s against 5.9-9.5, on one thread 6.7-7.5;
// with 8 across (992 elements, 1,440 nodes) 3.1-4.0 s against 3.7-5.7, on
// one thread 4.5-5.2 (its contact loop, about 290 contact nodes, now forks
// too, so these runs measured that as well).  Before, each of these decks ran slower on 2 threads
// than on 1 in one of its 4 runs (9.5 s against 7.2; 5.7 against 4.6).  The
// same bits either way (the runs' histories compared byte for byte).
//
// What that gives (2 threads): the element loop forks from about 800
// elements; the node pass (nodal sums and integration) from about 500
// nodes when the element loop forked in that cycle, so in practice
// whenever it did, else from 25,000; contact from about 70 contact nodes
// when the element loop forked, else from about 3,300.  A model below these
// sizes runs serially, so it is never slower on 2 threads than on 1.  Results
// never depend on the decision: every parallel loop writes its own items and
// every total is summed in a fixed order.
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
inline constexpr double kHotForkNs = 2000;

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

/// This thread's number in its team (0 outside a parallel region).
inline int thread_num() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
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
