#pragma once
// The Yld2004-18p yield function (material/yld2004.cpp) on W elements side by
// side, for its plasticity model's lane twin (material/lanes/yld2004_lanes.hpp):
// the transformed deviators, their principal values (sym_eigenvalues: the one
// template both use, material/principal_values.hpp), Phi,
// sigma_bar and its gradient by divided differences (Yld2004::gradient,
// equivalent).  Each function is the scalar one named above it with the same
// arithmetic in the same order, so every lane has its bits:
//  - a branch of the scalar code is a mask here, both sides computed and the
//    mask selecting one (a bitwise select: a NaN or infinity of the side not
//    taken never leaks), coincident eigenvalues included (the derivative at
//    the midpoint, lane by lane where the scalar code takes it);
//  - std::max and std::clamp are their comparisons, in their order;
//  - pow, for an exponent that is not an integer, is the same libm call,
//    lane by lane (as lane_exp, core/lanes.hpp); the principal values need
//    none (no trigonometry).
// Why copies and not one template for both: hill48_lanes.hpp says why (the
// principal values are the exception: principal_values.hpp is instantiated in
// each instruction set's namespace and, for the scalar code, in the baseline's;
// the two problems of an evaluation run interleaved, principal_values_pair).
// A change to either side must be made to both: tests/unit/test_yld2004_lanes.cpp
// fails on any difference in the bits.
//
// Vectors are returned through references, as lane_sqrt's (core/lanes.hpp: a
// 32-byte vector returned by value changes the ABI between the baseline and
// AVX builds).
//
// Compiled once per instruction set, in its namespace (as element_kernel.hpp):
// nothing here may be an inline function shared with other translation units.
#include <cmath>
#include <cstdint>

#include "core/lanes.hpp"
#include "material/principal_values.hpp"
#include "material/yld2004_plasticity.hpp"

#ifndef DRAWBEND_ISA
#define DRAWBEND_ISA baseline  // as fe/hex8_geometry.hpp: the kernel's own source sets it
#endif

