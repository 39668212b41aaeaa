// A local bump of a column as a form (bump.hpp, form_bumps.cpp; h50-bump in
// heldout_record.md).  Expected answers (closed forms):
//  - The scan finds a bump that is there.  A residual that IS a Gaussian bump
//    of x, r_i = 3 b(x_i; c, w) with (c, w) a point of scan_bump's grid (the
//    12th centre and the 4th width of x's range), x on 61 equally spaced
//    values with 3 rows each: the slope of the bump at (c, w) explains all of
//    r's sum of squares about its mean (the correlation is 1), so the scan
//    returns exactly that grid point (the other grid points' bumps are not
//    proportional to it), its explained sum of squares r's.  With a
//    constant added to r and x in another row order, the same.
//  - The support rules.  A bump counts only with at least 5 distinct values
//    of x and max(10, n/20) rows within 1.5 widths of its centre, so
//    scan_bump returns nothing for a column of 4 distinct values (however
//    many rows), nothing when the only bumps with 5 values hold 9 rows of
//    n = 10 (10 needed) or 19 of n = 400 (20 needed), and a bump with 10 of
//    11 or 20 of 400.
//  - The F test counts the centre and width (f_test's extra_q): with extra_q
//    = 2 the p-value is the F distribution's with q + 2 and n - p - 2 degrees
//    of freedom, ((rss_a - rss_b) / (q + 2)) / (rss_b / (n - p - 2)).
//  - The basis.  bump_basis is b(x) centred and scaled to unit sd over the rows.
//  - Keys.  Two models with a bump of one column at another centre or width
//    have different spec_key (fit_memo.hpp): their fits never alias.
#define BOOST_TEST_MODULE loop_bump
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/distributions/fisher_f.hpp>

#include "loop/bump.hpp"
#include "loop/fit_memo.hpp"
#include "loop/forms.hpp"
#include "scan_grid.hpp"

using namespace drawbend::loop;
using drawbend::testing::grid_x;
namespace tt = boost::test_tools;

namespace {

double grid_centre(double lo, double range, int j) { return lo + range * j / (kBumpCentres - 1.0); }
double grid_width(double range, int k) {
  return range * kBumpWidthMin * std::pow(kBumpWidthMax / kBumpWidthMin, k / (kBumpWidths - 1.0));
}

}  // namespace

BOOST_AUTO_TEST_CASE(scan_finds_a_bump_at_its_grid_point) {
  const std::vector<double> x = grid_x();
  const double c = grid_centre(2.0, 12.0, 11), w = grid_width(12.0, 3);
  std::vector<double> r;
  for (double v : x) r.push_back(3.0 * bump_value(v, c, w));
  double m = 0, ss = 0;
  for (double v : r) m += v / r.size();
  for (double v : r) ss += (v - m) * (v - m);
  const auto b = scan_bump(x, r);
  BOOST_REQUIRE(b.has_value());
  BOOST_TEST(b->centre == c, tt::tolerance(1e-12));
  BOOST_TEST(b->width == w, tt::tolerance(1e-12));
  BOOST_TEST(b->explained == ss, tt::tolerance(1e-9));
  // A constant added and the rows reversed: the same grid point.
  std::vector<double> x2(x.rbegin(), x.rend()), r2;
  for (auto it = r.rbegin(); it != r.rend(); ++it) r2.push_back(*it + 7.5);
  const auto b2 = scan_bump(x2, r2);
  BOOST_REQUIRE(b2.has_value());
  BOOST_TEST(b2->centre == c, tt::tolerance(1e-12));
  BOOST_TEST(b2->width == w, tt::tolerance(1e-12));
  // Only the rows asked for: the bump's rows dropped leave no bump there.
  std::vector<char> use(x.size(), 1);
  for (size_t i = 0; i < x.size(); ++i) use[i] = std::abs(x[i] - c) > 4 * w;
  const auto b3 = scan_bump(x, r, use);
  BOOST_TEST((!b3 || std::abs(b3->centre - c) > 2 * w));
}

