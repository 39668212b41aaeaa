#pragma once
// The hexahedron's geometry as templates over the lane type (core/lanes.hpp):
// one source for the scalar functions of hex8.cpp and for the element loop's
// vector kernels (fe/element_kernel.hpp).
//
// Each instruction set compiles these templates in its own namespace
// (DRAWBEND_ISA, set per source file), so that a vector-ISA instantiation can
// never stand in for the baseline one at link time.
#include <cmath>

#include "core/lanes.hpp"
#include "fe/hex8.hpp"

#ifndef DRAWBEND_ISA
#define DRAWBEND_ISA baseline
#endif

// DRAWBEND_OUTLINE marks the element kernel's three large pieces (hex_walsh_t,
// velocity_gradient, scatter_forces): out of line where a vector has 16
// registers (AVX2, and the scalar build), inlined into the block where it has
// 32 (AVX-512).  With 16, GCC spills less of the block when they are calls
// (AVX2 kernel on Zen 1, bar 1,600, one thread: 265 ns with the three out of
// line, 291 with all inline; fe/element_kernel.hpp).  With 32 the calls' cost
// is the larger one: AVX-512 kernel on Zen 4 (AMD EPYC family 25 model 17,
// KVM), 1 thread, bar 1,600 with J2, 8 alternations of both builds: 86.1 ns
// shortest and 87.6 median inlined against 88.0 and 91.0; the strip, 5
// alternations: 90.7 shortest against 98.6 (2026-11-29).  Inlining changes
// no bits (no contraction, no reassociation: the same operations in the same order).
#if defined(__AVX512F__)
#define DRAWBEND_OUTLINE __attribute__((always_inline)) inline
#else
#define DRAWBEND_OUTLINE __attribute__((noinline)) inline
#endif

