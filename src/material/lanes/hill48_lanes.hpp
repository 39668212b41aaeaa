#pragma once
// Hill'48 in the sheet frame on W elements side by side, for the combined-
// hardening model on the lanes (material/lanes/combined_lanes.hpp): the sheet axes turned
// with the spin and re-orthonormalised, tensors into and out of the sheet
// axes, the Hill'48 equivalent stress and the relative-stress solve
// (I + kappa T M) xi = xi*.  Each function is the scalar one named above it
// (material/combined_plasticity.cpp, material/objectivity.hpp) with the same
// arithmetic in the same order, so every lane has its bits.
//
// Why copies and not one template for both.  The scalar functions live in the
// material library, built once for the x86-64 baseline; these are built per
// instruction set, each in that set's namespace, so that an AVX instantiation can
// never stand in for a baseline one at link time.  A change to either side
// must be made to both: tests/unit/test_element_kernel.cpp fails on any
// difference in the bits.
//
// Compiled once per instruction set, in its namespace (as element_kernel.hpp):
// nothing here may be an inline function shared with other translation units.
#include "core/lanes.hpp"
#include "material/hill48.hpp"
#include "material/objectivity.hpp"

#ifndef DRAWBEND_ISA
#define DRAWBEND_ISA baseline  // as fe/hex8_geometry.hpp: the kernel's own source sets it
#endif

namespace drawbend::material::lanes::DRAWBEND_ISA {

/// cross(a, b, c): c = a x b.
template <class T>
inline void lane_cross(const T a[3], const T b[3], T c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/// orthonormalise(rd, nd): RD unit, then ND made normal to RD and unit.
template <class T>
inline void lane_orthonormalise(T rd[3], T nd[3]) {
  T lr, ln;
  lane_sqrt(rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2], lr);
  for (int i = 0; i < 3; ++i) rd[i] /= lr;
  const T d = rd[0] * nd[0] + rd[1] * nd[1] + rd[2] * nd[2];
  for (int i = 0; i < 3; ++i) nd[i] -= d * rd[i];
  lane_sqrt(nd[0] * nd[0] + nd[1] * nd[1] + nd[2] * nd[2], ln);
  for (int i = 0; i < 3; ++i) nd[i] /= ln;
}

/// Step 1 of CombinedPlasticity::update() for the axes: with `turn` (a spin
/// over dt != 0), RD and ND turn with the spin w = (W_01, W_12, W_20) and are
/// re-orthonormalised; then Q's rows are RD, TD = ND x RD, ND.  Also the Q of
/// tangent_ratio() (axes()) for the same RD and ND.
template <class T>
inline void sheet_frame(const T w[3], double dt, bool turn, T rd[3], T nd[3], T Q[3][3]) {
  if (turn) {
    material::rotate_vector(w[0], w[1], w[2], dt, rd);
    material::rotate_vector(w[0], w[1], w[2], dt, nd);
    lane_orthonormalise(rd, nd);
  }
  T td[3];
  lane_cross(nd, rd, td);
  for (int i = 0; i < 3; ++i) {
    Q[0][i] = rd[i];
    Q[1][i] = td[i];
    Q[2][i] = nd[i];
  }
}

/// transform(Q, v, out, to_local): out = Q A Q^T (to_local) or Q^T A Q, A the
/// symmetric tensor of the Voigt vector v (tensor shears), as P (A P^T).
template <bool to_local, class T>
inline void sheet_transform(const T Q[3][3], const T v[6], T out[6]) {
  const T A[3][3] = {{v[0], v[3], v[5]}, {v[3], v[1], v[4]}, {v[5], v[4], v[2]}};
  T P[3][3], C[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) P[i][k] = to_local ? Q[i][k] : Q[k][i];
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) C[k][j] = A[k][0] * P[j][0] + A[k][1] * P[j][1] + A[k][2] * P[j][2];
  constexpr int I[6] = {0, 1, 2, 0, 1, 2}, J[6] = {0, 1, 2, 1, 2, 0};
  for (int n = 0; n < 6; ++n)
    out[n] = P[I[n]][0] * C[0][J[n]] + P[I[n]][1] * C[1][J[n]] + P[I[n]][2] * C[2][J[n]];
}

/// equivalent(x): q = sigma_bar(x), Hill'48 in the sheet axes.
template <class T>
inline void hill_equivalent(const Hill48& h, const T x[6], T& q) {
  const T a = x[1] - x[2], b = x[2] - x[0], c = x[0] - x[1];
  const T q2 = h.F * a * a + h.G * b * b + h.H * c * c + 2.0 * (h.N * x[3] * x[3] + h.L * x[4] * x[4] + h.M * x[5] * x[5]);
  lane_sqrt(q2, q);
}

/// solve_relative(kappa, xs, xi): (I + kappa T M) xi = xs.
template <class T>
inline void hill_solve_relative(const Hill48& h, const T& kappa, const T xs[6], T xi[6]) {
  const double F = h.F, G = h.G, H = h.H;
  const T A[3][3] = {{1.0 + kappa * (G + H), -kappa * H, -kappa * G},
                     {-kappa * H, 1.0 + kappa * (F + H), -kappa * F},
                     {-kappa * G, -kappa * F, 1.0 + kappa * (F + G)}};
  const T det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  const T b0 = xs[0], b1 = xs[1], b2 = xs[2];
  xi[0] = (b0 * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (b1 * A[2][2] - A[1][2] * b2) +
           A[0][2] * (b1 * A[2][1] - A[1][1] * b2)) / det;
  xi[1] = (A[0][0] * (b1 * A[2][2] - A[1][2] * b2) - b0 * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
           A[0][2] * (A[1][0] * b2 - b1 * A[2][0])) / det;
  xi[2] = (A[0][0] * (A[1][1] * b2 - b1 * A[2][1]) - A[0][1] * (A[1][0] * b2 - b1 * A[2][0]) +
           b0 * (A[1][0] * A[2][1] - A[1][1] * A[2][0])) / det;
  xi[3] = xs[3] / (1.0 + kappa * h.N);
  xi[4] = xs[4] / (1.0 + kappa * h.L);
  xi[5] = xs[5] / (1.0 + kappa * h.M);
}

}  // namespace drawbend::material::lanes::DRAWBEND_ISA
