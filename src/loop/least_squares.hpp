// Levenberg-Marquardt for the loop's nonlinear least-squares fits.
//
// Contract:
//  - minimises |r(theta)|^2 from the given start; returns the final SSE and
//    leaves J = d(prediction)/d(theta) = -dr/dtheta (forward differences,
//    step 1e-7 max(1, |theta_j|)) at the solution, for standard errors;
//  - `converged` is set when a step gains less than 1e-12 of the SSE or no
//    step (up to 20 damping increases) lowers it, and the SSE is finite (a
//    start whose SSE is NaN or infinite is never lowered, since no step
//    compares below it: theta stays at the start and `converged` is false);
//    at most 100 iterations (at the cap `converged` is false);
//  - with `row` (the residual of one row, bitwise the same as resid(theta)[k]),
//    the Jacobian is sparse after the first iteration: column j is evaluated
//    only on the rows where the first, dense Jacobian had a nonzero entry (a
//    group factor's level touches only its own rows, so a fit with L levels
//    costs about n instead of n L row evaluations per iteration; issue 50
//    item 6).  The last Jacobian (the one returned) is dense again; if it has a
//    nonzero entry outside those rows, the fit is rerun from the start with
//    dense Jacobians only, so the answer never rests on a wrong pattern.  When
//    the pattern holds, every Jacobian equals the dense one bit for bit (a row
//    that does not read theta_j gives exactly 0), and so does the fit;
//  - with `reads` as well (per row, the columns of theta it may read: a
//    superset, from the model's structure), the first and the last Jacobian
//    are evaluated only on those entries instead of densely (about 2 p n row
//    evaluations per fit saved; issue 50 item 6).  The claim is checked at the
//    start and at the end with one evaluation per row: every column it does
//    not list perturbed at once must leave the row's residual unchanged bit for
//    bit; if not, the fit runs dense as without `reads`.  A row whose residual
//    is not finite gets every column (as the dense Jacobian gives it).  So the
//    Jacobians, the pattern, its check and the fit are those of the dense
//    first Jacobian bit for bit;
//  - with want_jacobian false (a fit whose standard errors nobody reads: a
//    cross-validation fold, a sum of squares), J is left unspecified and the
//    last Jacobian is not made; only the entries that the pattern's check
//    reads and the first pattern does not hold are evaluated (usually none),
//    so theta, the SSE, `converged` and the check's decision are those of
//    want_jacobian true bit for bit.
#pragma once

#include <functional>
#include <vector>

#include <Eigen/Dense>

namespace drawbend::loop {

using ResidualFn = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

using RowResidualFn = std::function<double(const Eigen::VectorXd&, int)>;

/// Per row of the residual, the columns of theta it may read (ascending or not;
/// a superset), rows appended in order.  One flat list for all rows: a vector
/// per row was an allocation per row of every fit (and the frees' consolidation
/// of the heap), ~10 % of a 50,000-row loop (issue 50 item 6).
class RowReads {
 public:
  struct Cols {  // one row's columns
    const int *b, *e;
    const int* begin() const { return b; }
    const int* end() const { return e; }
  };
  /// Appends the next row's columns.
  void push_row(const std::vector<int>& cols) {
    cols_.insert(cols_.end(), cols.begin(), cols.end());
    end_.push_back(static_cast<int>(cols_.size()));
  }
  void reserve(size_t rows, size_t cols) { end_.reserve(rows), cols_.reserve(cols); }
  size_t size() const { return end_.size(); }
  Cols operator[](size_t k) const {
    const int* d = cols_.data();
    return {d + (k ? end_[k - 1] : 0), d + end_[k]};
  }

 private:
  std::vector<int> end_;   // per row: one past its last column in cols_
  std::vector<int> cols_;  // the rows' columns, row after row
};

double levenberg_marquardt(Eigen::VectorXd& th, const ResidualFn& resid, Eigen::MatrixXd& J, bool& converged,
                           const RowResidualFn& row = nullptr, const RowReads* reads = nullptr,
                           bool want_jacobian = true);

/// Row evaluations made by levenberg_marquardt's Jacobians since the program
/// started (a counter for the complexity test of issue 50, not a timing).
long long lm_jacobian_row_evaluations();

}  // namespace drawbend::loop
