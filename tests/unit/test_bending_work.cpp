// Bending work of a bend-unbend cycle under tension (analysis/bending_work.hpp).
// Closed-form answers:
//  - rigid, perfectly plastic (E = 1e9 MPa, sigma_0 = 100 MPa), no tension,
//    plane strain c = 2/sqrt(3): F_B = 2 M_p kappa = c sigma_0 w t^2 / (2 rho),
//    rho = D/2 + t/2; D = 20 mm, t = 1 mm, w = 10 mm: 2/sqrt(3) * 100 * 10 / 21
//    = 54.986 N (the elastic core, sigma_0 c rho / E' ~ 3e-6 mm, is negligible);
//    plane stress (c = 1): 47.619 N.  Tolerance 0.2 %: the trapezoidal sum of
//    M dkappa loses 1.5 M_p dkappa at the two jumps of M (start and reversal),
//    0.075 % of the work with 1000 steps.
//  - elastic (flow stress 1e6 MPa): no dissipation, F_B = 0 (to round-off).
//  - Hosford plane-strain factor: a = 2 gives 2/sqrt(3); a = 1 gives 1;
//    a = 8 gives ((1 + 2^-7) / 2)^(-1/8) = 1.0894474.
//  - A back stress lowers the work of unbending: X_sat > 0 gives a smaller F_B
//    than isotropic hardening on the same monotonic curve (ordering, no value).
//  - Rigid, perfectly plastic under tension T (plane strain, n = T / (c s0 w t)):
//    the neutral axis lies n t / 2 from the mid-surface, so each of bending and
//    unbending stretches the mid-surface by d eps_m = T / (2 c s0 w) d kappa =
//    a d kappa whatever the thickness, and the moment is M = c s0 w t^2 (1 -
//    n^2) / 4 = c s0 w t^2 / 4 - T^2 / (4 c s0 w).  Thickness fixed: F_B =
//    2 M kappa0, eps_m = 2 a kappa0.  With thinning, t = t0 exp(-eps_m):
//    F_B = c s0 w t0^2 / 4 (1 - exp(-4 a kappa0)) / (2 a) - T^2 kappa0 /
//    (2 c s0 w), the same eps_m.  D = 20, t0 = 1, w = 10, s0 = 100, T = 500 N:
//    44.67 N fixed, 42.47 N thinning, eps_m = 4.124 %.  Tolerance 0.2 % as the
//    first case (the trapezoidal loss at the jumps of M; the thickness lags
//    one of 1000 steps).  2000 layers: in a rigid-plastic section the neutral
//    axis sits at a layer's centre, so eps_m is quantised by up to half a
//    layer against n t / 2 = 0.217 mm (0.12 % with 2000 layers; the first try,
//    100 layers, gave eps_m 0.7 % low with the thickness fixed: 0.215 mm).
#define BOOST_TEST_MODULE bending_work
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <stdexcept>

#include "analysis/bending_work.hpp"

using namespace drawbend::analysis;
namespace tt = boost::test_tools;

namespace {
BendMaterial perfectly_plastic(double sigma0, double E) {
  BendMaterial m;
  m.E_MPa = E;
  m.flow = [sigma0](double) { return sigma0; };
  m.dflow = [](double) { return 0.0; };
  return m;
}
BendMaterial swift() {  // a Swift curve: the RD table's until issue 51 (YS at eps_p = 0); orderings only
  BendMaterial m;
  m.flow = [](double p) { return 447.9752871 * std::pow(0.009138808179 + p, 0.32); };
  m.dflow = [](double p) { return 0.32 * 447.9752871 * std::pow(0.009138808179 + p, 0.32 - 1); };
  return m;
}
}  // namespace

BOOST_AUTO_TEST_CASE(rigid_perfectly_plastic_closed_form) {
  BendCase bc{20, 1, 10, 0, 100, 1000};
  BendMaterial m = perfectly_plastic(100, 1e9);
  BOOST_TEST(bend_unbend(bc, m).bending_force_N == 2 / std::sqrt(3.0) * 100 * 10 / 21.0, tt::tolerance(2e-3));
  m.constraint = 1;
  BOOST_TEST(bend_unbend(bc, m).bending_force_N == 100 * 10 / 21.0, tt::tolerance(2e-3));
}

