// The element loop of the explicit solver: the hexahedron with two
// integration points through the thickness, for one element or for W elements
// side by side (one per lane, fe/lanes.hpp).  Compiled once per instruction
// set (fe/element_view.hpp); the solver's driver is fe/element_forces.cpp.
//
// Why two points.  A one-point element crossed by the neutral axis of a bent,
// plastic strip sees almost no strain at its centre, stays elastic, and its
// stabilisation then carries a large spurious bending moment; under back
// tension the neutral axis moves into the elements.  With two points at
// zeta = +-1/sqrt(3) through the thickness (zeta: the element's third natural
// axis, normal to the sheet in the generated meshes) each half of the element
// yields on its own.
//
// Assumed strain.  At the points, L_+- = L_mean +- (1/sqrt 3) L_C with
//   L_mean = sum_a v_a (x) B_a          (Flanagan-Belytschko uniform gradient)
//   L_C    = sum_a v_a (x) C_a,  C_a = R (gamma_zx,a / 8h_x, gamma_yz,a / 8h_y, 0),
// built from the hourglass vectors gamma (orthogonal to linear fields, so the
// patch test still holds) of the two modes that are linear in zeta.  For a
// rectangular element this is exact 1x1x2 Gauss integration of bending, free
// of transverse shear locking.  The thickness strain of a trilinear element
// cannot vary linearly through it, so its zeta-linear part is assumed:
//   (L_C)_zz = -c ((L_C)_xx + (L_C)_yy),  c = nu/(1-nu) elastic (plane stress
// through the thickness), 1 plastic (isochoric), blended by the tangent ratio;
// without it plastic incompressibility would lock the element in bending.
// The nodal forces follow from the internal power (V/2) sum_+- sigma : L.
//
// Stabilisation.  The two modes linear in zeta now have stiffness from the
// integration points; the remaining hourglass modes (xi*eta, xi*eta*zeta) keep
// the physical corotational stiffness of hex8.hpp with the elastic moduli.
//
// Include this header in exactly one translation unit per instruction set
// (element_kernel.cpp, element_kernel_avx2.cpp, element_kernel_avx512.cpp): it
// defines element_range.
//
// Structure (LULESH): gather -> geometry and strain rates on fixed-size locals
// (vector lanes) -> material update (J2 and combined hardening / Hill'48 on
// the lanes with masks; other models, and W = 1, one point at a time) ->
// forces on fixed-size locals -> scatter into the corner slots (node-major in
// the solver, so that its nodal sums read in order).
#include <algorithm>
#include <cmath>

#include "fe/combined_lanes.hpp"
#include "fe/element_view.hpp"
#include "fe/hex8_geometry.hpp"
#include "fe/material_lanes.hpp"

