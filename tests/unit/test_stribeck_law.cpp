// The Stribeck friction law of the solver (Sec. 3.3.2 interval averaging).
// Closed-form answers (Table 3.1 parameters):
//  - at constant p = 10 MPa and v = 8 mm/s the law returns mu(L) of Eq. (3.2)
//    with L = v eta/(p R_a) = 5.189e-4, on both texture axes;
//  - with an interval of 4 cycles and speeds 2, 14, 2, 14 mm/s, mu after the
//    fourth call is mu at the mean speed 8 mm/s, and it stays fixed during the
//    next three calls whatever the speed;
//  - interval 1 follows the instantaneous speed;
//  - no pressure gives mu_EHL; an interval < 1 is rejected.
#define BOOST_TEST_MODULE stribeck_law
#include <boost/test/unit_test.hpp>

#include "friction/stribeck_law.hpp"

using namespace drawbend;
namespace tt = boost::test_tools;

static analysis::StribeckParams t31() { return {0.1, 0.001, 4.5e-4, 5.4e-3, 1.85, 1.2}; }

BOOST_AUTO_TEST_CASE(constant_state) {
  friction::Stribeck law(t31(), 100);
  double st[3] = {0, 0, 0};
  friction::ContactState s;
  s.pressure = 10;
  s.slip_speed = 8;
  s.state = st;
  const auto lim = law.limit(s);
  const double expect = analysis::stribeck_mu(8, 10, t31());
  BOOST_TEST(lim.mu1 == expect, tt::tolerance(1e-14));
  BOOST_TEST(lim.mu2 == expect, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(interval_average) {
  friction::Stribeck law(t31(), 4);
  double st[3] = {0, 0, 0};
  friction::ContactState s;
  s.pressure = 10;
  s.state = st;
  const double speeds[4] = {2, 14, 2, 14};
  double mu = 0;
  for (double v : speeds) {
    s.slip_speed = v;
    mu = law.limit(s).mu1;
  }
  BOOST_TEST(mu == analysis::stribeck_mu(8, 10, t31()), tt::tolerance(1e-14));
  for (double v : {0.1, 50.0, 3.0}) {
    s.slip_speed = v;
    BOOST_TEST(law.limit(s).mu1 == mu);
  }
}

BOOST_AUTO_TEST_CASE(per_cycle_and_limits) {
  friction::Stribeck law(t31(), 1);
  double st[3] = {0, 0, 0};
  friction::ContactState s;
  s.pressure = 10;
  s.state = st;
  for (double v : {1.0, 30.0, 0.5}) {
    s.slip_speed = v;
    BOOST_TEST(law.limit(s).mu1 == analysis::stribeck_mu(v, 10, t31()), tt::tolerance(1e-14));
  }
  double st2[3] = {0, 0, 0};
  s.state = st2;
  s.pressure = 0;
  BOOST_TEST(law.limit(s).mu1 == t31().mu_EHL);
  BOOST_CHECK_THROW(friction::Stribeck(t31(), 0), std::invalid_argument);
}
