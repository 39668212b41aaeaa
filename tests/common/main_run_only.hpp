#pragma once
// A Boost.Test precondition for the cases that the sanitizer step skips
// (sanitizer_run.hpp): a case that runs the same code path as another case of
// its test on other data or options, where the sanitizer step looks for memory
// and undefined-behaviour errors on code paths, not for answers.  Boost.Test
// reports the skipped case as skipped, never as passed; the main run of
// `make test` runs it and checks every answer.
//   BOOST_AUTO_TEST_CASE(name, *drawbend::test::main_run_only()) { ... }
#include <boost/test/unit_test.hpp>

#include "sanitizer_run.hpp"

namespace drawbend::test {

inline boost::test_tools::assertion_result not_a_sanitizer_run(boost::unit_test::test_unit_id) {
  boost::test_tools::assertion_result r(!sanitizer_run());
  r.message() << "skipped in the sanitizer step (DRAWBEND_SANITIZER_RUN): the same code path runs in another case";
  return r;
}

// A function pointer, not a lambda: GCC 12 warns that a captureless lambda's
// bytes are copied uninitialized into boost::function's storage.
inline boost::unit_test::decorator::precondition main_run_only() {
  return boost::unit_test::decorator::precondition(&not_a_sanitizer_run);
}

}  // namespace drawbend::test