BOOST_AUTO_TEST_CASE(elastic_dissipates_nothing) {
  BendCase bc{20, 1, 10, 500, 100, 50};
  const BendResult r = bend_unbend(bc, perfectly_plastic(1e6, 70000));
  BOOST_TEST(std::abs(r.bending_force_N) < 1e-9);
  BOOST_TEST(r.max_plastic_strain == 0.0);
}

BOOST_AUTO_TEST_CASE(hosford_factor_closed_form) {
  BOOST_TEST(hosford_plane_strain_factor(2) == 2 / std::sqrt(3.0), tt::tolerance(1e-12));
  BOOST_TEST(hosford_plane_strain_factor(1) == 1.0, tt::tolerance(1e-12));
  BOOST_TEST(hosford_plane_strain_factor(8) == std::pow((1 + std::pow(2.0, -7)) / 2, -1.0 / 8), tt::tolerance(1e-12));
  BOOST_TEST(hosford_plane_strain_factor(8) == 1.0894474, tt::tolerance(1e-7));
  BOOST_CHECK_THROW(hosford_plane_strain_factor(0.5), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(back_stress_lowers_unbending_work) {
  BendCase bc{25.4, 1.05, 25.4, 1800, 100, 80};
  BendMaterial iso = swift(), af = swift();
  af.x_sat_MPa = 50;
  af.gamma = 60;
  const double f_iso = bend_unbend(bc, iso).bending_force_N, f_af = bend_unbend(bc, af).bending_force_N;
  BOOST_TEST(f_iso > 0);
  BOOST_TEST(f_af < f_iso);
}

BOOST_AUTO_TEST_CASE(bad_inputs_throw) {
  BendCase bc{20, 1, 10, 0, 50, 20};
  BOOST_CHECK_THROW(bend_unbend(BendCase{0, 1, 10, 0, 50, 20}, swift()), std::invalid_argument);
  BOOST_CHECK_THROW(bend_unbend(bc, BendMaterial{}), std::invalid_argument);  // no flow curve
  BOOST_CHECK_THROW(bend_unbend(BendCase{20, 1, 10, 1e6, 50, 20}, perfectly_plastic(100, 70000)),
                    std::invalid_argument);  // more tension than the section carries
}

BOOST_AUTO_TEST_CASE(thinning_rigid_plastic_under_tension_closed_form) {
  const double D = 20, t0 = 1, w = 10, s0 = 100, T = 500, c = 2 / std::sqrt(3.0);
  const double k0 = 1 / (D / 2 + t0 / 2), a = T / (2 * c * s0 * w), n = T / (c * s0 * w * t0);
  const double fixed = 2 * c * s0 * w * t0 * t0 / 4 * (1 - n * n) * k0;
  const double thin = c * s0 * w * t0 * t0 / 4 * (1 - std::exp(-4 * a * k0)) / (2 * a) - T * T * k0 / (2 * c * s0 * w);
  BendCase bc{D, t0, w, T, 2000, 1000};
  const BendMaterial m = perfectly_plastic(s0, 1e9);
  const BendResult r0 = bend_unbend(bc, m);
  bc.thinning = true;
  const BendResult r1 = bend_unbend(bc, m);
  BOOST_TEST_MESSAGE("fixed thickness " << r0.bending_force_N << " N (closed form " << fixed << "), thinning "
                                        << r1.bending_force_N << " N (" << thin << "), eps_m " << r0.membrane_strain
                                        << " / " << r1.membrane_strain << " (" << 2 * a * k0 << ")");
  BOOST_TEST(r0.bending_force_N == fixed, tt::tolerance(2e-3));
  BOOST_TEST(r1.bending_force_N == thin, tt::tolerance(2e-3));
  BOOST_TEST(r0.membrane_strain == 2 * a * k0, tt::tolerance(2e-3));
  BOOST_TEST(r1.membrane_strain == 2 * a * k0, tt::tolerance(2e-3));
}
