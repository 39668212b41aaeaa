// The sparse Jacobian of levenberg_marquardt (src/loop/least_squares.hpp,
// issue 50 item 6): an operation count, not a timing.  Expected answers:
//  - a group factor: n = 4000 rows in p = 40 groups, r_k = y_k - exp(theta_g(k))
//    with y from theta_g = 0.01 g.  The fit with the row function equals the
//    dense fit bit for bit (theta, SSE and J), and its Jacobians evaluate at
//    most 2 p n + 100 n rows (the first and the last Jacobian dense, at most
//    100 sparse ones of n rows each), where the dense fit needs p n per
//    iteration (the 50,000-row file with a 42-level column ran 2x slower for
//    this before).
//  - a pattern that changes: r_k = y_k - a tanh(s x_k) started at a = 0, where
//    d/ds is 0 on every row at the start but not at the solution: the fit
//    falls back to dense Jacobians and equals the dense fit bit for bit.
//  - structural reads: the group factor with `reads` (row k reads theta_g(k))
//    equals the dense fit bit for bit and evaluates at most 2 n (the two
//    checks) + 2 n (first and last Jacobian) + 100 n rows; with a wrong claim
//    (row k said to read theta_(g(k)+1)) the check fails and the fit still
//    equals the dense one bit for bit.
//  - without the Jacobian (want_jacobian false: a cross-validation fold):
//    the group factor with `reads` gives theta, SSE and `converged` bit for
//    bit as with it, and evaluates exactly n rows fewer (the last Jacobian's
//    one entry per row; the pattern's check evaluates none, as every entry of
//    the structure is nonzero); the changing pattern (a tanh, every row said
//    to read both parameters) is caught by the check without the Jacobian as
//    well, and the dense refit gives theta and SSE bit for bit as with it.
//  - the convergence flag: r_k = y_k - t0 (a mean, y_k = k) from t0 = 0
//    converges to t0 = (n - 1) / 2 with `converged` true; with one y_k NaN the
//    SSE is NaN at the start, no step compares below it, theta stays 0 and
//    `converged` is false (before 2026-12-06 it was set true, by the same
//    rule as a finite SSE no step can lower).
#define BOOST_TEST_MODULE lm_sparse
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "loop/least_squares.hpp"

using namespace drawbend::loop;

// The group factor of three cases: n rows in p groups, r_k = y_k - exp(theta_g(k)), g(k) = k mod p.
struct GroupFactor {
  int n = 4000, p = 40;
  Eigen::VectorXd y;
  GroupFactor() : y(n) {
    for (int k = 0; k < n; ++k) y[k] = std::exp(0.01 * (k % p)) + 1e-3 * std::sin(k);
  }
  double row(const Eigen::VectorXd& t, int k) const { return y[k] - std::exp(t[k % p]); }
  Eigen::VectorXd resid(const Eigen::VectorXd& t) const {
    Eigen::VectorXd r(n);
    for (int k = 0; k < n; ++k) r[k] = row(t, k);
    return r;
  }
};

// The tanh of two cases: r_k = y_k - a tanh(s x_k), y from a = 2, s = 1.5 plus a
// small cosine; d/ds is 0 on every row at a = 0.
struct TanhFit {
  int n = 200;
  Eigen::VectorXd x, y;
  TanhFit() : x(n), y(n) {
    for (int k = 0; k < n; ++k) x[k] = -1 + 2.0 * k / (n - 1), y[k] = 2 * std::tanh(1.5 * x[k]) + 0.01 * std::cos(7 * k);
  }
  double row(const Eigen::VectorXd& t, int k) const { return y[k] - t[0] * std::tanh(t[1] * x[k]); }
  Eigen::VectorXd resid(const Eigen::VectorXd& t) const {
    Eigen::VectorXd r(n);
    for (int k = 0; k < n; ++k) r[k] = row(t, k);
    return r;
  }
};

BOOST_AUTO_TEST_CASE(group_factor_is_sparse_and_exact) {
  const GroupFactor g;
  const int n = g.n, p = g.p;
  auto row = [&](const Eigen::VectorXd& t, int k) { return g.row(t, k); };
  auto resid = [&](const Eigen::VectorXd& t) { return g.resid(t); };
  Eigen::VectorXd th_dense = Eigen::VectorXd::Constant(p, 0.5), th_sparse = th_dense;
  Eigen::MatrixXd Jd, Js;
  bool cd = false, cs = false;
  const long long c0 = lm_jacobian_row_evaluations();
  const double sd = levenberg_marquardt(th_dense, resid, Jd, cd);
  const long long c1 = lm_jacobian_row_evaluations();
  const double ss = levenberg_marquardt(th_sparse, resid, Js, cs, row);
  const long long c2 = lm_jacobian_row_evaluations();
  BOOST_TEST(sd == ss);
  BOOST_TEST((th_dense.array() == th_sparse.array()).all());
  BOOST_TEST((Jd.array() == Js.array()).all());
  BOOST_TEST(cd == cs);
  BOOST_TEST(c2 - c1 <= 2LL * p * n + 100LL * n);
  BOOST_TEST(c1 - c0 > 3LL * p * n);  // the dense fit took more than 2 iterations: the bound above means something
  BOOST_TEST_MESSAGE("row evaluations: dense " << c1 - c0 << ", sparse " << c2 - c1);
}

