// Pairwise probes between numeric columns (src/loop/screen_pairs.cpp, issue 50,
// h50-pairs), on cases with known answers.
//  - Closed form of the statistic: 12 tests of 10 rows, three row-level
//    columns x1, x2, x3 drawn at random, a residual carrying c x1c x2c exactly
//    (xc: the column centred over all rows) and no noise.  The pair's
//    statistic is (sum a p)^2 / E, E = sum_t (sum_t p^2)(sum_t a^2)/(n_t - 1),
//    a the residual centred per test, p the product centred per test and made
//    orthogonal to x1 and x2 (centred per test): the test recomputes it from
//    the data and asks for the same number (1e-9 relative);
//    the family names x1*x2, no permutation reaches it (p = 1 / (1 + b)) and it
//    is significant at 0.05 / 5 (3 columns and 2 families).  The product is
//    made orthogonal by the normal equations (the code uses Gram-Schmidt).
//    Its held-out gain is above 0.8 (reason at the check).  A pure
//    crossover: each single column's slope explains next to nothing (checked: |corr(x1, r)| < 0.35 on these data).
//  - A main effect is not a pair: r = 3 x1 exactly; the products are
//    orthogonal to their own columns, so no family is significant.
//  - The fitted coefficient: noise-free rope-formula rows with
//    mu = 0.1 (1 + 0.2 z), z the z-score of the product of the centred columns
//    g1, g2 (Design::values("g1*g2")): the linear form on "g1*g2" fits beta
//    0.2 (1e-6) with a residual sum of squares below 1e-12.
//  - The null: the same design with a residual of pure noise N(0, 1) (60
//    replicate sets, alpha 0.10 for the family): the joint within-test
//    permutation is exact, so about 6 of 60 alarms are expected; pass when at
//    most 13 of 60 (P(Binomial(60, 0.1) > 13) = 0.002, fixed before the run)
//    and the mean p at least 0.4 (as test_loop_two_level.cpp), for each of
//    the two families (within tests; between the 12 tests of one block).
//  - Determinism: the same results for 1 and 2 threads.
#define BOOST_TEST_MODULE loop_pairs
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

#include "loop/candidates.hpp"
#include "loop/forms.hpp"
#include "loop/model.hpp"

using namespace drawbend::loop;
namespace tt = boost::test_tools;

namespace {

struct Data {
  Folds f;
  std::vector<double> r;
  std::vector<Candidate> cols;
};

Data make(double c, double noise, std::uint64_t seed) {
  Data d;
  std::mt19937_64 g(seed);
  std::normal_distribution<double> nz(0, 1);
  const int tests = 12, rows = 10;
  d.cols = {{"x1", "column", false, false, {}, {}, ""}, {"x2", "column", false, false, {}, {}, ""},
            {"x3", "column", false, false, {}, {}, ""}};
  for (int t = 0; t < tests; ++t)
    for (int k = 0; k < rows; ++k) {
      d.f.block.push_back(0), d.f.test.push_back(t), d.f.fold.push_back(t % 2);
      for (auto& col : d.cols) col.x.push_back(nz(g));
    }
  const size_t n = d.cols[0].x.size();
  double m1 = 0, m2 = 0;
  for (size_t i = 0; i < n; ++i) m1 += d.cols[0].x[i] / n, m2 += d.cols[1].x[i] / n;
  for (size_t i = 0; i < n; ++i) d.r.push_back(c * (d.cols[0].x[i] - m1) * (d.cols[1].x[i] - m2) + noise * nz(g));
  d.f.k = 2;
  return d;
}

}  // namespace

