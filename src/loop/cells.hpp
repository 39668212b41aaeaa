#pragma once
// Which cell of a model input the one-cell forms are tried in (forms.cpp):
//  - worst_group: the group of an input whose fixed-pin rows have the largest
//    mean squared held-out residual under the current model;
//  - scan_split: for a continuous speed or direction, the threshold and side
//    where a candidate column explains the most of that residual.
#include <optional>
#include <string>
#include <vector>

#include "loop/candidates.hpp"

namespace drawbend::loop {

/// The group of model input `by` (Design::groups) whose fixed-pin rows have
/// the largest mean squared held-out residual in `cur` (ties: the first).
int worst_group(const Design& d, const CvResult& cur, const std::string& by);

/// A threshold of a continuous model input and a side: side 0 the rows below
/// it, side 1 those at or above it (Design::groups of "input>=threshold").
struct Split {
  double threshold = 0;
  int side = 0;
};

/// For input speed_mm_s or direction_deg with more than 6 distinct values on
/// the fixed-pin rows: over every midpoint between two distinct values with
/// at least a tenth of the rows (and 10) on each side, and either side, the
/// one where column x explains the largest sum of squares of cur's held-out
/// residual r on that side (numeric: the slope's (sum (x - x_mean)(r -
/// r_mean))^2 / sum (x - x_mean)^2; categorical, x a level code: the
/// between-level sum of squares).  Running sums, one pass over the rows
/// sorted by the input.  Empty for another input, too few distinct values or
/// rows, or when no side explains anything.
std::optional<Split> scan_split(const Design& d, const CvResult& cur, const std::vector<double>& x,
                                bool categorical, const std::string& input);

}  // namespace drawbend::loop
