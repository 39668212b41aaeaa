// Residual analysis and the loop on small cases with known answers (src/loop).
//  - Categorical probe: one block, residual +1 on level A and -1 on level B
//    (8 tests of 2 rows each, 4 per level): explained SS = sum r^2 = 16 exactly;
//    the between-test permutation p is small (<= 0.05).
//  - Orthogonal case: each level carries residuals {+1, -1}: explained SS = 0,
//    p = 1 (every permutation reaches 0).
//  - Numeric probe: residual r = 3 x (x varies within tests, and its test
//    means by 0.1 between them: permuted on both levels): explained SS =
//    sum r^2 exactly.
//  - The fit recovers mu = 0.1 exactly from noise-free rope-formula data
//    F_out = F + F_B + F (exp(0.1 pi/2) - 1), and b0, b1 of the bending line.
//  - Loop on synthetic data: no hidden effect -> no step (empty "steps" in the
//    summary; the stop reason may still list screened variables); a planted test-order
//    drift -> first step names test_order and lowers the held-out RMS to within
//    30 % of the noise sd.
//  - The same drift in a column the library does not know (test_order renamed
//    lab_reading): the loop adds a generic effect of that column (linear or
//    saturating) with its size, SE and sign (mu increases with run order in
//    the generator, so the sign is "increases").
//  - FastMod (the shuffle's x % k without division) equals x % k exactly for
//    k = 2..1000 on 0, 1, k-1, k, 2^64-1, 2^63, the multiples of k next to
//    2^64 and 200 mt19937_64 draws per k.
//  - FastMod32 (the same for 32-bit x) equals x % k exactly for k = 2..5000
//    on 0, 1, k-1, k, 2^32-1, 2^31, the multiples of k next to 2^32 and 200
//    32-bit draws per k.
//  - Mt64 (the shuffle's random numbers) equals std::mt19937_64 number for
//    number: 100,000 draws (320 refills) from each of 5 seeds; its blocks
//    (available, take: the shuffle's) too, across refills.
//  - Mt64Halves (the shuffle's 32-bit draws) gives each std::mt19937_64
//    number's low half and then its high half, 200,000 draws from 3 seeds,
//    by calls and by blocks of 1 to 97 across refills.
#define BOOST_TEST_MODULE loop_residuals
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <random>

#include "loop/candidates.hpp"
#include "loop/fast_mod.hpp"
#include "loop/loop.hpp"
#include "loop/mt64.hpp"
#include "loop/synth.hpp"

using namespace drawbend::loop;
namespace tt = boost::test_tools;

static Folds one_block(int tests, int rows_per_test) {
  Folds f;
  f.k = 2;
  for (int t = 0; t < tests; ++t)
    for (int r = 0; r < rows_per_test; ++r) {
      f.block.push_back(0);
      f.test.push_back(t);
      f.fold.push_back((t / 2) % 2);
    }
  return f;
}

BOOST_AUTO_TEST_CASE(categorical_probe_known_answer) {
  const Folds f = one_block(8, 2);
  Candidate c{"lvl", "column", true, true, {}, {"A", "B"}, ""};
  std::vector<double> r;
  for (int t = 0; t < 8; ++t)
    for (int k = 0; k < 2; ++k) {
      c.x.push_back(t % 2);
      r.push_back(t % 2 ? -1.0 : 1.0);
    }
  auto res = rank_candidates({c}, r, f, 999, 7, 0.05);
  BOOST_TEST(res[0].stat == 16.0, tt::tolerance(1e-12));
  BOOST_TEST(res[0].p_value <= 0.05);
  BOOST_TEST(res[0].cv_reduction == 1.0, tt::tolerance(1e-12));
  // orthogonal: each level carries +1 and -1
  std::vector<double> r2;
  for (int t = 0; t < 8; ++t)
    for (int k = 0; k < 2; ++k) r2.push_back(k ? -1.0 : 1.0);
  res = rank_candidates({c}, r2, f, 199, 7, 0.05);
  BOOST_TEST(res[0].stat == 0.0, tt::tolerance(1e-12));
  BOOST_TEST(res[0].p_value == 1.0);
  BOOST_TEST(!res[0].significant);
}