BOOST_AUTO_TEST_CASE(changing_pattern_falls_back_to_dense) {
  const TanhFit g;
  auto row = [&](const Eigen::VectorXd& t, int k) { return g.row(t, k); };
  auto resid = [&](const Eigen::VectorXd& t) { return g.resid(t); };
  Eigen::VectorXd a(2), b(2);
  a << 0.0, 1.0;
  b = a;
  Eigen::MatrixXd Ja, Jb;
  bool ca = false, cb = false;
  const double sa = levenberg_marquardt(a, resid, Ja, ca);
  const double sb = levenberg_marquardt(b, resid, Jb, cb, row);
  BOOST_TEST(sa == sb);
  BOOST_TEST((a.array() == b.array()).all());
  BOOST_TEST(std::abs(a[0] - 2) < 0.05);
  BOOST_TEST(std::abs(a[1] - 1.5) < 0.1);
}

BOOST_AUTO_TEST_CASE(structural_reads_are_exact_and_checked) {
  const GroupFactor g;
  const int n = g.n, p = g.p;
  auto row = [&](const Eigen::VectorXd& t, int k) { return g.row(t, k); };
  auto resid = [&](const Eigen::VectorXd& t) { return g.resid(t); };
  RowReads right, wrong;
  for (int k = 0; k < n; ++k) right.push_row({k % p}), wrong.push_row({(k + 1) % p});
  Eigen::VectorXd th_dense = Eigen::VectorXd::Constant(p, 0.5), th_right = th_dense, th_wrong = th_dense;
  Eigen::MatrixXd Jd, Jr, Jw;
  bool cd = false, cr = false, cw = false;
  const double sd = levenberg_marquardt(th_dense, resid, Jd, cd);
  const long long c0 = lm_jacobian_row_evaluations();
  const double sr = levenberg_marquardt(th_right, resid, Jr, cr, row, &right);
  const long long c1 = lm_jacobian_row_evaluations();
  const double sw = levenberg_marquardt(th_wrong, resid, Jw, cw, row, &wrong);
  BOOST_TEST(sd == sr);
  BOOST_TEST(sd == sw);
  BOOST_TEST((th_dense.array() == th_right.array()).all());
  BOOST_TEST((th_dense.array() == th_wrong.array()).all());
  BOOST_TEST((Jd.array() == Jr.array()).all());
  BOOST_TEST((Jd.array() == Jw.array()).all());
  BOOST_TEST(cd == cr);
  BOOST_TEST(c1 - c0 <= 4LL * n + 100LL * n);
  BOOST_TEST_MESSAGE("row evaluations with reads: " << c1 - c0);
}

BOOST_AUTO_TEST_CASE(a_nan_start_is_not_converged) {
  const int n = 11;
  Eigen::VectorXd y(n);
  for (int k = 0; k < n; ++k) y[k] = k;
  auto resid = [&](const Eigen::VectorXd& t) { return Eigen::VectorXd((y.array() - t[0]).matrix()); };
  Eigen::VectorXd th = Eigen::VectorXd::Zero(1);
  Eigen::MatrixXd J;
  bool converged = false;
  levenberg_marquardt(th, resid, J, converged);
  BOOST_TEST(converged);
  BOOST_TEST(std::abs(th[0] - 0.5 * (n - 1)) <= 1e-6);
  y[3] = std::nan("");
  th[0] = 0;
  const double sse = levenberg_marquardt(th, resid, J, converged);
  BOOST_TEST(!converged);
  BOOST_TEST(th[0] == 0.0);
  BOOST_TEST(std::isnan(sse));
}

BOOST_AUTO_TEST_CASE(without_the_jacobian_the_same_fit) {
  const GroupFactor g;
  const int n = g.n, p = g.p;
  auto row = [&](const Eigen::VectorXd& t, int k) { return g.row(t, k); };
  auto resid = [&](const Eigen::VectorXd& t) { return g.resid(t); };
  RowReads reads;
  for (int k = 0; k < n; ++k) reads.push_row({k % p});
  Eigen::VectorXd a = Eigen::VectorXd::Constant(p, 0.5), b = a;
  Eigen::MatrixXd Ja, Jb;
  bool ca = false, cb = true;
  const long long c0 = lm_jacobian_row_evaluations();
  const double sa = levenberg_marquardt(a, resid, Ja, ca, row, &reads);
  const long long c1 = lm_jacobian_row_evaluations();
  const double sb = levenberg_marquardt(b, resid, Jb, cb, row, &reads, false);
  const long long c2 = lm_jacobian_row_evaluations();
  BOOST_TEST(sa == sb);
  BOOST_TEST((a.array() == b.array()).all());
  BOOST_TEST(ca == cb);
  BOOST_TEST((c1 - c0) - (c2 - c1) == static_cast<long long>(n));

  // The pattern changes between the start and the solution: caught without the Jacobian too.
  const TanhFit h;
  const int m = h.n;
  auto row2 = [&](const Eigen::VectorXd& t, int k) { return h.row(t, k); };
  auto resid2 = [&](const Eigen::VectorXd& t) { return h.resid(t); };
  RowReads both;
  for (int k = 0; k < m; ++k) both.push_row({0, 1});
  Eigen::VectorXd u(2), v(2), w(2);
  u << 0.0, 1.0;
  v = u, w = u;
  Eigen::MatrixXd Ju, Jv, Jw;
  bool cu = false, cv = false, cw = false;
  const double su = levenberg_marquardt(u, resid2, Ju, cu);  // dense throughout
  const double sv = levenberg_marquardt(v, resid2, Jv, cv, row2, &both);
  const double sw = levenberg_marquardt(w, resid2, Jw, cw, row2, &both, false);
  BOOST_TEST(su == sv);
  BOOST_TEST(sv == sw);
  BOOST_TEST((v.array() == w.array()).all());
  BOOST_TEST((u.array() == w.array()).all());
  BOOST_TEST(std::abs(w[1] - 1.5) < 0.1);
}
