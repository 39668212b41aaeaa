// What a loop figure of many rows draws (src/loop/figure_data.hpp), on cases
// with known answers.
//  - Bins by value: x = {1, 1, 2, 2, 2}, before = {1, 3, 2, 4, 6} -> two
//    bins, x = 1 with 2 rows, mean 2, sd sqrt(2); x = 2 with 3 rows, mean 4,
//    sd 2 (sample sd: sqrt(((2-4)^2 + 0 + (6-4)^2) / 2) = 2).  after = -before
//    gives the negated means and the same sd.
//  - Equal-count bins: x = 0..99 (100 distinct values > 40) in reverse row
//    order -> 40 bins; bin b holds x in [floor(100 b/40), floor(100 (b+1)/40)):
//    bin 0 {0, 1} (mean 0.5, 2 rows), bin 1 {2, 3, 4} (mean 3, 3 rows); the
//    rows add up to 100; a row with x = NaN is left out (101 rows given).
//  - Distinct points on a 250-cell grid over the box [0, 1] x [0, 1]: (0, 0)
//    and (0.001, 0) share cell (0, 0) (0.25 rounds to 0), (1, 1) and (0.999, 1)
//    share the last; (0.5, 0.5) is alone -> 3 points, at their first rows'
//    values, with counts 2, 2, 1 in first-seen order; a NaN pair is left out.
//  - A categorical column of 50 levels (x = level index 0..49, two rows each)
//    with max_values kFigureLevels: 50 bins, one per level (level 7's bin at
//    x = 7 with 2 rows); with the numeric default: 40 bins.
//  - One row: one bin with sd 0; an empty column: no bins, no points.
#define BOOST_TEST_MODULE figure_data
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "loop/figure_data.hpp"

using namespace drawbend::loop;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_CASE(bins_by_value_known_answer) {
  const std::vector<double> x = {2, 1, 2, 1, 2}, before = {2, 1, 4, 3, 6}, after = {-2, -1, -4, -3, -6};
  const auto b = residual_bins(x, before, after);
  BOOST_TEST_REQUIRE(b.size() == 2u);
  BOOST_TEST(b[0].x == 1.0);
  BOOST_TEST(b[0].rows == 2u);
  BOOST_TEST(b[0].before_mean == 2.0, tt::tolerance(1e-14));
  BOOST_TEST(b[0].before_sd == std::sqrt(2.0), tt::tolerance(1e-14));
  BOOST_TEST(b[1].x == 2.0);
  BOOST_TEST(b[1].rows == 3u);
  BOOST_TEST(b[1].before_mean == 4.0, tt::tolerance(1e-14));
  BOOST_TEST(b[1].before_sd == 2.0, tt::tolerance(1e-14));
  BOOST_TEST(b[1].after_mean == -4.0, tt::tolerance(1e-14));
  BOOST_TEST(b[1].after_sd == 2.0, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(equal_count_bins_known_answer) {
  std::vector<double> x, r;
  for (int i = 99; i >= 0; --i) x.push_back(i), r.push_back(0.5 * i);
  x.push_back(NAN), r.push_back(1.0);
  const auto b = residual_bins(x, r, r);
  BOOST_TEST_REQUIRE(b.size() == kFigureBins);
  BOOST_TEST(b[0].rows == 2u);
  BOOST_TEST(b[0].x == 0.5, tt::tolerance(1e-14));
  BOOST_TEST(b[1].rows == 3u);
  BOOST_TEST(b[1].x == 3.0, tt::tolerance(1e-14));
  BOOST_TEST(b[1].before_mean == 1.5, tt::tolerance(1e-14));
  std::size_t rows = 0;
  for (const auto& bin : b) rows += bin.rows;
  BOOST_TEST(rows == 100u);
}

BOOST_AUTO_TEST_CASE(distinct_points_known_answer) {
  const std::vector<double> u = {0, 0.5, 0.001, 1, NAN, 0.999}, v = {0, 0.5, 0, 1, 0.3, 1};
  const auto p = distinct_points(u, v, 250);
  BOOST_TEST_REQUIRE(p.size() == 3u);
  BOOST_TEST(p[0].u == 0.0);
  BOOST_TEST(p[0].rows == 2u);
  BOOST_TEST(p[1].u == 0.5);
  BOOST_TEST(p[1].rows == 1u);
  BOOST_TEST(p[2].u == 1.0);
  BOOST_TEST(p[2].rows == 2u);
}

BOOST_AUTO_TEST_CASE(one_row_and_none) {
  const auto b = residual_bins({3.0}, {1.0}, {2.0});
  BOOST_TEST_REQUIRE(b.size() == 1u);
  BOOST_TEST(b[0].before_sd == 0.0);
  BOOST_TEST(residual_bins({}, {}, {}).empty());
  BOOST_TEST(distinct_points({}, {}).empty());
}

BOOST_AUTO_TEST_CASE(levels_of_a_categorical_column) {
  std::vector<double> x, r;
  for (int i = 0; i < 100; ++i) x.push_back(i % 50), r.push_back(i);
  const auto b = residual_bins(x, r, r, kFigureLevels);
  BOOST_TEST_REQUIRE(b.size() == 50u);
  BOOST_TEST(b[7].x == 7.0);
  BOOST_TEST(b[7].rows == 2u);
  BOOST_TEST(residual_bins(x, r, r).size() == kFigureBins);
}