BOOST_AUTO_TEST_CASE(crossover_statistic_in_closed_form) {
  const Data d = make(2.5, 0.0, 11);
  const auto pairs = pair_candidates(d.cols);
  BOOST_TEST_REQUIRE(pairs.size() == 3u);
  BOOST_TEST(pairs[0].name == "x1*x2");
  BOOST_TEST(pair_families(pairs) == 2);  // within tests, and between tests (test means)
  // The closed form: p the product centred per test, made orthogonal to x1 and
  // x2 (centred per test) by the normal equations of p on them; r centred per
  // test; Z = (sum r p)^2 / sum_t (sum_t p^2)(sum_t r^2) / (n_t - 1).
  const std::vector<double>& x = pairs[0].x;
  const size_t n = x.size();
  auto centred = [&](const std::vector<double>& v) {
    std::vector<double> c(n);
    for (int t = 0; t < 12; ++t) {
      double m = 0;
      for (int k = 0; k < 10; ++k) m += v[t * 10 + k] / 10;
      for (int k = 0; k < 10; ++k) c[t * 10 + k] = v[t * 10 + k] - m;
    }
    return c;
  };
  std::vector<double> p = centred(x);
  const std::vector<double> m1 = centred(d.cols[0].x), m2 = centred(d.cols[1].x), rc = centred(d.r);
  double g11 = 0, g12 = 0, g22 = 0, h1 = 0, h2 = 0;
  for (size_t i = 0; i < n; ++i)
    g11 += m1[i] * m1[i], g12 += m1[i] * m2[i], g22 += m2[i] * m2[i], h1 += m1[i] * p[i], h2 += m2[i] * p[i];
  const double det = g11 * g22 - g12 * g12, b1 = (g22 * h1 - g12 * h2) / det, b2 = (g11 * h2 - g12 * h1) / det;
  for (size_t i = 0; i < n; ++i) p[i] -= b1 * m1[i] + b2 * m2[i];
  double num = 0, den = 0;
  for (size_t i = 0; i < n; ++i) num += rc[i] * p[i];
  for (int t = 0; t < 12; ++t) {
    double sp = 0, sr = 0;
    for (int k = 0; k < 10; ++k) sp += p[t * 10 + k] * p[t * 10 + k], sr += rc[t * 10 + k] * rc[t * 10 + k];
    den += sp * sr / 9.0;
  }
  const double Z = num * num / den;
  const auto res = rank_pairs(pairs, d.cols, d.r, d.f, 2000, 3, 0.05 / 5, nullptr);
  BOOST_TEST_REQUIRE(res.size() == 2u);
  BOOST_TEST(res[0].permuted == "within tests (pair family)");
  BOOST_TEST(res[0].name == "x1*x2");
  BOOST_TEST(res[0].kind == "pair");
  BOOST_TEST(res[0].stat == Z, tt::tolerance(1e-9));
  BOOST_TEST(res[0].p_value == 1.0 / (1 + res[0].n_perm), tt::tolerance(1e-12));
  BOOST_TEST(res[0].significant);
  // Held-out gain: positive (a significant family needs it) and large: the
  // noise-free residual is c times the product, whose test means (about a
  // tenth of its sum of squares on these data: 0.915 was measured before the
  // products were made orthogonal to their columns) and its small projection
  // on x1, x2 are all the slope on the probe leaves.
  BOOST_TEST(res[0].cv_reduction > 0.8);
  // The crossover has no main effect to speak of: each column alone.
  for (int j = 0; j < 2; ++j) {
    double sxy = 0, sxx = 0, syy = 0;
    for (size_t i = 0; i < d.r.size(); ++i)
      sxy += d.cols[j].x[i] * d.r[i], sxx += d.cols[j].x[i] * d.cols[j].x[i], syy += d.r[i] * d.r[i];
    BOOST_TEST(std::abs(sxy) / std::sqrt(sxx * syy) < 0.35);
  }
  // Through rank_candidates: the families are two more results, the threshold alpha / (3 + 2).
  ScreenContext one, two;
  two.threads = 2;
  const auto r1 = rank_candidates(d.cols, d.r, d.f, 2000, 3, 0.05, &one, &pairs);
  const auto r2 = rank_candidates(d.cols, d.r, d.f, 2000, 3, 0.05, &two, &pairs);
  BOOST_TEST_REQUIRE(r1.size() == 5u);
  BOOST_TEST(r1[0].name == "x1*x2");
  BOOST_TEST(r1[0].significant);
  for (size_t k = 0; k < r1.size(); ++k) {
    BOOST_TEST(r1[k].name == r2[k].name);
    BOOST_TEST(r1[k].p_value == r2[k].p_value);
    BOOST_TEST(r1[k].stat == r2[k].stat);
  }
}

// A main effect of one column is not a pair: r = 3 x1 exactly (no noise).  Each
// product is orthogonal to its own columns, so the pairs with x1 see nothing
// (statistic 0 to rounding) and x2*x3 only chance: no family significant at 0.05 / 5.
BOOST_AUTO_TEST_CASE(main_effect_is_not_a_pair) {
  Data d = make(0.0, 0.0, 13);
  for (size_t i = 0; i < d.r.size(); ++i) d.r[i] = 3 * d.cols[0].x[i];
  const auto res = rank_pairs(pair_candidates(d.cols), d.cols, d.r, d.f, 2000, 3, 0.05 / 5, nullptr);
  BOOST_TEST_REQUIRE(res.size() == 2u);
  for (const auto& r : res) {
    BOOST_TEST_MESSAGE(r.permuted << ": " << r.name << " stat " << r.stat << " p " << r.p_value);
    BOOST_TEST(!r.significant);
  }
}