namespace drawbend::fe::DRAWBEND_ISA {

// Walsh form.  The trilinear map is x(xi, eta, zeta) = (1/8) sum_k X_k h_k
// with the Walsh functions h_k = 1, xi, eta, zeta, xi*eta, eta*zeta,
// zeta*xi, xi*eta*zeta (k = 0 .. 7) and the Walsh sums X_k = sum_a h_k(a) x_a
// of the corner coordinates (signs kXiN, kEtaN, kZetaN of hex8.hpp).  Its
// exact volume, integrating det(dx/dxi) over the cube (odd powers vanish,
// the mean of xi^2 is 1/3), is a sum of four triple products:
//   192 V = 3 X1.(X2 x X3) + X1.(X4 x X6) + X4.(X2 x X5) + X6.(X5 x X3),
// so dV/dX_k = G_k / 192 with
//   G1 = 3 X2 x X3 + X4 x X6,   G4 = X6 x X1 + X2 x X5,
//   G2 = 3 X3 x X1 + X5 x X4,   G5 = X4 x X2 + X3 x X6,
//   G3 = 3 X1 x X2 + X6 x X5,   G6 = X1 x X4 + X5 x X3,   G0 = G7 = 0,
// 192 V = X1.G1 + X5.G5, and dV/dx_a = (1/192) sum_k h_k(a) G_k: the same
// polynomial as Flanagan & Belytschko's (1981) corner formula (LULESH's),
// in fewer operations.  The element kernel works on the Walsh sums
// throughout (velocities in, forces out), so B_a is never formed there: its
// volume and gradient take about 220 operations per element against the
// corner formula's 620 (with V and B_a).

/// The Walsh functions of kHg's modes (eta*zeta, zeta*xi, xi*eta, xi*eta*zeta).
inline constexpr int kWalshOfMode[4] = {5, 6, 4, 7};

/// W_k = sum_a h_k(a) u_a, k = 0 .. 7: three butterfly stages (24 additions).
template <class T>
inline void walsh8_t(const T u[8], T W[8]) {
  // xi: the node pairs (0, 1), (3, 2), (4, 5), (7, 6) differ in xi alone.
  const T p0 = u[0] + u[1], m0 = u[1] - u[0];  // eta -, zeta -
  const T p1 = u[3] + u[2], m1 = u[2] - u[3];  // eta +, zeta -
  const T p2 = u[4] + u[5], m2 = u[5] - u[4];  // eta -, zeta +
  const T p3 = u[7] + u[6], m3 = u[6] - u[7];  // eta +, zeta +
  // eta
  const T pp0 = p0 + p1, pe0 = p1 - p0, mp0 = m0 + m1, me0 = m1 - m0;  // zeta -
  const T pp1 = p2 + p3, pe1 = p3 - p2, mp1 = m2 + m3, me1 = m3 - m2;  // zeta +
  // zeta
  W[0] = pp0 + pp1, W[3] = pp1 - pp0;
  W[1] = mp0 + mp1, W[6] = mp1 - mp0;
  W[2] = pe0 + pe1, W[5] = pe1 - pe0;
  W[4] = me0 + me1, W[7] = me1 - me0;
}

/// f_a = sum_{k=1..7} h_k(a) F_k (F_0 is not read): walsh8_t transposed, 23 additions.
template <class T>
inline void walsh8_back_t(const T F[8], T f[8]) {
  // zeta: each group's value at zeta -, +
  const T e0 = F[2] - F[5], e1 = F[2] + F[5];  // eta group
  const T x0 = F[1] - F[6], x1 = F[1] + F[6];  // xi group
  const T y0 = F[4] - F[7], y1 = F[4] + F[7];  // xi*eta group
  // eta: A without xi, B its xi part, at (eta, zeta)
  const T Amm = -F[3] - e0, Apm = e0 - F[3], Amp = F[3] - e1, App = F[3] + e1;
  const T Bmm = x0 - y0, Bpm = x0 + y0, Bmp = x1 - y1, Bpp = x1 + y1;
  // xi
  f[0] = Amm - Bmm, f[1] = Amm + Bmm, f[2] = Apm + Bpm, f[3] = Apm - Bpm;
  f[4] = Amp - Bmp, f[5] = Amp + Bmp, f[6] = App + Bpp, f[7] = App - Bpp;
}

/// The Walsh sums of the coordinates, X[i][k], and G[i][k] = 192 dV/dX_k (i: x, y, z).
template <class T>
inline void walsh_volume_gradient_t(const T x[8], const T y[8], const T z[8], T X[3][8], T G[3][8]) {
  walsh8_t(x, X[0]);
  walsh8_t(y, X[1]);
  walsh8_t(z, X[2]);
  // c = a x b of Walsh sums a and b
  auto cross = [&](int a, int b, T c[3]) {
    c[0] = X[1][a] * X[2][b] - X[2][a] * X[1][b];
    c[1] = X[2][a] * X[0][b] - X[0][a] * X[2][b];
    c[2] = X[0][a] * X[1][b] - X[1][a] * X[0][b];
  };
  constexpr int kPairs[6][4] = {{2, 3, 4, 6}, {3, 1, 5, 4}, {1, 2, 6, 5}, {6, 1, 2, 5}, {4, 2, 3, 6}, {1, 4, 5, 3}};
  for (int k = 1; k <= 6; ++k) {
    const int* q = kPairs[k - 1];
    T c1[3], c2[3];
    cross(q[0], q[1], c1);
    cross(q[2], q[3], c2);
    for (int i = 0; i < 3; ++i) G[i][k] = k <= 3 ? 3.0 * c1[i] + c2[i] : c1[i] + c2[i];
  }
  for (int i = 0; i < 3; ++i) G[i][0] = G[i][7] = T{};
}

/// dV/dx_a of the trilinear hexahedron (exact).
template <class T>
inline void volume_derivatives_t(const T x[8], const T y[8], const T z[8], T dvdx[8], T dvdy[8], T dvdz[8]) {
  T X[3][8], G[3][8];
  walsh_volume_gradient_t(x, y, z, X, G);
  T* d[3] = {dvdx, dvdy, dvdz};
  for (int i = 0; i < 3; ++i) {
    walsh8_back_t(G[i], d[i]);
    for (int a = 0; a < 8; ++a) d[i][a] *= 1.0 / 192.0;
  }
}

/// The element's geometry in Walsh form, for the element kernel.
template <class T>
struct HexWalshT {
  T X[3][8];  ///< Walsh sums of the corner coordinates, X[i][k] = sum_a h_k(a) x_i,a [mm]
  T G[3][8];  ///< 192 dV/dX_k, zero for k = 0 and 7 [mm^2]
  T volume;   ///< exact volume [mm^3]
  T inv;      ///< 1 / (192 V): B_a = inv sum_k h_k(a) G_k [1/mm^3]
  T R[3][3];  ///< corotational frame: columns are the local axes e_xi, e_eta, e_zeta
  T h[3];     ///< half-lengths along the local axes [mm]
};

/// Walsh sums, volume gradient, V, the corotational frame and half-lengths.
/// Returns false, with only the volume set, when the volume of any lane is
/// not positive.  Out of line on purpose where vectors have 16 registers:
/// inlined into the element kernel's block, GCC spills more there
/// (DRAWBEND_OUTLINE, above).
template <class T>
DRAWBEND_OUTLINE bool hex_walsh_t(const T x[8], const T y[8], const T z[8], HexWalshT<T>& g) {
  walsh_volume_gradient_t(x, y, z, g.X, g.G);
  T v192 = {};
  for (int i = 0; i < 3; ++i) v192 += g.X[i][1] * g.G[i][1] + g.X[i][5] * g.G[i][5];
  g.volume = v192 * (1.0 / 192.0);
  if (!all_positive(g.volume)) return false;
  g.inv = 1.0 / v192;
  // Jacobian columns at the centre: dx/dxi = X_xi / 8 (a power of two: exact).
  T J[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) J[i][k] = g.X[i][1 + k] * 0.125;
  // Corotational frame by Gram-Schmidt on (xi, eta) and their cross product.
  T e1[3] = {J[0][0], J[1][0], J[2][0]}, e2[3] = {J[0][1], J[1][1], J[2][1]};
  T n1, n2;
  lane_sqrt(T(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]), n1);
  const T in1 = 1.0 / n1;
  for (T& c : e1) c *= in1;
  const T d = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
  for (int k = 0; k < 3; ++k) e2[k] -= d * e1[k];
  lane_sqrt(T(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]), n2);
  const T in2 = 1.0 / n2;
  for (T& c : e2) c *= in2;
  const T e3[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  for (int k = 0; k < 3; ++k) {
    g.R[k][0] = e1[k];
    g.R[k][1] = e2[k];
    g.R[k][2] = e3[k];
  }
  for (int c = 0; c < 3; ++c) lane_sqrt(T(J[0][c] * J[0][c] + J[1][c] * J[1][c] + J[2][c] * J[2][c]), g.h[c]);
  return true;
}

/// B, V, the corotational frame and half-lengths (hex_walsh_t, with B_a
/// formed).  Returns false, with only the volume set, when the volume of any
/// lane is not positive.
template <class T>
inline bool hex_geometry_t(const T x[8], const T y[8], const T z[8], HexGeometryT<T>& g) {
  HexWalshT<T> w;
  const bool ok = hex_walsh_t(x, y, z, w);
  g.volume = w.volume;
  if (!ok) return false;
  for (int i = 0; i < 3; ++i) {
    walsh8_back_t(w.G[i], g.B[i]);
    for (int a = 0; a < 8; ++a) g.B[i][a] *= w.inv;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) g.R[i][j] = w.R[i][j];
  for (int c = 0; c < 3; ++c) g.h[c] = w.h[c];
  return true;
}

/// hex_stable_length (hex8.hpp) of W elements: 2 min(h), the first smallest
/// as std::min({h0, h1, h2}) picks it, so every lane has its bits.
template <class T>
inline void hex_stable_length_t(const T h[3], T& len) {
  T m = h[1] < h[0] ? h[1] : h[0];
  m = h[2] < m ? h[2] : m;
  len = 2.0 * m;
}

}  // namespace drawbend::fe::DRAWBEND_ISA
