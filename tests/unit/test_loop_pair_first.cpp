// A pair step must beat its own columns (src/loop/pair_first.hpp, issue 50
// item 3, h50-pairfirst), on cases with known answers.
//  - The rule in closed form (pair_or_member): 4 tests of one row; the pair's
//    held-out residual is 1 on every row (MSE 1).  Column A's squared
//    residuals exceed 1 by {0.2, 0, 0.2, 0} per test: MSE difference 0.1, its
//    standard error sqrt(sum_t (d_t - 0.1)^2 * 4 / 3) / 4 = sqrt(0.04 * 4 / 3)
//    / 4 = 0.0577, so A is NOT within one standard error.  Column B's by
//    {0.1, -0.1, 0.1, 0.02}: difference 0.03, standard error sqrt(0.0268 * 4 /
//    3) / 4 = 0.0473: B takes the step.  A column with no passed form never
//    takes it (even with a perfect held-out result); of two columns within
//    one standard error, the lower RMS; a column better than the pair takes it.
//  - The loop on rope-formula data (noise sd 3 N, 20 fixed-pin tests of 10
//    rows and 4 rotating-pin tests): mu = 0.1 (1 + 0.3 exp(-(g1 - min g1) /
//    lambda)), lambda a tenth of g1's range: the response is driven by the
//    column g1 alone.  A second column g2 explains nothing of it: (a) drawn
//    independently per row; (b) test-level, a linear function of each test's
//    mean temperature (as a second thermometer would be), so correlated with
//    g1 but with no effect of its own (g1 carries the effect within tests too).
//    In both, the loop's first step must be on g1 and no step on the pair
//    g1*g2.  Case (b) is the failure of held-out run 16, wild set 1: within a
//    test the product of g1 with a column that follows g1's test means is a
//    slope in g1 that grows with the test's temperature, so it follows the
//    curve of the decay that a straight line in g1 misses.  A scan of 90 such
//    sets (lambda = range / 10, 20, 40; seeds 1-15; (a) and (b)) found the
//    pair the round's best step in 4, all (b); three of them are used here
//    (lambda = range / 40 seed 3, range / 20 seeds 4 and 8), and there the
//    test also requires the loop's note that g1 took the step from the pair,
//    so that the case the rule is for does occur.  The cases (a) keep
//    lambda = range / 10.
#define BOOST_TEST_MODULE loop_pair_first
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "loop/loop.hpp"
#include "loop/forms.hpp"
#include "loop/maps.hpp"
#include "loop/pair_first.hpp"

using namespace drawbend::loop;
namespace tt = boost::test_tools;

namespace {

Folds four_tests() {
  Folds f;
  f.k = 2;
  for (int t = 0; t < 4; ++t) f.fold.push_back(t % 2), f.block.push_back(0), f.test.push_back(t);
  return f;
}

// A held-out result whose squared residual on test t is 1 + d[t].
CvResult with_excess(const std::vector<double>& d) {
  CvResult c;
  double s = 0;
  for (double x : d) c.resid.push_back(std::sqrt(1 + x)), c.pred.push_back(0), s += 1 + x;
  c.rms = std::sqrt(s / d.size());
  c.n = static_cast<int>(d.size());
  return c;
}

PairMember member(const std::string& name, bool passed, const CvResult& cv) {
  PairMember m;
  m.name = name, m.passed = passed, m.best = cv, m.significant = true;
  return m;
}

}  // namespace

BOOST_AUTO_TEST_CASE(rule_in_closed_form) {
  const Folds f = four_tests();
  const CvResult pair = with_excess({0, 0, 0, 0});
  const CvResult a = with_excess({0.2, 0, 0.2, 0}), b = with_excess({0.1, -0.1, 0.1, 0.02});
  BOOST_TEST(mse_diff_se(a, pair, f) == std::sqrt(0.04 * 4 / 3) / 4, tt::tolerance(1e-12));
  BOOST_TEST(mse_diff_se(b, pair, f) == std::sqrt(0.0268 * 4 / 3) / 4, tt::tolerance(1e-12));
  // A alone: beyond one standard error, the pair keeps the step.
  PairVerdict v = pair_or_member("A*B", pair, {member("A", true, a)}, f);
  BOOST_TEST(v.member == -1);
  BOOST_TEST(v.note.find("kept the step") != std::string::npos);
  // A and B: B within one standard error takes it.
  v = pair_or_member("A*B", pair, {member("A", true, a), member("B", true, b)}, f);
  BOOST_TEST(v.member == 1);
  BOOST_TEST(v.note.find("B took the step from the pair A*B") == 0u);
  BOOST_TEST(v.note.find("within one standard error of the pair") != std::string::npos);
  // A column with no passed form never takes the step, whatever its result.
  v = pair_or_member("A*B", pair, {member("A", false, with_excess({-0.5, -0.5, -0.5, -0.5})), member("B", true, a)}, f);
  BOOST_TEST(v.member == -1);
  BOOST_TEST(v.note.find("no form passed") != std::string::npos);
  // Two within one standard error: the lower RMS; a column better than the pair qualifies.
  const CvResult better = with_excess({-0.1, -0.1, -0.1, -0.1});
  v = pair_or_member("A*B", pair, {member("A", true, b), member("B", true, better)}, f);
  BOOST_TEST(v.member == 1);
  BOOST_TEST(v.note.find("better than the pair") != std::string::npos);
}

