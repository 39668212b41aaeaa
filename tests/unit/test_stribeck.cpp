// Stribeck curve, thesis Eqs. (3.1), (3.2), parameters of Table 3.1.
// Closed-form answers:
//  - L = v eta/(p R_a): v = 8 mm/s, eta = 1.2 Pa s, p = 10 MPa, R_a = 1.85 um:
//    L = 0.008*1.2/(1e7*1.85e-6) = 5.189189e-4 (dimensionless).
//  - At L = sqrt(L_BL L_EHL) the tanh argument is 0: mu = (mu_BL + mu_EHL)/2.
//  - At L = L_BL the argument is 1: mu = 0.5[(mu_BL+mu_EHL) + tanh(1)(mu_BL-mu_EHL)];
//    at L = L_EHL it is -1 (mirror value).  Both hold in any log base.
//  - Limits: mu -> mu_BL as L -> 0 (and mu(0) = mu_BL), mu -> mu_EHL as L -> inf.
//  - mu decreases monotonically in L.
#define BOOST_TEST_MODULE stribeck
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "analysis/stribeck.hpp"

using namespace drawbend::analysis;
namespace tt = boost::test_tools;

static StribeckParams table_3_1() { return {0.1, 0.001, 4.5e-4, 5.4e-3, 1.85, 1.2}; }

BOOST_AUTO_TEST_CASE(lubricant_number_si) {
  BOOST_TEST(lubricant_number(8, 10, table_3_1()) == 0.008 * 1.2 / (1e7 * 1.85e-6), tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(characteristic_points) {
  const auto s = table_3_1();
  const double mid = std::sqrt(s.L_BL * s.L_EHL);
  BOOST_TEST(stribeck_mu(mid, s) == 0.5 * (s.mu_BL + s.mu_EHL), tt::tolerance(1e-12));
  const double at_bl = 0.5 * ((s.mu_BL + s.mu_EHL) + std::tanh(1.0) * (s.mu_BL - s.mu_EHL));
  const double at_ehl = 0.5 * ((s.mu_BL + s.mu_EHL) - std::tanh(1.0) * (s.mu_BL - s.mu_EHL));
  BOOST_TEST(stribeck_mu(s.L_BL, s) == at_bl, tt::tolerance(1e-12));
  BOOST_TEST(stribeck_mu(s.L_EHL, s) == at_ehl, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(limits_and_monotonic) {
  const auto s = table_3_1();
  BOOST_TEST(stribeck_mu(0.0, s) == s.mu_BL);
  BOOST_TEST(std::abs(stribeck_mu(1e-12, s) - s.mu_BL) < 1e-6);
  BOOST_TEST(std::abs(stribeck_mu(1e6, s) - s.mu_EHL) < 1e-6);
  double prev = stribeck_mu(1e-7, s);
  for (double L = 2e-7; L < 1; L *= 1.5) {
    const double m = stribeck_mu(L, s);
    BOOST_TEST(m <= prev);
    prev = m;
  }
}

BOOST_AUTO_TEST_CASE(validation) {
  auto s = table_3_1();
  s.L_BL = s.L_EHL;
  BOOST_CHECK_THROW(s.validate(), std::invalid_argument);
  s = table_3_1();
  s.mu_BL = -0.1;
  BOOST_CHECK_THROW(s.validate(), std::invalid_argument);
  BOOST_CHECK_THROW(lubricant_number(8, 0, table_3_1()), std::domain_error);
}
