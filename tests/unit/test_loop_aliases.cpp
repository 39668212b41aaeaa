// Collinear naming (src/loop/aliases.hpp): the share of a step's effect that
// another column's groups explain, and which columns are tried as aliases.
//  - Design: 60 tests run in order t = 0..59, 10 rows each (600 rows), two
//    blocks (even and odd tests).  Columns: test_order = t (test-level,
//    numeric, 60 values); operator = the shift, t * 3 / 60 (3 levels of 20
//    tests, categorical); cycle_count = 10 t + row (row-level, 600 values);
//    scrambled = (37 t) mod 60 (test-level, unrelated to t: a permutation);
//    strip_id = one level per test (60 levels, categorical); pin_d = a column
//    confounded with a model input; avg_p = a derived quantity.  The step's
//    effect e = 0.1 t on every row.
//  - Closed form: t centred per block has a variance of about (60^2 - 1) / 12
//    = 300 (tests), so
//      test_order, 8 quantile bins of 7 or 8 consecutive tests: within-bin
//        variance (7.5^2 - 1) / 12 = 4.6, share about 1 - 4.6 / 300 = 0.985;
//      cycle_count, 8 bins of 75 rows (7.5 tests): the same, about 0.985;
//      operator, 3 levels of 20 tests: within (20^2 - 1) / 12 = 33.25, share
//        about 1 - 33.25 / 300 = 0.889;
//      scrambled: a test-level column unrelated to e explains about
//        7 / 59 = 0.12 by its 8 bins alone (the reason for kAliasShare 0.2);
//        this fixed permutation is one draw of that, expected below 0.35;
//      strip_id: more than 12 levels, an identity, share 0 by rule.
//    Expected alias_columns(x = test_order): cycle_count then operator (the
//    shares, largest first), not scrambled (below 0.2), not strip_id, pin_d
//    (confounded) or avg_p (derived); with max 1 only cycle_count; with
//    test_order itself in `skip` no change (x is never its own alias).
//    Tolerance 0.005 on the three closed forms (the bins hold 7 or 8 tests,
//    not 7.5, and the block centring shifts t by 0.5: effects below 0.005).
//    Measured (first run): test_order 0.9836, cycle_count 0.9834, operator
//    0.8899, scrambled 0.0304.
//  - Missing values: e NaN on the first test's rows and operator NaN on the
//    second test's are skipped (the share stays within 0.02 of the above).
//  - prediction_rms_diff: a = {1, 2, NaN, 4}, b = {1, 0, 5, 1}: the rows
//    both predict differ by 0, 2, 3, so sqrt(13 / 3) = 2.0817 (1e-12).
//  - name_alikes: 4 tests of 5 rows, the step's residual -1 on every row.
//    Column C predicts the same (MSE difference 0, within its SE 0):
//    aliased_with.  Column A predicts 0.1 N higher on every row: residual
//    -1.1, MSE difference 0.21 N^2 in every test, so its SE is 0 and the
//    paired test prefers the step; its predictions are within 0.1 N RMS, under
//    a minimum effect of 0.5 N: same_effect_as.  Column B predicts 2 N higher:
//    neither.  The step's own column is skipped.  With no usable noise
//    (minimum effect NaN) A is not listed.  The names, aliased first, go to
//    alike_names as given: a column "A (lot)" keeps its " (" (the summary
//    once cut names there).
#define BOOST_TEST_MODULE loop_aliases
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "loop/aliases.hpp"
#include "loop/loop.hpp"

using namespace drawbend::loop;
namespace tt = boost::test_tools;

namespace {

struct Data {
  std::vector<double> e;
  std::vector<int> block;
  std::vector<Candidate> cands;
};

Data make() {
  Data d;
  Candidate order{"test_order", "column", false, true, {}, {}, ""};
  Candidate op{"operator", "column", true, true, {}, {"A", "B", "C"}, ""};
  Candidate cyc{"cycle_count", "column", false, false, {}, {}, ""};
  Candidate scr{"scrambled", "column", false, true, {}, {}, ""};
  Candidate strip{"strip_id", "column", true, true, {}, {}, ""};
  Candidate pin{"pin_d", "column", false, true, {}, {}, "pin"};
  Candidate avg{"avg_p", "derived", false, false, {}, {}, ""};
  for (int t = 0; t < 60; ++t) strip.levels.push_back("S" + std::to_string(t));
  for (int t = 0; t < 60; ++t)
    for (int k = 0; k < 10; ++k) {
      d.e.push_back(0.1 * t);
      d.block.push_back(t % 2);
      order.x.push_back(t);
      op.x.push_back(t * 3 / 60);
      cyc.x.push_back(10 * t + k);
      scr.x.push_back((37 * t) % 60);
      strip.x.push_back(t);
      pin.x.push_back(t);
      avg.x.push_back(t);
    }
  d.cands = {order, op, cyc, scr, strip, pin, avg};
  return d;
}

}  // namespace

