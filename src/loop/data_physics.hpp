#pragma once
// Whole-data-set plausibility of measured draw-bend data (`drawbend loop`):
// what no single row shows but the rows together do: every force or pin
// in the wrong unit, no fixed-pin rows to measure friction on, an outlet
// force pasted down the column, one test_id over several pins or directions,
// directions in radians (a warning).  Row-level checks are loop/measured.cpp's.
#include <vector>

#include "loop/measured.hpp"

namespace drawbend::loop {

/// Throws InputError (exit 2) naming the file and column when the usable
/// rows cannot be a draw-bend data set; returns warnings (legal but
/// suspicious: every speed below 1 mm/s) for the caller to print.
std::vector<Problem> check_data_physics(const Dataset& d);

}  // namespace drawbend::loop
