#pragma once
// The principal values of a symmetric 3x3 tensor without trigonometry, written
// once for one value (T = double: sym_eigenvalues, material/yld2004.cpp) and for
// W values side by side (T = a GCC vector: the Yld2004-18p lanes,
// material/lanes/yld2004_function_lanes.hpp).  Only +, -, *, /, sqrt and
// selects (?:, no branch on the data), so each lane gives the scalar bits.
//
// With m the mean, B = V - m I, p = sqrt(|B|^2 / 6) and Y = B / p (traceless,
// |Y|^2 = 6), the eigenvalues of Y are the roots of y^3 - 3 y - 2 r,
// r = det(Y) / 2 in [-1, 1]:
//  1. the isolated root x0 (the largest for r >= 0, the smallest for r < 0;
//     |x0| in [sqrt 3, 2], at least sqrt 3 from both others): the largest root
//     of y^3 - 3 y - 2 |r| by a degree-8 polynomial in |r| (error < 3.7e-9,
//     Chebyshev interpolation of 2 cos(acos(|r|) / 3) on [0, 1]) and one Newton
//     step (error 0.87 x 3.7e-9 squared, below round-off: the cubic's root
//     there is simple and well separated), signed as r;
//  2. the other two, x0's complement: with v the null vector of Y - x0 I (the
//     largest of the cross products of its rows, at least sqrt 3 long), the
//     tensor D = Y + (x0 / 2) I - (3 x0 / 2) v v^T / |v|^2 has eigenvalues 0
//     and +-h, h half the pair's distance, so h = sqrt(|D|^2 / 2) and the pair
//     is -x0 / 2 +- h.  D is formed from the tensor's entries, so h is exact to
//     round-off of the scale even where the two roots coincide (equibiaxial and
//     plane-strain points): the characteristic polynomial alone resolves a
//     double root only to the square root of round-off (~1e-8), as the
//     trigonometric form before this one did;
//  3. m + p y, in descending order by construction (no sort: the map is
//     monotone in y).  B = 0 (a triple root) gives m three times.
// Accuracy: within 1e-13 of the largest |eigenvalue| on every spectrum of
// tests/unit/test_material_yld2004.cpp (eigenvalues_closed_form_with_coincident_roots:
// 2,000 random spectra, exact and near-coincident pairs, triple roots, a large
// mean, each under two rotations; the worst 4.1e-16).
//
// Compiled in the material library (T = double) and once per instruction set in
// the element kernels, each in the namespace DRAWBEND_ISA names (as
// element_kernel.hpp): an AVX instantiation never stands in for a baseline one.
#include "core/lanes.hpp"

#ifndef DRAWBEND_ISA
#define DRAWBEND_ISA baseline  // as fe/hex8_geometry.hpp: the kernel's own source sets it
#endif

