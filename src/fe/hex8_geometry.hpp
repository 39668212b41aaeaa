#pragma once
// The hexahedron's geometry as templates over the lane type (fe/lanes.hpp):
// one source for the scalar functions of hex8.cpp and for the element loop's
// vector kernels (fe/element_kernel.hpp).
//
// Each instruction set compiles these templates in its own namespace
// (DRAWBEND_ISA, set per source file), so that a vector-ISA instantiation can
// never stand in for the baseline one at link time.
#include <cmath>

#include "fe/hex8.hpp"
#include "fe/lanes.hpp"

#ifndef DRAWBEND_ISA
#define DRAWBEND_ISA baseline
#endif

namespace drawbend::fe::DRAWBEND_ISA {

/// 12 dV/dx, 12 dV/dy, 12 dV/dz of one corner from the coordinates of the six
/// others that enter it (the twelfth is applied by the callers, once).
template <class T>
inline void volu_der12(const T& x0, const T& x1, const T& x2, const T& x3, const T& x4, const T& x5, const T& y0,
                       const T& y1, const T& y2, const T& y3, const T& y4, const T& y5, const T& z0, const T& z1,
                       const T& z2, const T& z3, const T& z4, const T& z5, T* dvdx, T* dvdy, T* dvdz) {
  *dvdx = (y1 + y2) * (z0 + z1) - (y0 + y1) * (z1 + z2) + (y0 + y4) * (z3 + z4) - (y3 + y4) * (z0 + z4) -
          (y2 + y5) * (z3 + z5) + (y3 + y5) * (z2 + z5);
  *dvdy = -(x1 + x2) * (z0 + z1) + (x0 + x1) * (z1 + z2) - (x0 + x4) * (z3 + z4) + (x3 + x4) * (z0 + z4) +
          (x2 + x5) * (z3 + z5) - (x3 + x5) * (z2 + z5);
  *dvdz = -(y1 + y2) * (x0 + x1) + (y0 + y1) * (x1 + x2) - (y0 + y4) * (x3 + x4) + (y3 + y4) * (x0 + x4) +
          (y2 + y5) * (x3 + x5) - (y3 + y5) * (x2 + x5);
}

/// 12 dV/dx_a of the trilinear hexahedron (Flanagan & Belytschko 1981, as in LULESH).
template <class T>
inline void volume_derivatives12_t(const T x[8], const T y[8], const T z[8], T dvdx[8], T dvdy[8], T dvdz[8]) {
  static constexpr int p[8][6] = {{1, 2, 3, 4, 5, 7}, {2, 3, 0, 5, 6, 4}, {3, 0, 1, 6, 7, 5}, {0, 1, 2, 7, 4, 6},
                                  {7, 6, 5, 0, 3, 1}, {4, 7, 6, 1, 0, 2}, {5, 4, 7, 2, 1, 3}, {6, 5, 4, 3, 2, 0}};
#pragma GCC unroll 8
  for (int a = 0; a < 8; ++a) {
    const int* q = p[a];
    volu_der12(x[q[0]], x[q[1]], x[q[2]], x[q[3]], x[q[4]], x[q[5]], y[q[0]], y[q[1]], y[q[2]], y[q[3]], y[q[4]],
               y[q[5]], z[q[0]], z[q[1]], z[q[2]], z[q[3]], z[q[4]], z[q[5]], &dvdx[a], &dvdy[a], &dvdz[a]);
  }
}

/// dV/dx_a of the trilinear hexahedron.
template <class T>
inline void volume_derivatives_t(const T x[8], const T y[8], const T z[8], T dvdx[8], T dvdy[8], T dvdz[8]) {
  constexpr double twelfth = 1.0 / 12.0;
  volume_derivatives12_t(x, y, z, dvdx, dvdy, dvdz);
  for (int a = 0; a < 8; ++a) {
    dvdx[a] *= twelfth;
    dvdy[a] *= twelfth;
    dvdz[a] *= twelfth;
  }
}

/// B, V, the corotational frame and half-lengths.  Returns false, with only
/// the volume set, when the volume of any lane is not positive.
template <class T>
inline bool hex_geometry_t(const T x[8], const T y[8], const T z[8], HexGeometryT<T>& g) {
  // D_a = 12 dV/dx_a; V is homogeneous of degree 3 in the coordinates:
  // V = (1/3) sum_a x_a . dV/dx_a = (1/36) sum_a x_a . D_a, and B_a = D_a / 12V.
  T dvdx[8], dvdy[8], dvdz[8];
  volume_derivatives12_t(x, y, z, dvdx, dvdy, dvdz);
  T v36 = {};
  for (int a = 0; a < 8; ++a) v36 += x[a] * dvdx[a] + y[a] * dvdy[a] + z[a] * dvdz[a];
  const T v = v36 * (1.0 / 36.0);
  g.volume = v;
  if (!all_positive(v)) return false;
  const T inv = 3.0 / v36;
  for (int a = 0; a < 8; ++a) {
    g.B[0][a] = dvdx[a] * inv;
    g.B[1][a] = dvdy[a] * inv;
    g.B[2][a] = dvdz[a] * inv;
  }
  // Jacobian columns at the centre: dx/dxi = sum_a x_a xi_a / 8, etc. (the
  // signed sums first: the eighth is exact, a power of two).
  T J[3][3] = {};
#pragma GCC unroll 8
  for (int a = 0; a < 8; ++a) {
    const double n[3] = {kXiN[a], kEtaN[a], kZetaN[a]};
    for (int k = 0; k < 3; ++k) {
      J[0][k] += x[a] * n[k];
      J[1][k] += y[a] * n[k];
      J[2][k] += z[a] * n[k];
    }
  }
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) J[i][k] *= 0.125;
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

/// hex_stable_length (hex8.hpp) of W elements: 2 min(h), the first smallest
/// as std::min({h0, h1, h2}) picks it, so every lane has its bits.
template <class T>
inline void hex_stable_length_t(const T h[3], T& len) {
  T m = h[1] < h[0] ? h[1] : h[0];
  m = h[2] < m ? h[2] : m;
  len = 2.0 * m;
}

}  // namespace drawbend::fe::DRAWBEND_ISA
