#pragma once
// Objectivity: how every direction-carrying history turns with the material.
//
// One rule for all of them.  Over an increment dt the element gives each
// integration point its spin W = skew(L_mid) (fe/element_kernel.hpp), with
// the three independent components w01 = W_01, w12 = W_12, w20 = W_20 [1/s].
//  - A symmetric tensor A (stress, back stress; Voigt xx, yy, zz, xy, yz, zx,
//    tensor shear components) takes the Jaumann increment
//        A <- A + dt (W A - A W),
//  - a vector a (a sheet axis RD, TD, ND) takes a <- a + dt W a.
// Both are the same first-order rotation: for A = a a^T the two agree, so a
// back stress, the stress and the anisotropy axes stay in the same relative
// orientation while the sheet wraps round a pin.  The element kernel rotates
// the stress with rotate_symmetric() before Material::update(); a material
// rotates its own tensors and axes with the same functions and the same spin
// inside update().  T is double or a lane vector (core/lanes.hpp): the
// operations and their order are the same, so results are bit-identical
// across kernels.
namespace drawbend::material {

/// The spin of one integration point over the increment: W's components [1/s]
/// and the increment's length dt [s].  All zero: no rotation.
struct Spin {
  double w01 = 0, w12 = 0, w20 = 0;
  double dt = 0;
};

/// A <- A + dt (W A - A W) for a symmetric Voigt tensor A (tensor shears).
template <class T>
inline void rotate_symmetric(const T& w01, const T& w12, const T& w20, double dt, T s[6]) {
  const T S[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  // WS = W S with W = [[0, w01, -w20], [-w01, 0, w12], [w20, -w12, 0]] (its
  // zeros left out: only the sign of a zero result could differ).
  T WS[3][3];
  for (int j = 0; j < 3; ++j) {
    WS[0][j] = w01 * S[1][j] - w20 * S[2][j];
    WS[1][j] = w12 * S[2][j] - w01 * S[0][j];
    WS[2][j] = w20 * S[0][j] - w12 * S[1][j];
  }
  // W S - S W = WS + (WS)^T since W is skew and S symmetric.
  s[0] += dt * 2 * WS[0][0];
  s[1] += dt * 2 * WS[1][1];
  s[2] += dt * 2 * WS[2][2];
  s[3] += dt * (WS[0][1] + WS[1][0]);
  s[4] += dt * (WS[1][2] + WS[2][1]);
  s[5] += dt * (WS[2][0] + WS[0][2]);
}

/// a <- a + dt W a for a vector a.
template <class T>
inline void rotate_vector(const T& w01, const T& w12, const T& w20, double dt, T a[3]) {
  const T a0 = a[0], a1 = a[1], a2 = a[2];
  a[0] = a0 + dt * (w01 * a1 - w20 * a2);
  a[1] = a1 + dt * (-w01 * a0 + w12 * a2);
  a[2] = a2 + dt * (w20 * a0 - w12 * a1);
}

inline void rotate_symmetric(const Spin& w, double s[6]) { rotate_symmetric(w.w01, w.w12, w.w20, w.dt, s); }
inline void rotate_vector(const Spin& w, double a[3]) { rotate_vector(w.w01, w.w12, w.w20, w.dt, a); }

}  // namespace drawbend::material
