// J^T J of a Jacobian with many zero entries, bit for bit as Eigen's
// `J.transpose() * J` (issue 50 item 6).
//
// A fit with a group factor of many levels (a 42-level coil) has a Jacobian
// whose level columns are zero on every row but their own, yet Eigen's dense
// product makes n p^2 multiply-adds (14 % of the loop on the 50,040-row
// lab-style file).  Here only the nonzero products are summed, in the order
// Eigen's product sums them, so the result is the same bit for bit:
//  - Eigen (3.4, one thread, SSE2 doubles: no FMA, mr = nr = 4, two doubles a
//    packet) cuts the depth (J's rows) into blocks of kc rows
//    (computeProductBlockingSizes, from this machine's cache sizes, as Eigen
//    does) and the result into mc x nc blocks; within a depth block each
//    element is a sum of the products in row order, started at +0, except
//    the elements of gebp's one-packet row panel (the 2 rows after the last
//    4-row panel of an mc block) in its 4-column panels, which sum the even and
//    the odd rows of the block's first (depth & ~7) rows apart, add the two,
//    then the remaining rows in order; the block's sum is added to the element
//    (alpha = 1: an exact product), which starts at +0;
//  - a skipped product is +-0 (a zero entry times a finite one), and adding
//    +-0 to a sum leaves it unchanged (a sum started at +0 is never -0).
// Where the blocking, the packet layout or the Eigen version differs, or J
// has an entry that is not finite, or J is dense enough that the skipped
// products do not pay, Eigen's product is used.  tests/unit/test_gram.cpp
// compares the two bit for bit.
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace drawbend::loop {

/// J^T J, bit for bit as Eigen's `J.transpose() * J`.  nz (optional): per
/// column of J, the rows (ascending) outside which the column is zero (+-0),
/// as levenberg_marquardt's sparse pattern; without it J is scanned.
Eigen::MatrixXd gram(const Eigen::MatrixXd& J, const std::vector<std::vector<int>>* nz = nullptr);

/// The sparse path only (tests): false when it does not apply (then A is unset).
bool gram_sparse(const Eigen::MatrixXd& J, Eigen::MatrixXd& A, bool force = false,
                 const std::vector<std::vector<int>>* nz = nullptr);

}  // namespace drawbend::loop
