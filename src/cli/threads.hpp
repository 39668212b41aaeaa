#pragma once
// `--threads N` of every drawbend command (issue 22, item 5).  N from 0 to
// io::kMaxThreads, 0 meaning the default (OMP_NUM_THREADS, else every
// hardware thread; a deck's own [numerics] threads for `run`).  Another N is
// an input error (exit 2): a negative one is not the default in disguise, and
// a huge one is not handed to libgomp to crash on.
//   - Commands that compute (loop, synth, export, drawbend-deck --run) set the
//     OpenMP threads with apply_threads();
//   - `run` passes N to io::run_case() (the deck's value when N = 0);
//   - `model-loop` (and `loop --model fe`) gives its FE runs N threads in all
//     (sim::set_case_threads: cases side by side, threads within a case);
//   - commands that write a deck (block-deck, strip-deck, cup-deck, and
//     drawbend-deck without --run) set the typed deck's numerics.threads
//     (io::set_threads on the builder's io::CaseSpec; cup-deck through
//     sim::CupSpec::threads), so that `drawbend run` of that deck uses it.
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/csv.hpp"
#include "io/deck.hpp"

namespace drawbend::cli {

/// Whether --threads n is one (0 .. io::kMaxThreads).
inline bool good_threads(int n) { return n >= 0 && n <= io::kMaxThreads; }

/// The message of a bad --threads n.
inline std::string bad_threads(int n) {
  return "--threads: expected a whole number from 0 (the default) to " + std::to_string(io::kMaxThreads) +
         ", found " + std::to_string(n);
}

/// Throws an InputError unless good_threads(n).
inline void check_threads(int n) {
  if (!good_threads(n)) throw InputError(bad_threads(n));
}

/// check_threads(n), then n OpenMP threads if n > 0.
inline void apply_threads(int n) {
  check_threads(n);
#ifdef _OPENMP
  if (n > 0) omp_set_num_threads(n);
#endif
}

}  // namespace drawbend::cli