namespace drawbend::material::lanes::DRAWBEND_ISA {

using YldParams = Yld2004Plasticity::LaneParams;

/// r = |v| lane by lane: the sign bit cleared (std::abs, also of -0.0 and NaN).
template <class T>
inline void lane_abs(const T& v, T& r) {
  using I = decltype(T{} < T{});
  r = (T)((I)v & ~(I{} + INT64_MIN));
}

/// r = f(v) lane by lane, f a libm function of one double (pow).
template <class T, class F>
inline void lane_call(const T& v, T& r, F&& f) {
  for (int l = 0; l < static_cast<int>(sizeof(T) / sizeof(double)); ++l) r[l] = f(v[l]);
}

/// a = std::max(a, |b|): (a < |b|) ? |b| : a.
template <class T>
inline void lane_max_abs(T& a, const T& b) {
  T m;
  lane_abs(b, m);
  a = a < m ? m : a;
}

/// r = pw(|d|, e, integral): |d|^e; integer exponents by squaring.
template <class T>
inline void yld_pw(const T& d, double e, bool integral, T& r) {
  T t;
  lane_abs(d, t);
  if (integral && e == 7.0) {  // a = 8's |d|^7: the loop below's products, unrolled (the same bits)
    const T t2 = t * t;
    r = (t * t2) * (t2 * t2);
    return;
  }
  if (integral && e >= 0) {
    r = T{} + 1.0;
    T b = t;
    for (int k = static_cast<int>(e); k > 0; k >>= 1) {
      if (k & 1) r *= b;
      if (k > 1) b *= b;
    }
    return;
  }
  T p;
  lane_call(t, p, [e](double x) { return std::pow(x, e); });
  const double at0 = e > 0 ? 0.0 : (e == 0 ? 1.0 : 0.0);
  r = t == 0.0 ? T{} + at0 : p;
}

/// transform_dev(c, s, X): X = C s (Voigt, tensor shears), Barlat's form.
template <class T>
inline void yld_transform(const double c[9], const T s[6], T X[6]) {
  X[0] = -(c[0] * s[1] + c[1] * s[2]);
  X[1] = -(c[2] * s[0] + c[3] * s[2]);
  X[2] = -(c[4] * s[0] + c[5] * s[1]);
  X[3] = c[8] * s[3];
  X[4] = c[6] * s[4];
  X[5] = c[7] * s[5];
}

/// transform_back(c, G, m): m += C^T G.
template <class T>
inline void yld_transform_back(const double c[9], const T G[6], T m[6]) {
  m[0] += -(c[2] * G[1] + c[4] * G[2]);
  m[1] += -(c[0] * G[0] + c[5] * G[2]);
  m[2] += -(c[1] * G[0] + c[3] * G[1]);
  m[3] += c[8] * G[3];
  m[4] += c[6] * G[4];
  m[5] += c[7] * G[5];
}

/// g = Exponent::g1, g2 of x against y[3].
template <class T>
inline void yld_g1(const YldParams& P, const T& x, const T y[3], T& g) {
  T r = {};
  for (int k = 0; k < 3; ++k) {
    T p;
    yld_pw(x - y[k], P.a - 2, P.integral, p);
    r += p;
  }
  g = P.a * (P.a - 1) * r;
}
template <class T>
inline void yld_g2(const YldParams& P, const T& x, const T y[3], T& g) {
  if (P.a == 2.0) {
    g = T{};
    return;
  }
  T r = {};
  for (int k = 0; k < 3; ++k) {
    const T d = x - y[k];
    T p;
    yld_pw(d, P.a - 3, P.integral && P.a >= 3, p);
    r = d == 0.0 ? r : r + (d < 0.0 ? -p : p);
  }
  g = P.a * (P.a - 1) * (P.a - 2) * r;
}

/// spectral_gradient: G = sum_i g(x_i) P_i by divided differences.  The
/// midpoint derivatives are evaluated only when some lane takes them.
template <class T>
inline void yld_spectral_gradient(const YldParams& P, const T X[6], const T x[3], const T y[3], const T f[3],
                                  const T& tol, T G[6]) {
  const T f1 = f[0], f2 = f[1], f3 = f[2];
  T mid;
  const auto s12 = x[0] - x[1] > tol, s23 = x[1] - x[2] > tol, s13 = x[0] - x[2] > tol;
  T d12 = (f1 - f2) / (x[0] - x[1]), d23 = (f2 - f3) / (x[1] - x[2]);
  if (any_set(~s12)) {
    yld_g1(P, 0.5 * (x[0] + x[1]), y, mid);
    d12 = s12 ? d12 : mid;
  }
  if (any_set(~s23)) {
    yld_g1(P, 0.5 * (x[1] + x[2]), y, mid);
    d23 = s23 ? d23 : mid;
  }
  T d123 = (d12 - d23) / (x[0] - x[2]);
  if (any_set(~s13)) {
    yld_g2(P, x[1], y, mid);
    d123 = s13 ? d123 : 0.5 * mid;
  }
  const T A[3][3] = {{X[0] - x[0], X[3], X[5]}, {X[3], X[1] - x[0], X[4]}, {X[5], X[4], X[2] - x[0]}};
  const T B[3][3] = {{X[0] - x[1], X[3], X[5]}, {X[3], X[1] - x[1], X[4]}, {X[5], X[4], X[2] - x[1]}};
  constexpr int I[6] = {0, 1, 2, 0, 1, 2}, J[6] = {0, 1, 2, 1, 2, 0};
  for (int n = 0; n < 6; ++n) {
    const int i = I[n], j = J[n];
    const T ab = A[i][0] * B[0][j] + A[i][1] * B[1][j] + A[i][2] * B[2][j];
    G[n] = (i == j ? f1 : T{}) + d12 * A[i][j] + d123 * ab;
  }
}

/// r = root_a(x, a): x^(1/a), square roots for a = 2, 4, 8.
template <class T>
inline void yld_root(const T& x, double a, T& r) {
  if (a == 8.0) {
    lane_sqrt(x, r);
    lane_sqrt(r, r);
    lane_sqrt(r, r);
  } else if (a == 4.0) {
    lane_sqrt(x, r);
    lane_sqrt(r, r);
  } else if (a == 2.0) {
    lane_sqrt(x, r);
  } else {
    lane_call(x, r, [a](double v) { return std::pow(v, 1.0 / a); });
  }
}

/// evaluate(): the scaled deviator's transforms, their principal values and
/// Phi; `some`: the lanes where the scalar evaluate() returns true (scale > 0).
template <class T>
struct YldEval {
  T scale, X1[6], X2[6], x[3], y[3], d[3][3], q[3][3], phi;
  decltype(T{} < T{}) some;
};
template <class T>
inline void yld_evaluate(const YldParams& P, const T sig[6], YldEval<T>& e) {
  const T mean = (sig[0] + sig[1] + sig[2]) / 3.0;
  T s[6] = {sig[0] - mean, sig[1] - mean, sig[2] - mean, sig[3], sig[4], sig[5]};
  e.scale = T{};
  for (const T& v : s) lane_max_abs(e.scale, v);
  e.some = e.scale > 0.0;
  const T inv = 1.0 / e.scale;
  for (T& v : s) v *= inv;
  yld_transform(P.c1, s, e.X1);
  yld_transform(P.c2, s, e.X2);
  principal_values_pair(e.X1, e.x, e.X2, e.y);  // sym_eigenvalues of each (material/principal_values.hpp)
  e.phi = T{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const T d = e.x[i] - e.y[j];
      T t;
      lane_abs(d, t);
      e.d[i][j] = d;
      yld_pw(d, P.a - 1, P.integral, e.q[i][j]);
      e.phi += e.q[i][j] * t;
    }
}

/// q = Yld2004::equivalent(sig): sigma_bar (0 for a zero deviator).  Through
/// references, as lane_sqrt (core/lanes.hpp): no vector return.
template <class T>
inline void yld_equivalent(const YldParams& P, const T sig[6], T& q) {
  YldEval<T> e;
  yld_evaluate(P, sig, e);
  T root;
  yld_root(0.25 * e.phi, P.a, root);
  const T v = e.scale * root;
  q = e.some ? v : T{};
}

/// q = Yld2004::gradient(sig, n): sigma_bar and n = d sigma_bar / d sigma (0
/// and 0 where the deviator or Phi is zero).
template <class T>
inline void yld_gradient(const YldParams& P, const T sig[6], T n[6], T& q) {
  YldEval<T> e;
  yld_evaluate(P, sig, e);
  const auto live = e.some & (e.phi > 0.0);
  T sbar_hat;
  yld_root(0.25 * e.phi, P.a, sbar_hat);
  // std::max({|x1|, |x3|, |y1|, |y3|, 1e-300}): the first of the largest, by its comparisons.
  T big;
  lane_abs(e.x[0], big);
  lane_max_abs(big, e.x[2]);
  lane_max_abs(big, e.y[0]);
  lane_max_abs(big, e.y[2]);
  lane_max_abs(big, T{} + 1e-300);
  const T tol = 1e-5 * big;  // kCoincide (yld2004.cpp)
  T fx[3], fy[3];  // g(x_i) against y, g(y_j) against x (y_j - x_i = -d_ij)
  for (int i = 0; i < 3; ++i) {
    T rx = {}, ry = {};
    for (int k = 0; k < 3; ++k) {
      rx += e.d[i][k] < 0.0 ? -e.q[i][k] : e.q[i][k];
      ry += e.d[k][i] > 0.0 ? -e.q[k][i] : e.q[k][i];
    }
    fx[i] = P.a * rx, fy[i] = P.a * ry;
  }
  T G1[6], G2[6], m[6] = {};
  yld_spectral_gradient(P, e.X1, e.x, e.y, fx, tol, G1);
  yld_spectral_gradient(P, e.X2, e.y, e.x, fy, tol, G2);
  yld_transform_back(P.c1, G1, m);
  yld_transform_back(P.c2, G2, m);
  const T mm = (m[0] + m[1] + m[2]) / 3.0;
  const T f = sbar_hat / (P.a * e.phi);
  const T nv[6] = {f * (m[0] - mm), f * (m[1] - mm), f * (m[2] - mm), f * m[3], f * m[4], f * m[5]};
  for (int c = 0; c < 6; ++c) n[c] = live ? nv[c] : T{};
  const T v = e.scale * sbar_hat;
  q = live ? v : T{};
}

}  // namespace drawbend::material::lanes::DRAWBEND_ISA
