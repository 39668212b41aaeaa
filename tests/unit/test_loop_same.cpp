// Candidates with the same information share one test (src/loop/screen_same.cpp;
// issue 50, h50-same).  Answers known by construction:
//  - Grouping: 12 tests of 4 rows, one block.  `pin` (categorical, t mod 3),
//    `pin_diameter_mm` (25, 12.5, 6.35 mm by t mod 3), `inv_R_per_mm`
//    (2 / D) and `relabelled` (categorical, the levels of `pin` renamed) split
//    the rows into the same three groups: one group, led by `pin_diameter_mm`
//    (the first numeric member in the candidates' order).  Not grouped:
//    `coarser` (two of the three levels merged: another partition), `wide`
//    (12 distinct values: not probed per level), `pin_gap` (the values of
//    `pin_diameter_mm` but missing on one test: other rows screened) and
//    `test_id` (an identity, a random effect).
//  - One test: a residual of +2 N on the tests with t mod 3 = 1, -1 N on the
//    others, plus a small test-level ripple.  Every member reports the
//    leader's p, permutation count, decision and significance bit for bit,
//    and names it in same_as; the ranking holds 5 tests (the group, coarser,
//    wide, pin_gap, test_id), the Bonferroni family of the round.
#define BOOST_TEST_MODULE loop_same
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "loop/candidates.hpp"

using namespace drawbend::loop;

namespace {

constexpr int kTests = 12, kRows = 4;

Folds one_block() {
  Folds f;
  f.k = 2;
  for (int t = 0; t < kTests; ++t)
    for (int r = 0; r < kRows; ++r) {
      f.block.push_back(0);
      f.test.push_back(t);
      f.fold.push_back((t / 3) % 2);
    }
  return f;
}

Candidate make(const std::string& name, bool categorical, double (*value)(int t)) {
  Candidate c{name, categorical ? "group" : "derived", categorical, true, {}, {}, ""};
  for (int t = 0; t < kTests; ++t)
    for (int r = 0; r < kRows; ++r) c.x.push_back(value(t));
  return c;
}

double diameter(int t) { return t % 3 == 0 ? 25.0 : t % 3 == 1 ? 12.5 : 6.35; }

std::vector<Candidate> candidates() {
  return {make("pin", true, [](int t) { return double(t % 3); }),
          make("coarser", false, [](int t) { return t % 3 == 0 ? 1.0 : 0.0; }),
          make("pin_diameter_mm", false, diameter),
          make("inv_R_per_mm", false, [](int t) { return 2.0 / diameter(t); }),
          make("wide", false, [](int t) { return 0.5 * t * t; }),
          make("relabelled", true, [](int t) { return double((t + 2) % 3); }),
          make("pin_gap", false, [](int t) { return t == 5 ? NAN : diameter(t); }),
          make("test_id", true, [](int t) { return double(t); })};
}

}  // namespace

BOOST_AUTO_TEST_CASE(same_levels_grouped_under_first_numeric) {
  const auto cands = candidates();
  const std::vector<double> resid(kTests * kRows, 0.5);
  const std::vector<int> leader = same_information(cands, resid);
  const std::vector<int> want = {2, 1, 2, 2, 4, 2, 6, 7};
  BOOST_TEST(leader == want, boost::test_tools::per_element());
  // A residual missing on the rows of one test takes those rows out of every
  // candidate alike: pin_gap's missing test is then no difference.
  std::vector<double> gap = resid;
  for (int r = 0; r < kRows; ++r) gap[5 * kRows + r] = NAN;
  BOOST_TEST(same_information(cands, gap)[6] == 2);
}

BOOST_AUTO_TEST_CASE(one_test_reported_for_every_member) {
  const auto cands = candidates();
  const Folds f = one_block();
  std::vector<double> resid;
  for (int t = 0; t < kTests; ++t)
    for (int r = 0; r < kRows; ++r) resid.push_back((t % 3 == 1 ? 2.0 : -1.0) + 0.05 * std::sin(1.7 * t + r));
  const auto res = rank_candidates(cands, resid, f, 2000, 13, 0.05);
  BOOST_TEST(tests_in(res) == 5u);
  const CandidateResult* lead = nullptr;
  for (const auto& c : res)
    if (c.name == "pin_diameter_mm") lead = &c;
  BOOST_REQUIRE(lead);
  BOOST_TEST(lead->same_as.empty());
  BOOST_TEST(lead->n_perm > 0);
  int members = 0;
  for (const auto& c : res) {
    const bool member = c.name == "pin" || c.name == "inv_R_per_mm" || c.name == "relabelled";
    BOOST_TEST((c.same_as == (member ? "pin_diameter_mm" : "")), c.name);
    BOOST_TEST(test_of(c) == (member ? "pin_diameter_mm" : c.name));
    if (!member) continue;
    ++members;
    BOOST_TEST(c.p_value == lead->p_value);
    BOOST_TEST(c.n_perm == lead->n_perm);
    BOOST_TEST(c.decision == lead->decision);
    BOOST_TEST(c.significant == lead->significant);
    BOOST_TEST(c.cv_reduction == lead->cv_reduction);
  }
  BOOST_TEST(members == 3);
}
