#pragma once
// The sanitizer step (tests/sanitize/run.sh) sets DRAWBEND_SANITIZER_RUN=1 for
// the tests it runs.  There a test that repeats one code path over many seeds
// or sizes runs a share of them: AddressSanitizer and UBSan look for memory and
// undefined-behaviour errors on the code paths, which the share takes too
// (every class, every matrix shape's residues); the main run of `make test`
// (Release) runs every repetition and checks every answer.  The answers checked
// are the same in both runs; only how many repetitions differs.
#include <algorithm>
#include <cstdlib>

namespace drawbend::test {

/// Is this test run by the sanitizer step?
inline bool sanitizer_run() {
  const char* v = std::getenv("DRAWBEND_SANITIZER_RUN");
  return v && *v && *v != '0';
}

/// n repetitions in the main run; n / share (at least 1) in the sanitizer step.
inline int repetitions(int n, int share) { return sanitizer_run() ? std::max(1, n / share) : n; }

}  // namespace drawbend::test
