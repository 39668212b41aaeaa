// Nine-node friction surface, thesis Eqs. (6.1)-(6.3).
// Closed-form answers:
//  - The shape functions sum to one everywhere and N_k(node_l) = delta_kl.
//  - The printed Eq. (6.1) (N5 = N4) sums to 0 at the centre (xi = eta = 0),
//    so it is not a partition of unity.
//  - A biquadratic mu(p,v) is reproduced exactly by its nodal values.
//  - surface_from_lines with lines linear in p reproduces each line exactly at
//    its own speed, for every p (the nodal values stay linear in p).
//  - Corrected Eq. (6.3): v_min -> eta = -1, v_max -> +1; the printed map gives
//    eta(v_min) = 2*6.35/95.25 - 1 = -0.8667 (13/15 below zero: 12.7/95.25 = 2/15).
//  - Built with the printed map, the surface evaluated through the printed map
//    again reproduces all three lines (the 3 x 3 Lagrange solve is exact), and
//    node 1 is no longer the slow line's p = 0 value.
//  - validate(): a surface whose speed nodes are out of order (v_min > v_max),
//    whose pressure nodes coincide, or with a NaN nodal value is refused; the
//    default domain (p 0-80 MPa, v 6.35-101.6 mm/s) is accepted.
//  - ellipse_mu (Sec. 6.4, Fig. 6.5) with mu_RD = 0.1, mu_TD = 0.2: RD (c = 1,
//    s = 0) gives 0.1 and TD (c = 0, s = 1) gives 0.2 (a b / sqrt(b^2) rounds the
//    products: relative 1e-14, a few ulps); at 45 deg
//    0.02 / sqrt((0.01 + 0.04)/2) = 0.02/sqrt(0.025) = 0.126491106...; both
//    coefficients zero give 0 (not 0/0).
#define BOOST_TEST_MODULE friction_surface
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "analysis/friction_surface.hpp"

using namespace drawbend::analysis;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_CASE(partition_of_unity_and_kronecker) {
  for (double xi = -1.5; xi <= 1.5; xi += 0.25)
    for (double eta = -1.5; eta <= 1.5; eta += 0.25) {
      double s = 0;
      for (double n : nine_node_shape(xi, eta)) s += n;
      BOOST_TEST(s == 1.0, tt::tolerance(1e-13));
    }
  const double c[3] = {-1, 0, 1};
  for (int k = 0; k < 9; ++k) {
    const auto N = nine_node_shape(c[k / 3], c[k % 3]);
    for (int l = 0; l < 9; ++l) BOOST_TEST(N[l] == (k == l ? 1.0 : 0.0), tt::tolerance(1e-15));
  }
}

BOOST_AUTO_TEST_CASE(printed_shape_functions_are_not_a_partition) {
  double s = 0;
  for (double n : nine_node_shape_as_printed(0, 0)) s += n;
  BOOST_TEST(s == 0.0, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(biquadratic_exact) {
  FrictionSurface S;
  auto f = [](double p, double v) { return 0.02 + 0.001 * p - 2e-6 * p * p + 3e-4 * v - 1e-6 * v * v + 1e-6 * p * v; };
  const double P[3] = {S.p_min, 0.5 * (S.p_min + S.p_max), S.p_max};
  const double V[3] = {S.v_min, 0.5 * (S.v_min + S.v_max), S.v_max};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) S.mu[3 * i + j] = f(P[i], V[j]);
  for (double p : {0.0, 13.0, 55.5, 80.0})
    for (double v : {6.35, 25.4, 70.0, 101.6}) BOOST_TEST(S(p, v) == f(p, v), tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(surface_from_lines_reproduces_lines) {
  const std::vector<SpeedLine> lines = {{6.35, {{0.0142, 0.0025}}}, {25.4, {{0.0279, 0.0015}}}, {101.6, {{0.0234, 0.0003}}}};
  const auto S = surface_from_lines(lines, 0, 80);
  for (const auto& l : lines)
    for (double p : {0.0, 10.0, 40.0, 77.0}) BOOST_TEST(S(p, l.v_mm_s) == l.mu(p), tt::tolerance(1e-12));
  BOOST_TEST(S.eta(6.35) == -1.0, tt::tolerance(1e-14));
  BOOST_TEST(S.eta(101.6) == 1.0, tt::tolerance(1e-14));
  BOOST_TEST(S.eta_as_printed(6.35) == -13.0 / 15.0, tt::tolerance(1e-14));
  BOOST_CHECK_THROW(surface_from_lines({lines[0], lines[1]}, 0, 80), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(printed_map_surface_is_consistent) {
  const std::vector<SpeedLine> lines = {{6.35, {{0.0142, 0.0025}}}, {25.4, {{0.0279, 0.0015}}}, {101.6, {{0.0234, 0.0003}}}};
  const auto P = surface_from_lines(lines, 0, 80, /*use_printed_eta=*/true);
  for (const auto& l : lines)
    for (double p : {0.0, 40.0, 80.0}) {
      const auto N = nine_node_shape(P.xi(p), P.eta_as_printed(l.v_mm_s));
      double m = 0;
      for (int k = 0; k < 9; ++k) m += N[k] * P.mu[k];
      BOOST_TEST(m == l.mu(p), tt::tolerance(1e-10));
    }
  BOOST_TEST(std::abs(P.mu[0] - 0.0142) > 1e-3);
}

BOOST_AUTO_TEST_CASE(node_ordering_is_validated) {
  FrictionSurface ok;
  BOOST_CHECK_NO_THROW(ok.validate());
  FrictionSurface swapped;
  swapped.v_min = 101.6;
  swapped.v_max = 6.35;
  BOOST_CHECK_THROW(swapped.validate(), std::invalid_argument);
  FrictionSurface flat;
  flat.p_max = flat.p_min;
  BOOST_CHECK_THROW(flat.validate(), std::invalid_argument);
  FrictionSurface nan_node;
  nan_node.mu[4] = NAN;
  BOOST_CHECK_THROW(nan_node.validate(), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(anisotropic_ellipse) {
  // Tolerance 1e-14: a few ulps of the products and the sqrt (the formula is not exact in binary).
  BOOST_TEST(ellipse_mu(0.1, 0.2, 1.0, 0.0) == 0.1, tt::tolerance(1e-14));
  BOOST_TEST(ellipse_mu(0.1, 0.2, 0.0, 1.0) == 0.2, tt::tolerance(1e-14));
  BOOST_TEST(ellipse_mu(0.1, 0.2, 1.0, 0.0) != 0.2, tt::tolerance(1e-14));  // RD is not TD
  const double h = std::sqrt(0.5);
  BOOST_TEST(ellipse_mu(0.1, 0.2, h, h) == 0.02 / std::sqrt(0.025), tt::tolerance(1e-14));
  BOOST_TEST(ellipse_mu(0.0, 0.0, h, h) == 0.0);
}