BOOST_AUTO_TEST_CASE(shares_and_aliases) {
  const Data d = make();
  const double s_order = explained_share(d.e, d.block, d.cands[0]);
  const double s_op = explained_share(d.e, d.block, d.cands[1]);
  const double s_cyc = explained_share(d.e, d.block, d.cands[2]);
  const double s_scr = explained_share(d.e, d.block, d.cands[3]);
  BOOST_TEST_MESSAGE("shares: test_order " << s_order << " operator " << s_op << " cycle_count " << s_cyc
                                           << " scrambled " << s_scr);
  BOOST_TEST(std::abs(s_order - 0.985) < 0.005);
  BOOST_TEST(std::abs(s_cyc - 0.985) < 0.005);
  BOOST_TEST(std::abs(s_op - 0.889) < 0.005);
  BOOST_TEST(s_scr < 0.35);
  BOOST_TEST(explained_share(d.e, d.block, d.cands[4]) == 0.0);  // 60 levels: identity
  const auto a = alias_columns(d.cands, d.e, d.block, "test_order", {});
  BOOST_TEST_REQUIRE(a.size() == 2u);
  BOOST_TEST(a[0].name == "cycle_count");
  BOOST_TEST(a[1].name == "operator");
  const auto one = alias_columns(d.cands, d.e, d.block, "test_order", {}, kAliasShare, 1);
  BOOST_TEST_REQUIRE(one.size() == 1u);
  BOOST_TEST(one[0].name == "cycle_count");
  const auto skipped = alias_columns(d.cands, d.e, d.block, "test_order", {"cycle_count", "test_order"});
  BOOST_TEST_REQUIRE(skipped.size() == 1u);
  BOOST_TEST(skipped[0].name == "operator");
}

BOOST_AUTO_TEST_CASE(missing_values_skipped) {
  Data d = make();
  for (int k = 0; k < 10; ++k) d.e[k] = NAN, d.cands[1].x[10 + k] = NAN;
  BOOST_TEST(std::abs(explained_share(d.e, d.block, d.cands[0]) - 0.985) < 0.02);
  BOOST_TEST(std::abs(explained_share(d.e, d.block, d.cands[1]) - 0.889) < 0.02);
  const std::vector<double> flat(d.e.size(), 1.0);  // constant e: nothing to explain
  BOOST_TEST(explained_share(flat, d.block, d.cands[0]) == 0.0);
}

BOOST_AUTO_TEST_CASE(prediction_difference_known_answer) {
  const double d = prediction_rms_diff({1, 2, NAN, 4}, {1, 0, 5, 1});
  BOOST_TEST(std::abs(d - std::sqrt(13.0 / 3.0)) < 1e-12);
  BOOST_TEST(std::isnan(prediction_rms_diff({NAN}, {1.0})));
}

BOOST_AUTO_TEST_CASE(same_effect_listed_apart_from_aliases) {
  Folds f;
  for (int t = 0; t < 4; ++t)
    for (int r = 0; r < 5; ++r) f.test.push_back(t), f.block.push_back(0), f.fold.push_back(t);
  auto model = [](double shift) {  // predictions 10 + shift, residual -1 - shift (y = 9 on every row)
    CvResult c;
    c.pred.assign(20, 10 + shift);
    c.resid.assign(20, -1 - shift);
    c.rms = 1 + shift;
    c.n = 20;
    return c;
  };
  const CvResult best = model(0);
  const std::vector<std::pair<std::string, CvResult>> kept = {
      {"x", best}, {"A (lot)", model(0.1)}, {"C", model(0)}, {"B", model(2)}};
  Step s;
  s.variable = "x";
  name_alikes(s, kept, best, f, 0.5);
  BOOST_TEST_REQUIRE(s.aliased_with.size() == 1u);
  BOOST_TEST(s.aliased_with[0].rfind("C (", 0) == 0);
  BOOST_TEST_REQUIRE(s.same_effect_as.size() == 1u);
  BOOST_TEST(s.same_effect_as[0].rfind("A (lot) (", 0) == 0);
  BOOST_TEST(s.alike_names == (std::vector<std::string>{"C", "A (lot)"}), tt::per_element());
  Step none;
  none.variable = "x";
  name_alikes(none, kept, best, f, NAN);
  BOOST_TEST(none.same_effect_as.empty());
  BOOST_TEST(none.aliased_with.size() == 1u);
}
