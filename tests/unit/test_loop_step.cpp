// A step of a column as a form (bump.hpp, form_bumps.cpp; h50-step in
// heldout_record.md).  Expected answers (closed forms):
//  - The scan finds a step that is there.  A residual that IS a step of x,
//    r_i = 2 [x_i > t] with t midway between the 21st and 22nd of 61 equally
//    spaced values (3 rows each): the step at t explains all of r's sum of
//    squares about its mean, 4 n_above (1 - n_above / n) = 4 * 120 * 63 /
//    183, and every other threshold less (its correlation with r is below
//    1), so scan_step returns t and that sum.  With a constant added and the
//    rows reversed, the same.
//  - The support rules.  A threshold counts only with at least 2 distinct
//    values and max(10, n / 20) rows on each side: a step after the first
//    value (1 value below) or with 9 rows below (10 needed) is not returned,
//    the same step with 10 rows below is; fewer than 5 distinct values: none.
//  - The basis.  step_basis is [x > t] centred and scaled to unit sd over the
//    rows: (s - m) / sqrt(m (1 - m)), m the share of rows above t.
//  - The F test counts the threshold: searched_params of a step effect is 1
//    (a bump's 2), and two models with steps at other thresholds have
//    different spec_key (their fits never alias).
//  - The same model named by its simpler description (takes_the_step,
//    aliases.hpp): a form whose held-out predictions equal the held one's
//    (within 1e-6 x its RMS) takes the step only with fewer parameters (2 vs
//    1: no; 1 vs 2: yes; 1 vs 1: no, the one held), whatever the rounding of
//    the RMS; forms that predict differently compare by held-out RMS only
//    (lower takes it, even with more parameters).
#define BOOST_TEST_MODULE loop_step
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "loop/aliases.hpp"
#include "loop/bump.hpp"
#include "loop/fit_memo.hpp"
#include "loop/forms.hpp"
#include "scan_grid.hpp"

