// Rope-formula analysis, thesis Eqs. (2.1), (2.2), (2.3), (5.1).
// Closed-form answers:
//  - Swift: sigma_y = 100 MPa, t = 1 mm, w = 20 mm, r = 10 mm, Theta = 90 deg:
//    F_B = 100*1*20/(2*10)*tan(45 deg) = 100 N (full strip); 50 N on the half model.
//  - Eq. (2.2): F_x = 1000 N, F_y = 1200 N, r = 10 mm, w = 20 mm: P = 2200/400 = 5.5 MPa;
//    the half model (500 N, 600 N on w/2 = 10 mm) gives the same 5.5 MPa.
//  - Eq. (2.3): F_y = F_x exp(mu Theta) + F_B recovers mu exactly (mu = 0.1, Theta = pi/2).
//  - Eq. (5.1): F_fric = F_back (exp(mu pi/2) - 1) recovers mu.
//  - friction_from_mu (Eq. 5.1 solved for F_fric): mu = ln 2 / (pi/2) doubles the
//    tension, so F_back = 300 N gives F_fric = 300 N; mu = 0 gives exactly 0 N;
//    mu_from_friction(friction_from_mu(0.12, 800, pi/2), 800, pi/2) = 0.12.
#define BOOST_TEST_MODULE rope
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "analysis/rope.hpp"

using namespace drawbend::analysis;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_CASE(swift_bending_force_closed_form) {
  BOOST_TEST(swift_bending_force(100, 1, 20, 10, M_PI / 2, ForceBasis::full_strip) == 100.0, tt::tolerance(1e-12));
  BOOST_TEST(swift_bending_force(100, 1, 20, 10, M_PI / 2, ForceBasis::half_model) == 50.0, tt::tolerance(1e-12));
  BOOST_CHECK_THROW(swift_bending_force(100, 1, 20, 10, M_PI, ForceBasis::full_strip), std::domain_error);
  BOOST_CHECK_THROW(swift_bending_force(100, -1, 20, 10, 1.0, ForceBasis::full_strip), std::domain_error);
}

BOOST_AUTO_TEST_CASE(average_pressure_basis) {
  BOOST_TEST(average_pressure(1000, 1200, 10, 20, ForceBasis::full_strip) == 5.5, tt::tolerance(1e-12));
  BOOST_TEST(average_pressure(500, 600, 10, 20, ForceBasis::half_model) == 5.5, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(mu_roundtrip) {
  const double mu = 0.1, th = M_PI / 2, Fx = 1000, FB = 80;
  const double Fy = Fx * std::exp(mu * th) + FB;
  BOOST_TEST(mu_rope(Fx, Fy, FB, th) == mu, tt::tolerance(1e-12));
  const double Ffric = Fx * (std::exp(mu * th) - 1.0);
  BOOST_TEST(mu_from_friction(Ffric, Fx, th) == mu, tt::tolerance(1e-12));
  BOOST_CHECK_THROW(mu_rope(1000, 50, 80, th), std::domain_error);
  BOOST_CHECK_THROW(mu_from_friction(10, 0, th), std::domain_error);
}

BOOST_AUTO_TEST_CASE(friction_from_mu_inverts_eq_5_1) {
  // Tolerances: a few ulps of exp and log (relative 1e-12).
  BOOST_TEST(friction_from_mu(std::log(2.0) / (M_PI / 2), 300, M_PI / 2) == 300.0, tt::tolerance(1e-12));
  BOOST_TEST(friction_from_mu(0.0, 300, M_PI / 2) == 0.0);
  BOOST_TEST(mu_from_friction(friction_from_mu(0.12, 800, M_PI / 2), 800, M_PI / 2) == 0.12, tt::tolerance(1e-12));
}