BOOST_AUTO_TEST_CASE(numeric_probe_known_answer) {
  const Folds f = one_block(4, 5);
  Candidate c{"x", "column", false, false, {}, {}, ""};
  std::vector<double> r;
  double ss = 0, mean = 0;
  for (int t = 0; t < 4; ++t)
    for (int k = 0; k < 5; ++k) c.x.push_back(k + 0.1 * t), mean += (k + 0.1 * t) / 20;
  for (double x : c.x) r.push_back(3 * (x - mean)), ss += 9 * (x - mean) * (x - mean);
  const auto res = rank_candidates({c}, r, f, 999, 7, 0.05);
  BOOST_TEST(res[0].stat == ss, tt::tolerance(1e-9));
  // its test means differ (0.1 t): permuted within and between tests (screen.cpp: two_level)
  BOOST_TEST(res[0].permuted == "within and between tests");
  BOOST_TEST(res[0].p_value <= 0.01);
}

BOOST_AUTO_TEST_CASE(fit_recovers_rope_mu) {
  Dataset d;
  d.has_sliding = d.has_time = false;
  const double mu = 0.1, b0 = 300, b1 = -0.05;
  for (int k = 0; k < 5; ++k)
    for (bool rot : {true, false}) {
      Sample s;
      s.test_id = rot ? "r" : "f";
      s.pin_d_mm = 12.7;
      s.rotating = rot;
      s.speed_mm_s = 25.4;
      s.lubricant = "oil";
      s.back_tension_N = 1400 + 100 * k;
      const double F = s.back_tension_N;
      s.outlet_force_N = F + b0 + b1 * F + (rot ? 0.0 : F * (std::exp(mu * M_PI / 2) - 1));
      d.rows.push_back(s);
    }
  const MapLibrary maps = MapLibrary::stand_in({12.7});
  const Design des = make_design(d, maps);
  const Fit f = fit_model(des, ModelSpec{});
  BOOST_TEST(f.theta[0] == mu, tt::tolerance(1e-8));
  BOOST_TEST(f.b0[0] == b0, tt::tolerance(1e-9));
  BOOST_TEST(f.b1[0] == b1, tt::tolerance(1e-9));
  BOOST_TEST(f.rss < 1e-12);
}

static LoopResult loop_on(const std::string& effect, double noise, int seed, const std::string& rename = "") {
  static MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  SynthOptions o;
  o.effect = effect;
  o.noise_N = noise;
  o.seed = seed;
  SynthTruth t;
  static Dataset d;
  d = synthesize(o, maps, t);
  if (!rename.empty()) d.extra_columns[d.extra_index("test_order")] = rename;
  const Design des = make_design(d, maps);
  return run_loop(des, LoopOptions{});
}

