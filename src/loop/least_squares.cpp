// Levenberg-Marquardt with a forward-difference Jacobian (least_squares.hpp).
#include "loop/least_squares.hpp"

#include "loop/gram.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>

namespace drawbend::loop {

namespace {
std::atomic<long long> g_row_evals{0};
}  // namespace

long long lm_jacobian_row_evaluations() { return g_row_evals.load(); }

namespace {
// Does every row keep its residual r[k] bit for bit when all the columns it
// does not read are perturbed at once (the step of the Jacobian)?  Rows with a
// residual that is not finite are not asked (they get dense columns).
bool reads_hold(const Eigen::VectorXd& th, const Eigen::VectorXd& r, const RowResidualFn& row, const RowReads& reads,
                long long& evals) {
  const int p = static_cast<int>(th.size()), n = static_cast<int>(r.size());
  Eigen::VectorXd tp = th;
  for (int j = 0; j < p; ++j) tp[j] += 1e-7 * std::max(1.0, std::abs(th[j]));
  Eigen::VectorXd t = tp;
  for (int k = 0; k < n; ++k) {
    if (!std::isfinite(r[k])) continue;
    for (int j : reads[k]) t[j] = th[j];
    const double v = row(t, k);
    ++evals;
    for (int j : reads[k]) t[j] = tp[j];
    if (!(v == r[k])) return false;
  }
  return true;
}
}  // namespace

double levenberg_marquardt(Eigen::VectorXd& th, const ResidualFn& resid, Eigen::MatrixXd& J, bool& converged,
                           const RowResidualFn& row, const RowReads* reads, bool want_jacobian) {
  const int p = static_cast<int>(th.size());
  const Eigen::VectorXd th_start = th;
  Eigen::VectorXd r = resid(th);
  const int n = static_cast<int>(r.size());
  double sse = r.squaredNorm(), lambda = 1e-3;
  J.resize(n, p);
  std::vector<std::vector<int>> support;  // rows of each column; empty: dense
  // Structural columns (`reads`): rows of each column, checked at the start.
  std::vector<std::vector<int>> structure;
  if (row && reads && n > 0 && static_cast<int>(reads->size()) == n) {
    long long evals = 0;
    const bool hold = reads_hold(th, r, row, *reads, evals);
    g_row_evals += evals;
    if (hold) {
      structure.assign(p, {});
      for (int k = 0; k < n; ++k)
        if (std::isfinite(r[k]))
          for (int j : (*reads)[k]) structure[j].push_back(k);
        else
          for (int j = 0; j < p; ++j) structure[j].push_back(k);
      for (auto& s : structure) {
        if (!std::is_sorted(s.begin(), s.end())) std::sort(s.begin(), s.end());  // rows ascending: usually sorted
        s.erase(std::unique(s.begin(), s.end()), s.end());
      }
    }
  }
  bool use_structure = !structure.empty();
  // The entries of J outside the rows evaluated are zero: set once, on the
  // first Jacobian (the structure's, or the dense one), and never written
  // since (the pattern is within the structure, and both are within what the
  // first Jacobian wrote or zeroed), so each later Jacobian writes its rows only.
  bool zeroed = false;
  auto jacobian = [&]() {
    long long evals = 0;
    if (!zeroed && (use_structure || !support.empty())) J.setZero();
    zeroed = true;
    for (int j = 0; j < p; ++j) {
      Eigen::VectorXd t2 = th;
      const double h = 1e-7 * std::max(1.0, std::abs(th[j]));
      t2[j] += h;
      if (support.empty() && use_structure) {  // the dense column, on the rows that may read theta_j
        for (int k : structure[j]) J(k, j) = (r[k] - row(t2, k)) / h;
        evals += static_cast<long long>(structure[j].size());
      } else if (support.empty()) {
        J.col(j) = (r - resid(t2)) / h;  // d(prediction)/d(theta)
        evals += n;
      } else {
        for (int k : support[j]) J(k, j) = (r[k] - row(t2, k)) / h;
        evals += static_cast<long long>(support[j].size());
      }
    }
    g_row_evals += evals;
  };
  // Nonzero (or NaN) entries of the dense Jacobian, per column.  After a
  // Jacobian made on the structure (use_structure), every entry outside a
  // column's structural rows is the +0 of the first Jacobian's zeroing, never
  // written since (see `zeroed`): only those rows are looked at (ascending, as
  // the full scan finds them), not all n rows of every column.
  auto pattern = [&]() {
    std::vector<std::vector<int>> s(p);
    for (int j = 0; j < p; ++j)
      if (use_structure) {
        for (int k : structure[j])
          if (!(J(k, j) == 0)) s[j].push_back(k);
      } else {
        for (int k = 0; k < n; ++k)
          if (!(J(k, j) == 0)) s[j].push_back(k);
      }
    return s;
  };
  converged = false;
  for (int it = 0; it < 100; ++it) {
    jacobian();
    if (it == 0 && row && n > 0) support = pattern();
    const Eigen::MatrixXd A = gram(J, support.empty() ? nullptr : &support);  // J^T J, Eigen's bits (gram.hpp)
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 20; ++tries) {
      Eigen::MatrixXd Ad = A;
      for (int j = 0; j < p; ++j) Ad(j, j) += lambda * std::max(A(j, j), 1e-12);
      const Eigen::VectorXd t2 = th + Ad.ldlt().solve(g);
      const Eigen::VectorXd r2 = resid(t2);
      const double s2 = r2.squaredNorm();
      if (std::isfinite(s2) && s2 < sse) {
        const double rel = (sse - s2) / std::max(sse, 1e-300);
        th = t2;
        r = r2;
        sse = s2;
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
        if (rel < 1e-12) converged = true;
        break;
      }
      lambda *= 10;
    }
    if (!improved || converged) {
      converged = std::isfinite(sse);  // a NaN start is never improved on: not a solution
      break;
    }
  }
  const bool was_sparse = !support.empty();
  const std::vector<std::vector<int>> used = std::move(support);
  support.clear();
  if (use_structure) {  // the structure must hold at the solution too (non-finite rows: dense columns)
    for (int k = 0; k < n && use_structure; ++k)
      if (!std::isfinite(r[k])) use_structure = false;
    long long evals = 0;
    if (use_structure) use_structure = reads_hold(th, r, row, *reads, evals);
    g_row_evals += evals;
  }
  if (!want_jacobian && was_sparse && use_structure) {
    // No Jacobian wanted: only the pattern's check below, on the entries it
    // looks at that the first pattern does not hold (the structure's rows of
    // column j outside used[j]; the entries in both cannot fail it), each the
    // same expression as jacobian()'s, so the same decision bit for bit.
    long long evals = 0;
    bool holds = true;
    for (int j = 0; j < p && holds; ++j) {
      Eigen::VectorXd t2 = th;
      const double h = 1e-7 * std::max(1.0, std::abs(th[j]));
      t2[j] += h;
      auto u = used[j].begin();
      for (int k : structure[j]) {
        while (u != used[j].end() && *u < k) ++u;
        if (u != used[j].end() && *u == k) continue;
        ++evals;
        if (!((r[k] - row(t2, k)) / h == 0)) {
          holds = false;
          break;
        }
      }
    }
    g_row_evals += evals;
    if (holds) return sse;
    th = th_start;  // as below: the dense fit instead
    return levenberg_marquardt(th, resid, J, converged, nullptr, nullptr, false);
  }
  if (!want_jacobian && !was_sparse) return sse;  // no pattern to check
  jacobian();  // dense (or the structure's entries of it): the one returned for the standard errors
  if (was_sparse) {
    const std::vector<std::vector<int>> now = pattern();
    for (int j = 0; j < p; ++j)
      if (!std::includes(used[j].begin(), used[j].end(), now[j].begin(), now[j].end())) {
        th = th_start;  // a derivative outside the first pattern: the dense fit instead
        return levenberg_marquardt(th, resid, J, converged, nullptr, nullptr, want_jacobian);  // dense throughout
      }
  }
  return sse;
}

}  // namespace drawbend::loop