BOOST_AUTO_TEST_CASE(support_rules_refuse_thin_bumps) {
  // 4 distinct values, 40 rows all near the centre: too few values.
  std::vector<double> x;
  for (int r = 0; r < 10; ++r)
    for (double v : {1.0, 1.1, 1.2, 1.3}) x.push_back(v);
  std::vector<double> r(x.size());
  for (size_t i = 0; i < r.size(); ++i) r[i] = std::sin(3.0 * i);
  BOOST_TEST(!scan_bump(x, r).has_value());
  // The row rules through scan_bump itself: a cluster of 5 values in
  // [0, 0.004] and the rest of the rows at x = 1 (range 1).  The widest bump
  // reaches 1.5 x 0.33 = 0.495 of the range from its centre, so no bump
  // holds the cluster and x = 1 both; a bump of x = 1 alone has 1 value.
  // Only the cluster's rows can support a bump, and r (1 on the cluster, 0
  // at x = 1) gives every supported cluster bump something to explain.
  const auto fixture = [](int cluster_rows, int far_rows, std::vector<double>& xs, std::vector<double>& rs) {
    xs.clear(), rs.clear();
    for (int i = 0; i < cluster_rows; ++i) xs.push_back(0.001 * (i % 5)), rs.push_back(1.0);
    for (int i = 0; i < far_rows; ++i) xs.push_back(1.0), rs.push_back(0.0);
  };
  std::vector<double> xs, rs;
  fixture(9, 1, xs, rs);  // n = 10: 10 rows needed near the centre, 9 there
  BOOST_TEST(!scan_bump(xs, rs).has_value());
  fixture(10, 1, xs, rs);  // 10 there
  const auto b10 = scan_bump(xs, rs);
  BOOST_REQUIRE(b10.has_value());
  BOOST_TEST(b10->centre <= 0.5);
  fixture(19, 381, xs, rs);  // n = 400: max(10, 400 / 20) = 20 needed, 19 there
  BOOST_TEST(!scan_bump(xs, rs).has_value());
  fixture(20, 380, xs, rs);  // 20 there
  BOOST_TEST(scan_bump(xs, rs).has_value());
}

BOOST_AUTO_TEST_CASE(f_test_counts_the_centre_and_width) {
  JointFit a, b;
  a.rss = 500, a.n = 200, a.p = 10;
  b.rss = 450, b.n = 200, b.p = 11;
  const auto p_of = [](double ra, double rb, int q, int dof) {
    const double F = ((ra - rb) / q) / (rb / dof);
    return boost::math::cdf(boost::math::complement(boost::math::fisher_f_distribution<double>(q, dof), F));
  };
  BOOST_TEST(f_test(a, b) == p_of(500, 450, 1, 189), tt::tolerance(1e-12));
  BOOST_TEST(f_test(a, b, 2) == p_of(500, 450, 3, 187), tt::tolerance(1e-12));
  BOOST_TEST(f_test(a, b, 2) > f_test(a, b));
}

BOOST_AUTO_TEST_CASE(bump_basis_is_centred_and_scaled) {
  const std::vector<double> x = grid_x();
  const std::vector<double> b = bump_basis(x, 5.0, 1.5);
  double m = 0, q = 0;
  for (double v : b) m += v / b.size();
  for (double v : b) q += (v - m) * (v - m) / b.size();
  BOOST_TEST(std::abs(m) <= 1e-12);
  BOOST_TEST(q == 1.0, tt::tolerance(1e-12));
  // (b(x) - mean) / sd, the mean and sd (over n) of b(x) over the rows.
  std::vector<double> raw;
  double rm = 0, rq = 0;
  for (double v : x) raw.push_back(bump_value(v, 5.0, 1.5));
  for (double v : raw) rm += v / raw.size();
  for (double v : raw) rq += (v - rm) * (v - rm) / raw.size();
  for (size_t i = 0; i < x.size(); ++i) BOOST_TEST(std::abs(b[i] - (raw[i] - rm) / std::sqrt(rq)) <= 1e-9);
}

BOOST_AUTO_TEST_CASE(bumps_of_another_centre_or_width_never_alias) {
  ModelSpec s;
  Effect e;
  e.kind = EffectKind::generic_smooth;
  e.variable = "oil_age_days";
  e.n_basis = 1;
  e.bump_centre = 10, e.bump_width = 2;
  s.effects.push_back(e);
  ModelSpec t = s, u = s, v = s;
  t.effects[0].bump_centre = 11;
  u.effects[0].bump_width = 3;
  v.effects[0].bump_width = 0;  // the spline of 1 dof
  BOOST_TEST(spec_key(s) != spec_key(t));
  BOOST_TEST(spec_key(s) != spec_key(u));
  BOOST_TEST(spec_key(s) != spec_key(v));
  BOOST_TEST(spec_key(s) == spec_key(ModelSpec(s)));
}