BOOST_AUTO_TEST_CASE(null_data_gives_no_step) {
  const LoopResult r = loop_on("none", 5, 11);
  BOOST_TEST(r.steps.empty());
  BOOST_TEST(!r.stopped_because.empty());
  BOOST_TEST(summary_json(r).find("\"steps\": []") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(planted_drift_detected) {
  const LoopResult r = loop_on("drift", 5, 11);
  BOOST_TEST_REQUIRE(!r.steps.empty());
  BOOST_TEST(r.steps[0].variable == "test_order");
  BOOST_TEST(r.steps[0].effect == "drift");
  BOOST_TEST(r.steps[0].rms_after < r.steps[0].rms_before);
  BOOST_TEST(r.steps.back().rms_after < 1.3 * 5);
}

BOOST_AUTO_TEST_CASE(unknown_column_gets_generic_effect) {
  const LoopResult r = loop_on("drift", 5, 11, "lab_reading");
  BOOST_TEST_REQUIRE(!r.steps.empty());
  BOOST_TEST(r.steps[0].variable == "lab_reading");
  BOOST_TEST(r.steps[0].effect.rfind("generic_", 0) == 0);
  BOOST_TEST_REQUIRE(r.steps[0].params.size() == 1u);
  BOOST_TEST(r.steps[0].params[0].value > 0);
  BOOST_TEST(r.steps[0].params[0].se > 0);
  BOOST_TEST(r.steps[0].sign.find("increases") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(fast_mod_is_exact) {
  const std::size_t kmax = 1000;
  const FastMod mod(kmax);
  std::mt19937_64 rng(12345);
  std::size_t bad = 0;
  for (std::uint64_t k = 2; k <= kmax; ++k) {
    const std::uint64_t top = ~std::uint64_t{0};
    std::vector<std::uint64_t> xs = {0, 1, k - 1, k, top, std::uint64_t{1} << 63, top - top % k, top - top % k - 1};
    for (int j = 0; j < 200; ++j) xs.push_back(rng());
    for (std::uint64_t x : xs) bad += mod(x, k) != x % k;
  }
  BOOST_TEST(bad == 0u);
}

BOOST_AUTO_TEST_CASE(fast_mod32_is_exact) {
  const std::size_t kmax = 5000;
  const FastMod32 mod(kmax);
  std::mt19937 rng(12345);
  std::size_t bad = 0;
  for (std::uint32_t k = 2; k <= kmax; ++k) {
    const std::uint32_t top = ~std::uint32_t{0};
    std::vector<std::uint32_t> xs = {0, 1, k - 1, k, top, std::uint32_t{1} << 31, top - top % k, top - top % k - 1};
    for (int j = 0; j < 200; ++j) xs.push_back(static_cast<std::uint32_t>(rng()));
    for (std::uint32_t x : xs) bad += mod(x, k) != x % k;
  }
  BOOST_TEST(bad == 0u);
}

BOOST_AUTO_TEST_CASE(mt64_halves_are_mt19937_64_halves) {
  std::size_t bad = 0, taken = 0;
  for (std::uint64_t seed : {1ULL, 5489ULL, 52100000ULL + 7919ULL * 5}) {
    std::mt19937_64 ref(seed);
    std::vector<std::uint32_t> want;
    for (int j = 0; j < 100000; ++j) {
      const std::uint64_t v = ref();
      want.push_back(static_cast<std::uint32_t>(v)), want.push_back(static_cast<std::uint32_t>(v >> 32));
    }
    Mt64Halves calls(seed), blocks(seed);
    for (std::uint32_t w : want) bad += calls() != w;
    for (std::size_t at = 0, b = 0; at < want.size(); ++b) {
      const std::size_t n = std::min({blocks.available(), 1 + b * 37 % 97, want.size() - at});
      bad += n == 0;
      const std::uint32_t* y = blocks.take(n);
      for (std::size_t t = 0; t < n; ++t) bad += y[t] != want[at + t];
      at += n, taken += n;
    }
  }
  BOOST_TEST(bad == 0u);
  BOOST_TEST(taken == 600000u);
}

BOOST_AUTO_TEST_CASE(mt64_is_mt19937_64) {
  std::size_t bad = 0;
  for (std::uint64_t seed : {0ULL, 1ULL, 5489ULL, 52100000ULL + 7919ULL * 3, ~0ULL}) {
    std::mt19937_64 ref(seed);
    Mt64 mine(seed);
    for (int j = 0; j < 100000; ++j) bad += mine() != ref();
  }
  BOOST_TEST(bad == 0u);
}

// The shuffle's blocks (Mt64::available, take) are the same numbers as one
// call at a time: blocks of 1 to 97 numbers, calls between them, across refills.
BOOST_AUTO_TEST_CASE(mt64_blocks_are_its_calls) {
  std::size_t bad = 0, taken = 0;
  for (std::uint64_t seed : {1ULL, 5489ULL, 52100000ULL + 7919ULL * 5}) {
    std::mt19937_64 ref(seed);
    Mt64 mine(seed);
    for (int b = 0; b < 5000; ++b) {
      std::size_t want = 1 + static_cast<std::size_t>(b * 37 % 97);
      while (want > 0) {
        const std::size_t n = std::min(mine.available(), want);
        bad += n == 0;
        const std::uint64_t* y = mine.take(n);
        for (std::size_t t = 0; t < n; ++t) bad += y[t] != ref();
        want -= n, taken += n;
      }
      if (b % 3 == 0) bad += mine() != ref();
    }
  }
  BOOST_TEST(bad == 0u);
  BOOST_TEST(taken > 3u * 312u * 100u);  // hundreds of refills crossed
}
