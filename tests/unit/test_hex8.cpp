// The one-point hexahedron's geometry (Flanagan-Belytschko uniform gradient).
// Closed-form answers:
//  - dV/dx_a equals the finite-difference derivative of the exact (2x2x2 Gauss)
//    volume of a distorted hexahedron; V = (1/3) sum_a x_a . dV/dx_a equals it too.
//  - Consistency: sum_a B_a = 0 and sum_a x_a (x) B_a = I (linear fields are
//    differentiated exactly), for any shape.
//  - The Walsh transform of fe/hex8_geometry.hpp: W_k = sum_a h_k(a) u_a
//    for each Walsh function h_k, and walsh8_back_t(W) + W_0 = 8 u (the
//    Hadamard matrix squared is 8 I), exact on integers.
//  - A unit cube has B_a = (xi_a, eta_a, zeta_a)/4, half-lengths 0.5, and
//    stable length 2 min(h) = 1 (= V / A_max).
#define BOOST_TEST_MODULE hex8
#include <boost/test/unit_test.hpp>

#include "fe/hex8.hpp"
#include "fe/hex8_geometry.hpp"
#include "fe/mesh.hpp"

using namespace drawbend::fe;
namespace tt = boost::test_tools;

static void distorted(double x[8], double y[8], double z[8]) {
  const double base[8][3] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, 0.5}, {2, 0, 0.5}, {2, 1, 0.5}, {0, 1, 0.5}};
  const double pert[8][3] = {{0.1, -0.05, 0.02}, {-0.2, 0.1, 0.0}, {0.15, 0.2, -0.03}, {-0.1, 0.05, 0.04},
                             {0.05, 0.1, 0.1}, {0.1, -0.1, 0.07}, {-0.15, 0.05, 0.12}, {0.2, -0.2, -0.05}};
  for (int a = 0; a < 8; ++a) {
    x[a] = base[a][0] + pert[a][0];
    y[a] = base[a][1] + pert[a][1];
    z[a] = base[a][2] + pert[a][2];
  }
}

BOOST_AUTO_TEST_CASE(volume_derivative_matches_finite_difference) {
  double x[8], y[8], z[8], dx[8], dy[8], dz[8];
  distorted(x, y, z);
  volume_derivatives(x, y, z, dx, dy, dz);
  const double h = 1e-6;
  for (int a = 0; a < 8; ++a) {
    double* c[3] = {x, y, z};
    const double* d[3] = {dx, dy, dz};
    for (int k = 0; k < 3; ++k) {
      const double keep = c[k][a];
      c[k][a] = keep + h;
      const double vp = hex_volume(x, y, z);
      c[k][a] = keep - h;
      const double vm = hex_volume(x, y, z);
      c[k][a] = keep;
      BOOST_TEST(d[k][a] == (vp - vm) / (2 * h), tt::tolerance(1e-6));
    }
  }
  HexGeometry g;
  BOOST_TEST(hex_geometry(x, y, z, g));
  BOOST_TEST(g.volume == hex_volume(x, y, z), tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(walsh_transform_and_its_transpose) {
  const double u[8] = {3, -7, 11, 2, -5, 13, 1, -4};
  double W[8], back[8];
  baseline::walsh8_t(u, W);
  const double* n[3] = {kXiN, kEtaN, kZetaN};
  for (int k = 0; k < 8; ++k) {
    double want = 0;
    for (int a = 0; a < 8; ++a) {
      // h_k: 1, xi, eta, zeta, xi*eta, eta*zeta, zeta*xi, xi*eta*zeta
      const double h[8] = {1, n[0][a], n[1][a], n[2][a], n[0][a] * n[1][a], n[1][a] * n[2][a], n[2][a] * n[0][a],
                           n[0][a] * n[1][a] * n[2][a]};
      want += h[k] * u[a];
    }
    BOOST_TEST(W[k] == want);
  }
  for (int al = 0; al < 4; ++al) {  // kHg's modes are Walsh functions
    double want = 0;
    for (int a = 0; a < 8; ++a) want += kHg[al][a] * u[a];
    BOOST_TEST(W[baseline::kWalshOfMode[al]] == want);
  }
  baseline::walsh8_back_t(W, back);
  for (int a = 0; a < 8; ++a) BOOST_TEST(back[a] + W[0] == 8 * u[a]);
}

BOOST_AUTO_TEST_CASE(consistency) {
  double x[8], y[8], z[8];
  distorted(x, y, z);
  HexGeometry g;
  hex_geometry(x, y, z, g);
  const double* X[3] = {x, y, z};
  for (int i = 0; i < 3; ++i) {
    double s = 0;
    for (int a = 0; a < 8; ++a) s += g.B[i][a];
    BOOST_TEST(std::abs(s) < 1e-12);
    for (int j = 0; j < 3; ++j) {
      double m = 0;
      for (int a = 0; a < 8; ++a) m += X[i][a] * g.B[j][a];
      BOOST_TEST(m == (i == j ? 1.0 : 0.0), tt::tolerance(1e-12));
    }
  }
}

BOOST_AUTO_TEST_CASE(unit_cube) {
  const double x[8] = {0, 1, 1, 0, 0, 1, 1, 0}, y[8] = {0, 0, 1, 1, 0, 0, 1, 1}, z[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  HexGeometry g;
  BOOST_TEST(hex_geometry(x, y, z, g));
  BOOST_TEST(g.volume == 1.0, tt::tolerance(1e-14));
  for (int a = 0; a < 8; ++a) {
    BOOST_TEST(g.B[0][a] == kXiN[a] / 4, tt::tolerance(1e-14));
    BOOST_TEST(g.B[2][a] == kZetaN[a] / 4, tt::tolerance(1e-14));
  }
  BOOST_TEST(g.h[0] == 0.5, tt::tolerance(1e-14));
  BOOST_TEST(hex_stable_length(g) == 1.0, tt::tolerance(1e-14));
}
