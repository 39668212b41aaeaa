// The new method, thesis Eqs. (4.2)-(4.5), (5.3), on synthetic pressure maps.
// Closed-form answers:
//  - One node, P' = 10 MPa, A = 2 mm^2, c = 1.1, mu = 0.1: F_T = 0.1*11*2 = 2.2 N.
//  - Forces computed by Eq. (4.2) from a known mu(p) are inverted exactly:
//    linear mu from 2 pins (square, Eq. 5.3), quadratic from 3 pins (Eq. 4.5),
//    a cubic from 4 pins, and linear from 4 pins by least squares (zero residual
//    because the data are consistent).
//  - M_jk = c_j^(k+1) sum_i P'_ij^(k+1) A_ij.
//  - Fewer pins than coefficients is an error.
#define BOOST_TEST_MODULE new_method
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "analysis/new_method.hpp"

using namespace drawbend::analysis;
namespace tt = boost::test_tools;

// A synthetic "draw-bend-like" map: peaks at entry/exit, plateau between.
static PressureMap synthetic_map(double plateau, double peak, int n, const std::string& label) {
  PressureMap m;
  m.label = label;
  for (int i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) / (n - 1);  // 0..1 along the contact
    const double bump = std::exp(-std::pow((s - 0.1) / 0.05, 2)) + 1.3 * std::exp(-std::pow((s - 0.9) / 0.05, 2));
    m.p_MPa.push_back(plateau + (peak - plateau) * bump);
    m.area_mm2.push_back(0.25 + 0.01 * (i % 3));
  }
  return m;
}

static std::vector<PinTest> pins_for(const Polynomial& mu, int count) {
  std::vector<PinTest> pins;
  for (int j = 0; j < count; ++j) {
    PinTest t;
    t.map = synthetic_map(6.0 + 4.0 * j, 60.0 - 9.0 * j, 200, "pin" + std::to_string(j));
    t.c = 1.06 - 0.01 * j;
    t.friction_force_N = predicted_friction_force(t.map, t.c, mu);
    pins.push_back(t);
  }
  return pins;
}

BOOST_AUTO_TEST_CASE(single_node_force) {
  PressureMap m{"one", {10.0}, {2.0}};
  BOOST_TEST(predicted_friction_force(m, 1.1, Polynomial{{0.1}}) == 2.2, tt::tolerance(1e-14));
  // A half-model map mirrored to the full strip carries twice the force: 4.4 N.
  BOOST_TEST(predicted_friction_force(m.scaled_areas(2.0), 1.1, Polynomial{{0.1}}) == 4.4, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(matrix_entries) {
  // Two hand-made maps: pin 1 nodes (10 MPa, 1 mm^2), (20 MPa, 2 mm^2), c = 1.1;
  // pin 2 node (5 MPa, 4 mm^2), c = 1.2.  By hand:
  //   M = [1.1*(10+40)        1.21*(100+800) ]   = [55   1089]
  //       [1.2*(20)           1.44*(100)     ]     [24    144]
  std::vector<PinTest> pins(2);
  pins[0].map = {"a", {10, 20}, {1, 2}};
  pins[0].c = 1.1;
  pins[0].friction_force_N = 1;
  pins[1].map = {"b", {5}, {4}};
  pins[1].c = 1.2;
  pins[1].friction_force_N = 1;
  const auto r = solve_new_method(pins, 1);
  BOOST_TEST(r.M(0, 0) == 55.0, tt::tolerance(1e-12));
  BOOST_TEST(r.M(0, 1) == 1089.0, tt::tolerance(1e-12));
  BOOST_TEST(r.M(1, 0) == 24.0, tt::tolerance(1e-12));
  BOOST_TEST(r.M(1, 1) == 144.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(rank_deficient_least_squares_is_an_error) {
  // Three pins with the same map and c carry one equation's information: rank 1 < 2.
  const Polynomial mu{{0.025, 0.0009}};
  auto pins = pins_for(mu, 3);
  pins[1] = pins[0];
  pins[2] = pins[0];
  BOOST_CHECK_THROW(solve_new_method(pins, 1), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(exact_recovery_square) {
  for (int order = 0; order <= 3; ++order) {
    Polynomial mu{{0.03, 0.0012, -1.5e-5, 1e-7}};
    mu.a.resize(order + 1);
    const auto r = solve_new_method(pins_for(mu, order + 1), order);
    BOOST_TEST(!r.least_squares);
    for (int k = 0; k <= order; ++k) BOOST_TEST(r.mu.a[k] == mu.a[k], tt::tolerance(1e-7));
  }
}

BOOST_AUTO_TEST_CASE(least_squares_overdetermined) {
  const Polynomial mu{{0.025, 0.0009}};
  const auto r = solve_new_method(pins_for(mu, 4), 1);
  BOOST_TEST(r.least_squares);
  BOOST_TEST(r.mu.a[0] == mu.a[0], tt::tolerance(1e-9));
  BOOST_TEST(r.mu.a[1] == mu.a[1], tt::tolerance(1e-9));
  BOOST_TEST(r.residual_N < 1e-9);
}

BOOST_AUTO_TEST_CASE(underdetermined_is_an_error) {
  const Polynomial mu{{0.025, 0.0009}};
  BOOST_CHECK_THROW(solve_new_method(pins_for(mu, 1), 1), std::invalid_argument);
  auto bad = pins_for(mu, 2);
  bad[0].map.area_mm2.pop_back();
  BOOST_CHECK_THROW(solve_new_method(bad, 1), std::invalid_argument);
}