namespace drawbend::fe::DRAWBEND_ISA {

namespace kernel {
constexpr double kRelax = 0.01;                 // tangent ratio relaxes over ~100 cycles (no chatter)
constexpr double kZg = 0.57735026918962576;    // 1/sqrt(3)
inline constexpr material::Spin kNoSpin{};       // for materials without rotating history

template <class T>
inline void inverse3(const T M[3][3], T Mi[3][3]) {
  const T det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
  const T id = 1.0 / det;
  Mi[0][0] = (M[1][1] * M[2][2] - M[1][2] * M[2][1]) * id;
  Mi[0][1] = (M[0][2] * M[2][1] - M[0][1] * M[2][2]) * id;
  Mi[0][2] = (M[0][1] * M[1][2] - M[0][2] * M[1][1]) * id;
  Mi[1][0] = (M[1][2] * M[2][0] - M[1][0] * M[2][2]) * id;
  Mi[1][1] = (M[0][0] * M[2][2] - M[0][2] * M[2][0]) * id;
  Mi[1][2] = (M[0][2] * M[1][0] - M[0][0] * M[1][2]) * id;
  Mi[2][0] = (M[1][0] * M[2][1] - M[1][1] * M[2][0]) * id;
  Mi[2][1] = (M[0][1] * M[2][0] - M[0][0] * M[2][1]) * id;
  Mi[2][2] = (M[0][0] * M[1][1] - M[0][1] * M[1][0]) * id;
}

/// out = R A R^T (to_local false: local to global) or R^T A R (to_local true).
template <bool to_local, class T>
inline void rotate(const T R[3][3], const T A[3][3], T out[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T sacc = {};
      for (int k = 0; k < 3; ++k)
        for (int m = 0; m < 3; ++m) {
          if constexpr (to_local)
            sacc += R[k][i] * A[k][m] * R[m][j];
          else
            sacc += R[i][k] * A[k][m] * R[j][m];
        }
      out[i][j] = sacc;
    }
}

/// Jaumann rotation of one point's stress s (in place) over dt, its strain
/// increment deps (engineering shear) and its spin w = (W_01, W_12, W_20),
/// from the mid-interval gradient L.  The material turns its own back stresses
/// and axes with the same spin and function (material/objectivity.hpp).
template <class T>
inline void rotate_and_strain(const T L[3][3], double dt, T s[6], T deps[6], T w[3]) {
  w[0] = 0.5 * (L[0][1] - L[1][0]);
  w[1] = 0.5 * (L[1][2] - L[2][1]);
  w[2] = 0.5 * (L[2][0] - L[0][2]);
  material::rotate_symmetric(w[0], w[1], w[2], dt, s);
  deps[0] = L[0][0] * dt;
  deps[1] = L[1][1] * dt;
  deps[2] = L[2][2] * dt;
  deps[3] = (L[0][1] + L[1][0]) * dt;
  deps[4] = (L[1][2] + L[2][1]) * dt;
  deps[5] = (L[2][0] + L[0][2]) * dt;
}

/// The time-stamp counter (fe/phase_times.hpp), for the per-phase split of
/// make bench; a builtin, so no code outside this namespace (build.isa_symbols).
inline std::uint64_t ticks() {
#if defined(__x86_64__)
  return __builtin_ia32_rdtsc();
#else
  return 0;
#endif
}

/// Elements e0 .. e0+W-1.  Returns the lowest inverted one, or -1.
template <int W>
int element_block(const ElementView& ev, int e0) {
  using T = typename Lanes<W>::type;
  const double dtp = ev.dtp;
  // Gather.
  T x[8], y[8], z[8], v[8][3];
  for (int a = 0; a < 8; ++a)
    for (int l = 0; l < W; ++l) {
      const int i = ev.hex[e0 + l][a];
      set_lane(x[a], l, ev.nodes.x[i]);
      set_lane(y[a], l, ev.nodes.y[i]);
      set_lane(z[a], l, ev.nodes.z[i]);
      set_lane(v[a][0], l, ev.nodes.vx[i]);
      set_lane(v[a][1], l, ev.nodes.vy[i]);
      set_lane(v[a][2], l, ev.nodes.vz[i]);
    }
  HexGeometryT<T> g;
  if (!hex_geometry_t(x, y, z, g)) {
    if constexpr (W == 1) {
      return e0;
    } else {  // one by one: the inverted element is reported, the others proceed as usual
      int inverted = -1;
      for (int l = 0; l < W; ++l) {
        const int r = element_block<1>(ev, e0 + l);
        if (r >= 0 && inverted < 0) inverted = r;
      }
      return inverted;
    }
  }
  const T V = g.volume;
  const T(*R)[3] = g.R;
  // Hourglass vectors gamma_alpha,a = h_alpha,a - (h_alpha . x) . B_a.
  T gam[4][8];
#pragma GCC unroll 4
  for (int al = 0; al < 4; ++al) {
    T hx = {}, hy = {}, hz = {};
#pragma GCC unroll 8
    for (int b = 0; b < 8; ++b) {
      hx += kHg[al][b] * x[b];
      hy += kHg[al][b] * y[b];
      hz += kHg[al][b] * z[b];
    }
    for (int a = 0; a < 8; ++a) gam[al][a] = kHg[al][a] - (hx * g.B[0][a] + hy * g.B[1][a] + hz * g.B[2][a]);
  }
  // Local velocities, mean and thickness-linear velocity gradients.
  T vl[8][3], Ln[3][3] = {}, LCl[3][3] = {}, cx[8], cy[8];
#pragma GCC unroll 8
  for (int a = 0; a < 8; ++a) {
    for (int i = 0; i < 3; ++i) vl[a][i] = R[0][i] * v[a][0] + R[1][i] * v[a][1] + R[2][i] * v[a][2];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Ln[i][j] += v[a][i] * g.B[j][a];
    cx[a] = gam[1][a] / (8.0 * g.h[0]);  // zeta*xi mode: d/dx of the zeta-linear part
    cy[a] = gam[0][a] / (8.0 * g.h[1]);  // eta*zeta mode: d/dy
    for (int i = 0; i < 3; ++i) {
      LCl[i][0] += vl[a][i] * cx[a];
      LCl[i][1] += vl[a][i] * cy[a];
    }
  }
  T rbar;
  for (int l = 0; l < W; ++l) set_lane(rbar, l, ev.hg_ratio[e0 + l]);
  const T c = rbar * ev.c_elastic + (1.0 - rbar);
  LCl[2][2] = -c * (LCl[0][0] + LCl[1][1]);
  T LC[3][3];
  rotate<false>(R, LCl, LC);  // R LCl R^T
  // Mid-interval geometry: L_mid = L (I - dt/2 L_mean)^-1 (exact for rigid rotation).
  T M[3][3], Mi[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M[i][j] = (i == j ? 1.0 : 0.0) - 0.5 * dtp * Ln[i][j];
  inverse3(M, Mi);
  // The two integration points: Jaumann rotation and strain increment ...
  T s[2][6], deps[2][6], spin[2][3];
  for (int gp = 0; gp < 2; ++gp) {
    const double zeta = gp == 0 ? kZg : -kZg;
    T Lg[3][3], Lmid[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Lg[i][j] = Ln[i][j] + zeta * LC[i][j];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Lmid[i][j] = Lg[i][0] * Mi[0][j] + Lg[i][1] * Mi[1][j] + Lg[i][2] * Mi[2][j];
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < W; ++l) set_lane(s[gp][k], l, ev.sig[12 * (e0 + l) + 6 * gp + k]);
    rotate_and_strain(Lmid, dtp, s[gp], deps[gp], spin[gp]);
  }
  // ... the material update, with the stress power increment per unit volume
  // by the midpoint rule; the tangent ratio.  J2 and CombinedPlasticity on
  // the lanes, branch-free (fe/material_lanes.hpp, fe/combined_lanes.hpp);
  // other materials one point at a time (each turns its own history with the
  // point's spin).
  const material::Material& mat = *ev.mat;
  const std::uint64_t tick0 = ev.material_ticks ? ticks() : 0;
  T ratio, snew[2][6];
  bool on_lanes = false;
  if constexpr (W > 1) {
    if (ev.j2_lanes) {
      j2_points<W>(ev, e0, s, deps, V, ratio, snew);
      on_lanes = true;
    } else if (ev.combined_lanes) {
      combined_points<W>(ev, e0, s, deps, spin, V, ratio, snew);
      on_lanes = true;
    }
  }
  for (int l = 0; l < W && !on_lanes; ++l) {
    const int e = e0 + l;
    double* st[2] = {nullptr, nullptr};
    if (ev.ns) {
      st[0] = &ev.state[static_cast<std::size_t>(e) * 2 * ev.ns];
      st[1] = st[0] + ev.ns;
    }
    double ie = 0;
    for (int gp = 0; gp < 2; ++gp) {
      double* sp = &ev.sig[12 * e + 6 * gp];
      double d[6];
      for (int k = 0; k < 6; ++k) {
        sp[k] = lane(s[gp][k], l);
        d[k] = lane(deps[gp][k], l);
      }
      if (ev.spin) {
        const material::Spin wp{lane(spin[gp][0], l), lane(spin[gp][1], l), lane(spin[gp][2], l), dtp};
        mat.update(d, wp, sp, st[gp]);
      } else {
        mat.update(d, kNoSpin, sp, st[gp]);
      }
      double w = 0;
      for (int k = 0; k < 6; ++k) w += 0.5 * (lane(s[gp][k], l) + sp[k]) * d[k];
      ie += w;
    }
    ev.ie_inc[e] = 0.5 * lane(V, l) * ie;
    const double r0 = mat.tangent_ratio(&ev.sig[12 * e], st[0]), r1 = mat.tangent_ratio(&ev.sig[12 * e + 6], st[1]);
    set_lane(ratio, l, 0.5 * (r0 + r1));
  }
  if (ev.material_ticks) __atomic_fetch_add(ev.material_ticks, ticks() - tick0, __ATOMIC_RELAXED);
  // The new stresses: from the lanes, or from ev.sig where the points were updated one by one.
  T sp[6], sm[6];
  for (int k = 0; k < 6; ++k) {
    if (on_lanes) {
      sp[k] = snew[0][k];
      sm[k] = snew[1][k];
      continue;
    }
    for (int l = 0; l < W; ++l) {
      set_lane(sp[k], l, ev.sig[12 * (e0 + l) + k]);
      set_lane(sm[k], l, ev.sig[12 * (e0 + l) + 6 + k]);
    }
  }
  // Internal forces: mean part (V/2)(sig+ + sig-) . B_a ...
  T smean[6], f[8][3];
  for (int k = 0; k < 6; ++k) smean[k] = 0.5 * (sp[k] + sm[k]);
  for (int a = 0; a < 8; ++a) {
    const T b0 = g.B[0][a], b1 = g.B[1][a], b2 = g.B[2][a];
    f[a][0] = V * (smean[0] * b0 + smean[3] * b1 + smean[5] * b2);
    f[a][1] = V * (smean[3] * b0 + smean[1] * b1 + smean[4] * b2);
    f[a][2] = V * (smean[5] * b0 + smean[4] * b1 + smean[2] * b2);
  }
  // ... plus the thickness-linear part (V/2) Dl : LCl(v), Dl = R^T (sig+ - sig-)/sqrt3 R.
  const T dg[3][3] = {{kZg * (sp[0] - sm[0]), kZg * (sp[3] - sm[3]), kZg * (sp[5] - sm[5])},
                      {kZg * (sp[3] - sm[3]), kZg * (sp[1] - sm[1]), kZg * (sp[4] - sm[4])},
                      {kZg * (sp[5] - sm[5]), kZg * (sp[4] - sm[4]), kZg * (sp[2] - sm[2])}};
  T Dl[3][3];
  rotate<true>(R, dg, Dl);  // R^T dg R
  // Remaining hourglass modes (xi*eta, xi*eta*zeta), corotational, physical stiffness.
  const T rnew = rbar + kRelax * (ratio - rbar);
  for (int l = 0; l < W; ++l) ev.hg_ratio[e0 + l] = lane(rnew, l);
  // The remaining modes keep the elastic modulus: bending is carried by the
  // integration points, and a stiffness that follows yielding would pump
  // energy into these modes as material streams through a bend (elastic ->
  // plastic -> elastic), which a draw-bend strip does.
  const double Er = ev.E0;
  const T ih2[3] = {1.0 / (g.h[0] * g.h[0]), 1.0 / (g.h[1] * g.h[1]), 1.0 / (g.h[2] * g.h[2])};
  T q[2][3] = {};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) {
      q[0][i] += vl[a][i] * gam[2][a];
      q[1][i] += vl[a][i] * gam[3][a];
    }
  T Q[6], Qo[6];  // [mode xi*eta: 3][mode xi*eta*zeta: 3], now and before this step
  for (int k = 0; k < 6; ++k) {
    for (int l = 0; l < W; ++l) set_lane(Q[k], l, ev.hgq[6 * (e0 + l) + k]);
    Qo[k] = Q[k];
  }
  for (int i = 0; i < 3; ++i) {
    const T K2 = i < 2 ? Er * V * ih2[i] / 3.0 : ev.G0 * V * (ih2[0] + ih2[1]) / 3.0;
    const T K3 = Er * V * ih2[i] / 9.0;
    Q[i] += dtp * ev.hourglass * K2 / 64.0 * q[0][i];
    Q[3 + i] += dtp * ev.hourglass * K3 / 64.0 * q[1][i];
  }
  for (int k = 0; k < 6; ++k)
    for (int l = 0; l < W; ++l) ev.hgq[6 * (e0 + l) + k] = lane(Q[k], l);
  // Hourglass energy by the midpoint rule, as the stress power above:
  // sum_a (R fh_a) . v_a = sum_a fh_a . vl_a = Q . q, with the mean of the
  // generalised forces before and after this step.  With the new Q alone the
  // sum gains k (dq)^2 every cycle, a drift that grows with the number of
  // cycles and the modes' vibration and is in no work done on the sheet.
  T ehg = {};
  for (int k = 0; k < 3; ++k)
    ehg += (0.5 * (Qo[k] + Q[k]) * q[0][k] + 0.5 * (Qo[3 + k] + Q[3 + k]) * q[1][k]) * dtp;
  for (int a = 0; a < 8; ++a) {
    const T fc[3] = {0.5 * V * (Dl[0][0] * cx[a] + Dl[0][1] * cy[a] - c * Dl[2][2] * cx[a]),
                     0.5 * V * (Dl[1][0] * cx[a] + Dl[1][1] * cy[a] - c * Dl[2][2] * cy[a]),
                     0.5 * V * (Dl[2][0] * cx[a] + Dl[2][1] * cy[a])};
    T fh[3];
    for (int i = 0; i < 3; ++i) fh[i] = Q[i] * gam[2][a] + Q[3 + i] * gam[3][a];
    T fg[3], hgg[3];
    for (int i = 0; i < 3; ++i) {
      fg[i] = R[i][0] * fc[0] + R[i][1] * fc[1] + R[i][2] * fc[2];
      hgg[i] = R[i][0] * fh[0] + R[i][1] * fh[1] + R[i][2] * fh[2];
    }
    T fa[3];
    for (int i = 0; i < 3; ++i) fa[i] = -(f[a][i] + fg[i] + hgg[i]);
    for (int l = 0; l < W; ++l) {
      const int e = e0 + l;
      double* out = ev.corner + 3 * static_cast<std::size_t>(ev.corner_slot ? ev.corner_slot[8 * e + a] : 8 * e + a);
      for (int i = 0; i < 3; ++i) out[i] = lane(fa[i], l);
    }
  }
  // The stable time step, len / c sqrt(mass factor), on the lanes.
  T mf, smf, len;
  for (int l = 0; l < W; ++l) set_lane(mf, l, ev.mass_factor[e0 + l]);
  lane_sqrt(mf, smf);
  hex_stable_length_t(g.h, len);
  const T dte = len / ev.wave_speed * smf;
  for (int l = 0; l < W; ++l) {
    ev.hg_inc[e0 + l] = lane(ehg, l);
    ev.dt_elem[e0 + l] = lane(dte, l);
  }
  return -1;
}
}  // namespace kernel

int element_range(const ElementView& v, int begin, int end, int width) {
  int inverted = -1;
  auto note = [&](int r) {
    if (r >= 0 && inverted < 0) inverted = r;
  };
  int e = begin;
#ifdef __AVX512F__
  if (width == 8)
    for (; e + 8 <= end; e += 8) note(kernel::element_block<8>(v, e));
#endif
  if (width == 4)
    for (; e + 4 <= end; e += 4) note(kernel::element_block<4>(v, e));
  for (; e < end; ++e) note(kernel::element_block<1>(v, e));
  return inverted;
}

}  // namespace drawbend::fe::DRAWBEND_ISA
