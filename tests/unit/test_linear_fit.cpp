// Linear force fits and their arithmetic.
// Closed-form answers:
//  - (0.0285 x + 503.6) - (-0.0625 x + 396.84) = 0.091 x + 106.76, valid on the
//    intersection [1450, 1700] N of [1400, 1700] and [1450, 1800].
//  - evaluation at 1500 N is inside (no flag); at 1800 N it extrapolates.
//  - least squares through y = 2x + 1 sampled exactly gives slope 2, intercept 1.
//  - ranges [0, 1] and [2, 3] intersect to an empty range: every use extrapolates.
#define BOOST_TEST_MODULE linear_fit
#include <boost/test/unit_test.hpp>

#include "analysis/linear_fit.hpp"

using namespace drawbend::analysis;

BOOST_AUTO_TEST_CASE(subtraction_and_range) {
  const LinearFit fb{0.0285, 503.6, Range{1400, 1700}, "fric+bend"};
  const LinearFit b{-0.0625, 396.84, Range{1450, 1800}, "bend"};
  const LinearFit f = subtract(fb, b);
  BOOST_TEST(f.slope == 0.091, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(f.intercept == 106.76, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(f.range->lo == 1450.0);
  BOOST_TEST(f.range->hi == 1700.0);
  const auto in = evaluate(f, 1500.0);
  BOOST_TEST(!in.extrapolated);
  BOOST_TEST(in.value == 0.091 * 1500 + 106.76, boost::test_tools::tolerance(1e-12));
  const auto out = evaluate(f, 1800.0);
  BOOST_TEST(out.extrapolated);
  BOOST_TEST(out.note.find("outside the fit range") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(empty_intersection_always_extrapolates) {
  const LinearFit a{1, 0, Range{0, 1}, "a"}, b{0, 0, Range{2, 3}, "b"};
  const LinearFit d = subtract(a, b);
  BOOST_TEST(d.range->empty());
  BOOST_TEST(evaluate(d, 0.5).extrapolated);
  BOOST_TEST(evaluate(d, 2.5).extrapolated);
}

BOOST_AUTO_TEST_CASE(no_range_is_not_flagged_but_known_unknown) {
  const LinearFit a{1, 0, std::nullopt, "a"};
  const auto e = evaluate(a, 1e6);
  BOOST_TEST(!e.extrapolated);
  BOOST_TEST(!e.range_known);
}

BOOST_AUTO_TEST_CASE(least_squares_line) {
  const LinearFit f = fit_line({0, 1, 2, 3}, {1, 3, 5, 7});
  BOOST_TEST(f.slope == 2.0, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(f.intercept == 1.0, boost::test_tools::tolerance(1e-14));
  BOOST_CHECK_THROW(fit_line({1, 1}, {0, 1}), std::invalid_argument);
  BOOST_CHECK_THROW(fit_line({1}, {0}), std::invalid_argument);
}
