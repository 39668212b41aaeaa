#pragma once
// The column the scan tests of the loop's local forms read (test_loop_bump,
// test_loop_step): x on 61 equally spaced values from 2 to 14 (range 12),
// 3 rows each, in row order value by value.
#include <vector>

namespace drawbend::testing {

inline std::vector<double> grid_x() {
  std::vector<double> x;
  for (int r = 0; r < 3; ++r)
    for (int j = 0; j <= 60; ++j) x.push_back(2.0 + 12.0 * j / 60.0);
  return x;
}

}  // namespace drawbend::testing