namespace {

// Rope-formula rows: 12.7 mm pin, 20 fixed-pin tests of 10 back tensions and
// 4 rotating-pin tests; each test at its own room temperature T_t.  g1: a
// row-level temperature (T_t plus a drift within the test and reading noise);
// g2: (a) independent, or (b) a test-level reading 1.8 T_t + 32 (rounded to
// 0.1).  mu = 0.1 (1 + 0.3 exp(-(g1 - min g1) / lambda)), lambda = range / 10.
Dataset rows(bool g2_test_level, std::uint64_t seed, double frac = 10) {
  Dataset d;
  d.has_sliding = false, d.has_time = false;
  d.extra_columns = {"g1", "g2"};
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> room(18, 22), u(0, 1);
  std::normal_distribution<double> nz(0, 1);
  std::vector<double> g1;
  for (int t = 0; t < 24; ++t) {
    const bool rot = t >= 20;
    const double T = room(g);
    for (int k = 0; k < 10; ++k) {
      Sample s;
      s.test_id = (rot ? "r" : "f") + std::to_string(t);
      s.pin_d_mm = 12.7, s.rotating = rot, s.speed_mm_s = 25.4, s.lubricant = "oil";
      s.back_tension_N = 1000 + 100 * k;
      const double x1 = T + 0.05 * k + 0.05 * nz(g);
      const double x2 = g2_test_level ? 1.8 * T + 32 : 60 + 20 * u(g);
      char a[32], b[32];
      std::snprintf(a, sizeof a, "%.3f", x1);
      std::snprintf(b, sizeof b, "%.1f", x2);
      s.extra = {a, b};
      g1.push_back(std::stod(a));
      d.rows.push_back(s);
    }
  }
  double lo = g1[0], hi = g1[0];
  for (double x : g1) lo = std::min(lo, x), hi = std::max(hi, x);
  const double lambda = (hi - lo) / frac, b0 = 300, b1 = -0.05;
  for (size_t i = 0; i < d.rows.size(); ++i) {
    Sample& s = d.rows[i];
    const double mu = 0.1 * (1 + 0.3 * std::exp(-(g1[i] - lo) / lambda)), F = s.back_tension_N;
    s.outlet_force_N = F + b0 + b1 * F + (s.rotating ? 0.0 : F * (std::exp(mu * M_PI / 2) - 1)) + 3 * nz(g);
  }
  return d;
}

LoopResult loop_on(const Dataset& d) {
  static const MapLibrary maps = MapLibrary::stand_in({12.7});
  const Design des = make_design(d, maps);
  LoopOptions o;
  return run_loop(des, o);
}

std::string steps_text(const LoopResult& r) {
  std::string s;
  for (const auto& k : r.steps) s += k.variable + " -> " + k.effect + "; ";
  return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(one_column_not_its_pair) {
  struct Case {
    bool g2_test_level;
    std::uint64_t seed;
    double frac;
  };
  // (a) g2 independent; (b) g2 test-level, the sets of the scan where the
  // pair was a round's best step (see the header).
  for (const Case& c : {Case{false, 1, 10}, Case{false, 2, 10}, Case{false, 3, 10}, Case{true, 3, 40},
                        Case{true, 4, 20}, Case{true, 8, 20}}) {
    const LoopResult r = loop_on(rows(c.g2_test_level, c.seed, c.frac));
    std::string notes;
    for (const auto& s : r.steps) notes += s.pair_note;
    BOOST_TEST_MESSAGE((c.g2_test_level ? "g2 test-level" : "g2 independent")
                       << ", seed " << c.seed << ", lambda = range / " << c.frac << ": " << steps_text(r) << notes);
    BOOST_TEST_REQUIRE(!r.steps.empty());
    BOOST_TEST(r.steps[0].variable == "g1");
    for (const auto& s : r.steps) BOOST_TEST(s.columns.empty());  // no step on a pair
    if (c.g2_test_level) BOOST_TEST(notes.find("g1 took the step from the pair") != std::string::npos);
  }
}