namespace drawbend::material::lanes::DRAWBEND_ISA {

/// The work of principal_values in four stages, each ending at a square root or a division: the pair form
/// runs each stage for both tensors before the next, so that their latency chains overlap (the same
/// operations on each tensor in the same order: the same bits as one at a time).
template <class T>
struct PrincipalWork {
  T m, p2, p, y[6], r, x0, u[3], nu;
};
template <class T>
__attribute__((always_inline)) inline void principal_stage1(const T v[6], PrincipalWork<T>& k) {
  k.m = (v[0] + v[1] + v[2]) * (1.0 / 3.0);  // products, not divisions: the chain is latency-bound
  const T b0 = v[0] - k.m, b1 = v[1] - k.m, b2 = v[2] - k.m;
  k.p2 = b0 * b0 + b1 * b1 + b2 * b2 + 2.0 * (v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
  lane_sqrt(k.p2 * (1.0 / 6.0), k.p);
  const T q = 1.0 / k.p;  // infinite for B = 0: that lane's NaNs are not selected below
  k.y[0] = b0 * q, k.y[1] = b1 * q, k.y[2] = b2 * q, k.y[3] = v[3] * q, k.y[4] = v[4] * q, k.y[5] = v[5] * q;
}
template <class T>
__attribute__((always_inline)) inline void principal_stage2(PrincipalWork<T>& k) {
  const T y0 = k.y[0], y1 = k.y[1], y2 = k.y[2], y3 = k.y[3], y4 = k.y[4], y5 = k.y[5];
  const T det = y0 * (y1 * y2 - y4 * y4) - y3 * (y3 * y2 - y4 * y5) + y5 * (y3 * y4 - y1 * y5);
  const T h = 0.5 * det;
  const T r = h < -1.0 ? T{} - 1.0 : (1.0 < h ? T{} + 1.0 : h);
  const T s = r < 0.0 ? -r : r;
  // 1. The largest root of y^3 - 3 y - 2 s, s in [0, 1]: the start (Estrin's scheme), one Newton step.
  const T s2 = s * s, s4 = s2 * s2;
  const T e01 = 1.7320508111991297 + 0.33333274228889065 * s, e23 = -0.0962088829033415 + 0.049208593562890236 * s;
  const T e45 = -0.030214550230533002 + 0.018766660931406574 * s, e67 = -0.009859382080473248 + 0.00352971357400141 * s;
  T x = (e01 + e23 * s2) + (e45 + e67 * s2) * s4 + -0.0006057083575999261 * (s4 * s4);
  x = x - (x * (x * x - 3.0) - 2.0 * s) / (3.0 * (x * x - 1.0));
  k.r = r;
  k.x0 = r < 0.0 ? -x : x;
}
template <class T>
__attribute__((always_inline)) inline void principal_stage3(PrincipalWork<T>& k) {
  // 2. The null vector of M = Y - x0 I: the longest cross product of two of its rows.
  const T y3 = k.y[3], y4 = k.y[4], y5 = k.y[5];
  const T m00 = k.y[0] - k.x0, m11 = k.y[1] - k.x0, m22 = k.y[2] - k.x0;
  const T ca[3] = {y3 * y4 - y5 * m11, y5 * y3 - m00 * y4, m00 * m11 - y3 * y3};  // row 0 x row 1
  const T cb[3] = {m11 * m22 - y4 * y4, y4 * y5 - y3 * m22, y3 * y4 - m11 * y5};  // row 1 x row 2
  const T cc[3] = {y4 * y5 - m22 * y3, m22 * m00 - y5 * y5, y5 * y3 - y4 * m00};  // row 2 x row 0
  const T na = ca[0] * ca[0] + ca[1] * ca[1] + ca[2] * ca[2];
  const T nb = cb[0] * cb[0] + cb[1] * cb[1] + cb[2] * cb[2];
  const T nc = cc[0] * cc[0] + cc[1] * cc[1] + cc[2] * cc[2];
  T nu = nb > na ? nb : na;
  for (int i = 0; i < 3; ++i) k.u[i] = nb > na ? cb[i] : ca[i];
  for (int i = 0; i < 3; ++i) k.u[i] = nc > nu ? cc[i] : k.u[i];
  k.nu = nc > nu ? nc : nu;
}
template <class T>
__attribute__((always_inline)) inline void principal_stage4(const PrincipalWork<T>& k, T lam[3]) {
  const T* y = k.y;
  const T* u = k.u;
  const T x0 = k.x0, w = 1.5 * x0 / k.nu, hx = 0.5 * x0;
  const T d0 = y[0] + hx - w * u[0] * u[0], d1 = y[1] + hx - w * u[1] * u[1], d2 = y[2] + hx - w * u[2] * u[2];
  const T d3 = y[3] - w * u[0] * u[1], d4 = y[4] - w * u[1] * u[2], d5 = y[5] - w * u[2] * u[0];
  const T dd = d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * (d3 * d3 + d4 * d4 + d5 * d5);
  T half;
  lane_sqrt(0.5 * dd, half);
  const T hi = -hx + half, lo = -hx - half;
  // 3. Descending: x0 first for r >= 0, last for r < 0.
  const T m = k.m, p = k.p, r = k.r;
  const T l0 = m + p * (r < 0.0 ? hi : x0), l1 = m + p * (r < 0.0 ? lo : hi), l2 = m + p * (r < 0.0 ? x0 : lo);
  lam[0] = k.p2 > 0.0 ? l0 : m;
  lam[1] = k.p2 > 0.0 ? l1 : m;
  lam[2] = k.p2 > 0.0 ? l2 : m;
}

/// The eigenvalues of the symmetric tensor v (Voigt: xx, yy, zz, xy, yz, zx; tensor shears), descending.
template <class T>
__attribute__((always_inline)) inline void principal_values(const T v[6], T lam[3]) {
  PrincipalWork<T> k;
  principal_stage1(v, k);
  principal_stage2(k);
  principal_stage3(k);
  principal_stage4(k, lam);
}
/// The same for two tensors (a, b), interleaved stage by stage: the bits of two calls of principal_values.
template <class T>
__attribute__((always_inline)) inline void principal_values_pair(const T va[6], T la[3], const T vb[6], T lb[3]) {
  PrincipalWork<T> a, b;
  principal_stage1(va, a);
  principal_stage1(vb, b);
  principal_stage2(a);
  principal_stage2(b);
  principal_stage3(a);
  principal_stage3(b);
  principal_stage4(a, la);
  principal_stage4(b, lb);
}

}  // namespace drawbend::material::lanes::DRAWBEND_ISA