BOOST_AUTO_TEST_CASE(pair_null_is_calibrated) {
  for (int fam = 0; fam < 2; ++fam) {  // within tests, between tests
    int alarms = 0;
    double mp = 0;
    for (int s = 0; s < 60; ++s) {
      const Data d = make(0.0, 1.0, 2000 + s);
      const auto r = rank_pairs(pair_candidates(d.cols), d.cols, d.r, d.f, 400, 31 + s, 0.10, nullptr);
      alarms += r[fam].p_value <= 0.10;
      mp += r[fam].p_value / 60;
    }
    BOOST_TEST_MESSAGE("pair null, family " << fam << ": " << alarms << " of 60 with p <= 0.10, mean p " << mp);
    BOOST_TEST(alarms <= 13);
    BOOST_TEST(mp >= 0.4);
  }
}

namespace {

// Rope-formula rows (no noise): mu = 0.1 (1 + beta z), z the z-score of the
// product of the centred columns g1, g2 (one value each per row).
Dataset rope_rows(double beta) {
  Dataset d;
  d.has_sliding = d.has_time = false;
  d.extra_columns = {"g1", "g2"};
  std::mt19937_64 g(5);
  std::uniform_real_distribution<double> u(1, 9);
  for (int t = 0; t < 8; ++t)
    for (int k = 0; k < 6; ++k)
      for (bool rot : {true, false}) {
        Sample s;
        s.test_id = (rot ? "r" : "f") + std::to_string(t);
        s.pin_d_mm = 12.7;
        s.rotating = rot;
        s.speed_mm_s = 25.4;
        s.lubricant = "oil";
        s.back_tension_N = 1400 + 100 * k;
        char a[32], b[32];
        std::snprintf(a, sizeof a, "%.3f", u(g));
        std::snprintf(b, sizeof b, "%.3f", u(g));
        s.extra = {a, b};
        d.rows.push_back(s);
      }
  std::vector<double> x1, x2;
  for (const auto& s : d.rows) x1.push_back(std::stod(s.extra[0])), x2.push_back(std::stod(s.extra[1]));
  double m1 = 0, m2 = 0;
  for (size_t i = 0; i < x1.size(); ++i) m1 += x1[i] / x1.size(), m2 += x2[i] / x2.size();
  std::vector<double> z(x1.size());
  for (size_t i = 0; i < z.size(); ++i) z[i] = (x1[i] - m1) * (x2[i] - m2);
  zscore_in_place(z);
  const double b0 = 300, b1 = -0.05;
  for (size_t i = 0; i < d.rows.size(); ++i) {
    Sample& s = d.rows[i];
    const double mu = 0.1 * (1 + beta * z[i]), F = s.back_tension_N;
    s.outlet_force_N = F + b0 + b1 * F + (s.rotating ? 0.0 : F * (std::exp(mu * M_PI / 2) - 1));
  }
  return d;
}

}  // namespace

BOOST_AUTO_TEST_CASE(product_coefficient_recovered) {
  const Dataset d = rope_rows(0.2);
  const MapLibrary maps = MapLibrary::stand_in({12.7});
  const Design des = make_design(d, maps);
  const std::vector<double> p = des.values("g1*g2"), a = des.values("g1"), b = des.values("g2");
  double ma = 0, mb = 0;
  for (size_t i = 0; i < a.size(); ++i) ma += a[i] / a.size(), mb += b[i] / b.size();
  for (size_t i = 0; i < p.size(); ++i) BOOST_TEST(p[i] == (a[i] - ma) * (b[i] - mb), tt::tolerance(1e-9));
  const ModelSpec s = with_effect(des, ModelSpec{}, EffectKind::generic_linear, "g1*g2");
  BOOST_TEST_REQUIRE(s.effects.size() == 1u);
  const Fit f = fit_model(des, s);
  BOOST_TEST(f.rss < 1e-12);
  BOOST_TEST(f.theta[f.theta.size() - 1] == 0.2, tt::tolerance(1e-6));
}