using namespace drawbend::loop;
using drawbend::testing::grid_x;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_CASE(scan_finds_a_step_at_its_threshold) {
  const std::vector<double> x = grid_x();
  const double t = 0.5 * ((2.0 + 12.0 * 20 / 60.0) + (2.0 + 12.0 * 21 / 60.0));
  std::vector<double> r;
  for (double v : x) r.push_back(v > t ? 2.0 : 0.0);
  const auto s = scan_step(x, r);
  BOOST_REQUIRE(s.has_value());
  BOOST_TEST(s->at == t, tt::tolerance(1e-12));
  BOOST_TEST(s->explained == 4.0 * 120 * 63 / 183.0, tt::tolerance(1e-9));
  std::vector<double> x2(x.rbegin(), x.rend()), r2;
  for (auto it = r.rbegin(); it != r.rend(); ++it) r2.push_back(*it - 3.25);
  const auto s2 = scan_step(x2, r2);
  BOOST_REQUIRE(s2.has_value());
  BOOST_TEST(s2->at == t, tt::tolerance(1e-12));
  BOOST_TEST(s2->explained == s->explained, tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(support_rules_refuse_thin_steps) {
  // Values 0..5; r = 1 above `cut`, rows per value given.
  const auto fixture = [](const std::vector<int>& rows, double cut, std::vector<double>& xs, std::vector<double>& rs) {
    xs.clear(), rs.clear();
    for (size_t v = 0; v < rows.size(); ++v)
      for (int i = 0; i < rows[v]; ++i) xs.push_back(static_cast<double>(v)), rs.push_back(v > cut ? 1.0 : 0.0);
  };
  std::vector<double> xs, rs;
  fixture({20, 20, 20, 20, 20, 20}, 0.5, xs, rs);  // 1 value below 0.5: refused
  const auto a = scan_step(xs, rs);
  BOOST_TEST((!a || a->at != 0.5));
  fixture({4, 5, 20, 20, 20, 20}, 1.5, xs, rs);  // n = 89: 10 rows a side needed, 9 below 1.5
  const auto b = scan_step(xs, rs);
  BOOST_TEST((!b || b->at != 1.5));
  fixture({5, 5, 20, 20, 20, 20}, 1.5, xs, rs);  // 10 below
  const auto c = scan_step(xs, rs);
  BOOST_REQUIRE(c.has_value());
  BOOST_TEST(c->at == 1.5);
  fixture({20, 20, 20, 20}, 1.5, xs, rs);  // 4 distinct values: no step
  BOOST_TEST(!scan_step(xs, rs).has_value());
  // Only the rows asked for: without the rows above the cut nothing changes there.
  fixture({20, 20, 20, 20, 20, 20}, 2.5, xs, rs);
  std::vector<char> use(xs.size(), 1);
  for (size_t i = 0; i < xs.size(); ++i) use[i] = xs[i] < 2.5;
  BOOST_TEST(!scan_step(xs, rs, use).has_value());  // 3 values left: fewer than 5
}

BOOST_AUTO_TEST_CASE(step_basis_is_centred_and_scaled) {
  const std::vector<double> x = grid_x();
  const double t = 7.1;
  const std::vector<double> b = step_basis(x, t);
  double m = 0;
  for (double v : x) m += (v > t ? 1.0 : 0.0) / x.size();
  for (size_t i = 0; i < x.size(); ++i)
    BOOST_TEST(std::abs(b[i] - ((x[i] > t ? 1.0 : 0.0) - m) / std::sqrt(m * (1 - m))) <= 1e-12);
  const std::vector<double> none = step_basis(x, 100.0);  // no row above: all zeros
  for (double v : none) BOOST_TEST(v == 0.0);
}

BOOST_AUTO_TEST_CASE(the_threshold_is_counted_and_keyed) {
  Effect e;
  e.kind = EffectKind::force_offset;
  e.variable = "pin_travel_m";
  e.n_basis = 1;
  e.step = true, e.step_at = 2.0;
  BOOST_TEST(searched_params({e}) == 1);
  Effect b = e;
  b.step = false, b.step_at = 0, b.bump_centre = 2.0, b.bump_width = 0.5;
  BOOST_TEST(searched_params({b}) == 2);
  ModelSpec s;
  s.effects.push_back(e);
  ModelSpec t = s, u = s;
  t.effects[0].step_at = 2.5;
  u.effects[0].step = false;  // the spline of 1 dof
  BOOST_TEST(spec_key(s) != spec_key(t));
  BOOST_TEST(spec_key(s) != spec_key(u));
  BOOST_TEST(spec_key(s) == spec_key(ModelSpec(s)));
}

BOOST_AUTO_TEST_CASE(the_same_model_is_named_by_fewer_parameters) {
  CvResult held;
  held.pred = {10.0, 12.0, 14.0, 16.0};
  held.rms = 3.0;
  FormTrial a;
  a.cv.pred = {10.0, 12.0, 14.0 + 1e-9, 16.0};  // the same model: 5e-10 N RMS apart
  a.cv.rms = 3.0 - 1e-9;                         // lower by rounding
  a.q = 2;
  BOOST_TEST(!takes_the_step(a, held, 1));  // more parameters: not taken despite the lower RMS
  a.cv.rms = 3.0 + 1e-9;
  a.q = 1;
  BOOST_TEST(takes_the_step(a, held, 2));   // fewer parameters: taken despite the higher RMS
  BOOST_TEST(!takes_the_step(a, held, 1));  // as many: the one held
  FormTrial b;
  b.cv.pred = {10.0, 12.5, 14.0, 16.0};  // another model: 0.25 N RMS apart
  b.cv.rms = 2.9;
  b.q = 5;
  BOOST_TEST(takes_the_step(b, held, 1));  // lower RMS takes it
  b.cv.rms = 3.1;
  b.q = 0;
  BOOST_TEST(!takes_the_step(b, held, 1));  // higher RMS does not, however few its parameters
}
