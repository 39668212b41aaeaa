// The element loop of the explicit solver: the hexahedron with two
// integration points through the thickness, for one element or for W elements
// side by side (one per lane, core/lanes.hpp).  Compiled once per instruction
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
// Structure (LULESH): gather -> geometry (in Walsh form, fe/hex8_geometry.hpp)
// and strain rates on fixed-size locals (vector lanes) -> material update (J2
// and combined hardening / Hill'48 / Yld2004-18p on the lanes with masks; other models, and
// W = 1, one point at a time) -> forces on fixed-size locals -> scatter into
// the corner slots (node-major in the solver, so that its nodal sums read in
// order).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/lane_records.hpp"
#include "fe/corner_slots.hpp"
#include "fe/element_view.hpp"
#include "fe/hex8_geometry.hpp"
#include "material/lanes/combined_lanes.hpp"
#include "material/lanes/j2_lanes.hpp"
#include "material/lanes/yld2004_lanes.hpp"

namespace drawbend::fe::DRAWBEND_ISA {

namespace kernel {
// The material updates on the lanes: each model's lane twin, beside its scalar
// law in material/lanes/, compiled here for this instruction set.
using material::lanes::DRAWBEND_ISA::combined_points;
using material::lanes::DRAWBEND_ISA::j2_points;
using material::lanes::DRAWBEND_ISA::yld2004_points;

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

/// Whether hex[l][a] = hex[0][a] + l for every lane l and corner a: each
/// connectivity row as one vector of 8 ints, its difference from row 0 against
/// l, and the mismatches or-ed (no branch per corner).
template <int W>
inline bool nodes_run_on(const std::array<int, 8>* hex) {
  using I8 = int __attribute__((vector_size(32)));
  I8 r0, bad = {};
  std::memcpy(&r0, hex[0].data(), sizeof(I8));
  for (int l = 1; l < W; ++l) {
    I8 rl;
    std::memcpy(&rl, hex[l].data(), sizeof(I8));
    bad |= (rl - r0) ^ l;
  }
  int any = 0;
  for (int a = 0; a < 8; ++a) any |= bad[a];
  return any == 0;
}

/// The mean velocity gradient Ln and the modes' coordinates hxa and local
/// velocities gl (R^T sum_a v_a gamma_alpha,a) from the corner velocities v.
/// Out of line on AVX2, as scatter_forces (DRAWBEND_OUTLINE, fe/hex8_geometry.hpp).
template <class T>
DRAWBEND_OUTLINE void velocity_gradient(const HexWalshT<T>& g, const T v[3][8], T hxa[4][3], T Ln[3][3],
                                        T gl[4][3]) {
  T Vw[3][8];
  for (int i = 0; i < 3; ++i) walsh8_t(v[i], Vw[i]);
  for (int al = 0; al < 4; ++al)
    for (int j = 0; j < 3; ++j) hxa[al][j] = g.X[j][kWalshOfMode[al]];
  // Mean velocity gradient.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T sum = Vw[i][1] * g.G[j][1];
      for (int k = 2; k <= 6; ++k) sum += Vw[i][k] * g.G[j][k];
      Ln[i][j] = sum * g.inv;
    }
  // The modes' velocities, global (gv) and local (R^T gv).
#pragma GCC unroll 4
  for (int al = 0; al < 4; ++al) {
    T gv[3];
    for (int i = 0; i < 3; ++i)
      gv[i] = Vw[i][kWalshOfMode[al]] - (Ln[i][0] * hxa[al][0] + Ln[i][1] * hxa[al][1] + Ln[i][2] * hxa[al][2]);
    for (int i = 0; i < 3; ++i) gl[al][i] = g.R[0][i] * gv[0] + g.R[1][i] * gv[1] + g.R[2][i] * gv[2];
  }
}

/// The corner forces of elements e0 .. e0+W-1 into their slots.  In Walsh
/// form f_a = -(Mf B_a + sum_alpha C_alpha h_alpha,a) = -sum_k h_k(a) F_k,
/// with F_k = inv Mf G_k (k = 1..6) plus C_alpha on the modes' functions
/// (walsh8_back_t).  Out of line on AVX2, as velocity_gradient and
/// hex_walsh_t: GCC then spills less of the block (AVX2 kernel on Zen 1, bar
/// 1,600, one thread: 265 ns with the three out of line, 279 with hex_walsh_t
/// alone, 291 with all inline; moving the points' strains out too: 270).
/// Inlined on AVX-512, which has twice the registers (DRAWBEND_OUTLINE, fe/hex8_geometry.hpp).
template <int W, class T>
DRAWBEND_OUTLINE void scatter_forces(const ElementView& ev, int e0, const HexWalshT<T>& g, const T Mf[3][3],
                                     const T C[4][3]) {
  T Mf_inv[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Mf_inv[i][j] = Mf[i][j] * g.inv;
  T F[3][8], f[3][8];
  for (int i = 0; i < 3; ++i) {
    for (int k = 1; k <= 6; ++k) F[i][k] = Mf_inv[i][0] * g.G[0][k] + Mf_inv[i][1] * g.G[1][k] + Mf_inv[i][2] * g.G[2][k];
    F[i][7] = C[3][i];
    for (int al = 0; al < 3; ++al) F[i][kWalshOfMode[al]] += C[al][i];
    walsh8_back_t(F[i], f[i]);
  }
#pragma GCC unroll 8
  for (int a = 0; a < 8; ++a) {
    const T fa[3] = {-f[0][a], -f[1][a], -f[2][a]};
    double* out[W];
    for (int l = 0; l < W; ++l) {
      const int e = e0 + l;
      out[l] = ev.corner + kCornerStride * static_cast<std::size_t>(ev.corner_slot ? ev.corner_slot[8 * e + a] : 8 * e + a);
    }
    store_slots<W>(out, fa);
  }
}

/// A prefetch hint (RW: 1 for a line to be written) for base[i], in integer
/// arithmetic: a pointer past an array's end, or from a null view in the
/// tests, is never formed.
template <int RW, class P>
__attribute__((always_inline)) inline void hint(const P* base, std::size_t i) {
  __builtin_prefetch(reinterpret_cast<const void*>(reinterpret_cast<std::uintptr_t>(base) + sizeof(P) * i), RW, 3);
}

/// Prefetch hints for the block after this one (elements e0+W .. e0+2W-1)
/// and the node rows two blocks on, where the nodes run on with the lanes
/// (nodes_run_on: corner a of element e0 + l is node hex[e0][a] + l).  Only
/// addresses computed from this block's, no loads: a hint past an array's end
/// is harmless.  Why: a block reads some forty arrays side by side (per-element
/// records, four node rows of six arrays, the corner slots), more streams than
/// the hardware prefetcher follows, so on a model larger than the cache every
/// block waited on memory.  Measured (AVX2 kernel on Zen 1, 1 thread, ns per
/// element-cycle, with and without, two alternations): bar 64,000 342 / 342
/// against 407 / 411, bar 8,000 294 / 302 against 356 / 317, the strip 274 /
/// 276 against 303 / 301, bar 1,600 269 / 275 against 266 / 270 (it fits the
/// L2 cache).  Hints for the next block's corner slots as well (eight
/// scattered lines) changed nothing measurable, so there are none.  Hints
/// change no result: they load nothing into a register.
template <int W>
__attribute__((always_inline)) inline void prefetch_next(const ElementView& ev, int e0) {
  constexpr int kLine = 8;  // doubles per 64-byte line
  const std::size_t n1 = static_cast<std::size_t>(e0 + W);
  for (int k = 0; k < 12 * W; k += kLine) hint<1>(ev.sig, 12 * n1 + k);
  for (int k = 0; k < 6 * W; k += kLine) hint<1>(ev.hgq, 6 * n1 + k);
  for (int k = 0; k < 2 * ev.ns * W; k += kLine) hint<1>(ev.state, 2 * ev.ns * n1 + k);
  hint<1>(ev.hg_ratio, n1 + W);
  hint<1>(ev.ie_inc, n1 + W);
  hint<1>(ev.hg_inc, n1 + W);
  hint<1>(ev.dt_elem, n1 + W);
  hint<0>(ev.sqrt_mass_factor, n1 + W);
  hint<0>(ev.hex, n1 + W);
  for (int a = 0; a < 8; a += 2) {
    const std::size_t n = static_cast<std::size_t>(ev.hex[e0][a]) + 2 * W;
    hint<0>(ev.nodes.x, n);
    hint<0>(ev.nodes.y, n);
    hint<0>(ev.nodes.z, n);
    hint<0>(ev.nodes.vx, n);
    hint<0>(ev.nodes.vy, n);
    hint<0>(ev.nodes.vz, n);
  }
}

// The steps of element_block, in its order, each inlined into it (the block
// is one function to the compiler: the same instructions as when it was
// written out in one piece).
#define DRAWBEND_STEP __attribute__((always_inline)) inline

/// Gather the corners' coordinates and velocities.  Where each corner's nodes
/// run on with the lanes (element e0 + l has node n + l at every corner: a row
/// of a structured block, numbered as mesh.cpp numbers them), each vector is
/// one load of W consecutive values; otherwise one load per lane.  The same
/// values either way.
template <int W, class T>
DRAWBEND_STEP void gather_corners(const ElementView& ev, int e0, T x[8], T y[8], T z[8], T v[3][8]) {
  if (W > 1 && nodes_run_on<W>(ev.hex + e0)) {
    prefetch_next<W>(ev, e0);
    for (int a = 0; a < 8; ++a) {
      const int n = ev.hex[e0][a];
      std::memcpy(&x[a], ev.nodes.x + n, sizeof(T));
      std::memcpy(&y[a], ev.nodes.y + n, sizeof(T));
      std::memcpy(&z[a], ev.nodes.z + n, sizeof(T));
      std::memcpy(&v[0][a], ev.nodes.vx + n, sizeof(T));
      std::memcpy(&v[1][a], ev.nodes.vy + n, sizeof(T));
      std::memcpy(&v[2][a], ev.nodes.vz + n, sizeof(T));
    }
  } else {
    for (int a = 0; a < 8; ++a) {
      int n[W];
      for (int l = 0; l < W; ++l) n[l] = ev.hex[e0 + l][a];
      from_lanes(x[a], [&](int l) { return ev.nodes.x[n[l]]; });
      from_lanes(y[a], [&](int l) { return ev.nodes.y[n[l]]; });
      from_lanes(z[a], [&](int l) { return ev.nodes.z[n[l]]; });
      from_lanes(v[0][a], [&](int l) { return ev.nodes.vx[n[l]]; });
      from_lanes(v[1][a], [&](int l) { return ev.nodes.vy[n[l]]; });
      from_lanes(v[2][a], [&](int l) { return ev.nodes.vz[n[l]]; });
    }
  }
}

/// The thickness-linear gradient LC (global) from the modes' local velocities
/// gl, with the points' zeta folded in (zi8h = zeta / 8h): locally
/// LCl_i0 = zeta sum_a vl_a,i gamma_zx,a / 8h_x, LCl_i1 likewise with
/// gamma_yz / 8h_y, LCl_22 = -c (LCl_00 + LCl_11) (the assumed thickness
/// strain), and LC = R LCl R^T.
template <class T>
DRAWBEND_STEP void thickness_gradient(const T (*R)[3], const T gl[4][3], const T zi8h[2], const T& c, T LC[3][3]) {
  T LCl[3][2];
  for (int i = 0; i < 3; ++i) {
    LCl[i][0] = gl[1][i] * zi8h[0];
    LCl[i][1] = gl[0][i] * zi8h[1];
  }
  const T LCl22 = -c * (LCl[0][0] + LCl[1][1]);
  // LC = R LCl R^T, with LCl's third column (0, 0, LCl22).
  T RL[3][3];
  for (int i = 0; i < 3; ++i) {
    RL[i][0] = R[i][0] * LCl[0][0] + R[i][1] * LCl[1][0] + R[i][2] * LCl[2][0];
    RL[i][1] = R[i][0] * LCl[0][1] + R[i][1] * LCl[1][1] + R[i][2] * LCl[2][1];
    RL[i][2] = R[i][2] * LCl22;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) LC[i][j] = RL[i][0] * R[j][0] + RL[i][1] * R[j][1] + RL[i][2] * R[j][2];
}

/// The two integration points' stresses s (read from ev.sig) turned by the
/// Jaumann rotation, their strain increments deps and spins, from the
/// mid-interval gradient L_mid = L (I - dt/2 L_mean)^-1 (exact for rigid
/// rotation) at zeta = +-1/sqrt3: (L_mean +- zeta L_C) M^-1.
template <class T>
DRAWBEND_STEP void point_rates(const ElementView& ev, int e0, const T Ln[3][3], const T LC[3][3], T s[2][6],
                               T deps[2][6], T spin[2][3]) {
  const double dtp = ev.dtp;
  T M[3][3], Mi[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M[i][j] = (i == j ? 1.0 : 0.0) - 0.5 * dtp * Ln[i][j];
  inverse3(M, Mi);
  load_records<12>(ev.sig + 12 * static_cast<std::size_t>(e0), &s[0][0]);
  // L_mid at zeta = +-1/sqrt3: (L_mean +- zeta L_C) M^-1 = L_mean M^-1 +- zeta (L_C M^-1).
  T LnM[3][3], LCM[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      LnM[i][j] = Ln[i][0] * Mi[0][j] + Ln[i][1] * Mi[1][j] + Ln[i][2] * Mi[2][j];
      LCM[i][j] = LC[i][0] * Mi[0][j] + LC[i][1] * Mi[1][j] + LC[i][2] * Mi[2][j];
    }
  for (int gp = 0; gp < 2; ++gp) {
    T Lmid[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Lmid[i][j] = gp == 0 ? LnM[i][j] + LCM[i][j] : LnM[i][j] - LCM[i][j];
    rotate_and_strain(Lmid, dtp, s[gp], deps[gp], spin[gp]);
  }
}

/// The material update of the two points, with the stress power increment per
/// unit volume by the midpoint rule (ev.ie_inc) and the tangent ratio; the new
/// stresses in snew.  J2, CombinedPlasticity and Yld2004Plasticity on the
/// lanes, branch-free (material/lanes/j2_lanes.hpp, combined_lanes.hpp,
/// yld2004_lanes.hpp); other materials one point at a time (each turns its own
/// history with the point's spin), their stresses then read back from ev.sig.
template <int W, class T>
DRAWBEND_STEP void material_points(const ElementView& ev, int e0, const T s[2][6], const T deps[2][6], const T spin[2][3], const T& V,
                                   T& ratio, T snew[2][6]) {
  const double dtp = ev.dtp;
  const material::Material& mat = *ev.mat;
  const std::uint64_t tick0 = ev.material_ticks ? ticks() : 0;
  bool on_lanes = false;
  if constexpr (W > 1) {
    if (ev.j2_lanes) {
      j2_points<W>(ev, e0, s, deps, V, ratio, snew);
      on_lanes = true;
    } else if (ev.combined_lanes) {
      combined_points<W>(ev, e0, s, deps, spin, V, ratio, snew);
      on_lanes = true;
    } else if (ev.yld2004_lanes) {
#if defined(__AVX__)
      yld2004_points<W>(ev, e0, s, deps, spin, V, ratio, snew);
      on_lanes = true;
#endif
      // The baseline kernel (SSE2: four lanes in two halves) keeps Yld2004-18p on the scalar path: its
      // lanes cost 1.3 times the scalar path there (38.4 against 28.2-29.8 CPU s on bench_solver's
      // yld2004 bar, docs/performance-log.md); on AVX2 and AVX-512 they cost a third of it.
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
  if (!on_lanes) load_records<12>(ev.sig + 12 * static_cast<std::size_t>(e0), &snew[0][0]);
}

/// The remaining hourglass modes (xi*eta, xi*eta*zeta): their generalised
/// forces Q (ev.hgq) advanced corotationally from the modes' local velocities
/// q, with the physical stiffness of the elastic moduli, and their energy
/// increment ehg.  They keep the elastic modulus: bending is carried by the
/// integration points, and a stiffness that followed yielding would pump
/// energy into these modes as material streams through a bend (elastic ->
/// plastic -> elastic), which a draw-bend strip does.
template <class T>
DRAWBEND_STEP void hourglass_modes(const ElementView& ev, int e0, const HexWalshT<T>& g, const T& V, const T gl[4][3],
                                   T Q[6], T& ehg) {
  const double dtp = ev.dtp;
  const double Er = ev.E0;
  const T ih2[3] = {1.0 / (g.h[0] * g.h[0]), 1.0 / (g.h[1] * g.h[1]), 1.0 / (g.h[2] * g.h[2])};
  const T* q[2] = {gl[2], gl[3]};  // the modes' local velocities
  T Qo[6];  // Q: [mode xi*eta: 3][mode xi*eta*zeta: 3], now; Qo: before this step
  load_records<6>(ev.hgq + 6 * static_cast<std::size_t>(e0), Q);
  for (int k = 0; k < 6; ++k) Qo[k] = Q[k];
  const T kq = (dtp * ev.hourglass / 64.0) * V;
  for (int i = 0; i < 3; ++i) {
    const T K2 = i < 2 ? (Er / 3.0) * ih2[i] : (ev.G0 / 3.0) * (ih2[0] + ih2[1]);
    const T K3 = (Er / 9.0) * ih2[i];
    Q[i] += kq * K2 * q[0][i];
    Q[3 + i] += kq * K3 * q[1][i];
  }
  store_records<6>(ev.hgq + 6 * static_cast<std::size_t>(e0), Q);
  // Hourglass energy by the midpoint rule, as the stress power:
  // sum_a (R fh_a) . v_a = sum_a fh_a . vl_a = Q . q, with the mean of the
  // generalised forces before and after this step.  With the new Q alone the
  // sum gains k (dq)^2 every cycle, a drift that grows with the number of
  // cycles and the modes' vibration and is in no work done on the sheet.
  ehg = T{};
  for (int k = 0; k < 3; ++k)
    ehg += (0.5 * (Qo[k] + Q[k]) * q[0][k] + 0.5 * (Qo[3 + k] + Q[3 + k]) * q[1][k]) * dtp;
}

/// The modes' global force vectors C and the mean-stress matrix Mf of the
/// internal forces f_a = -(V sigma_mean B_a + sum_alpha C_alpha gamma_alpha,a)
/// from the points' new stresses sp, sm (at zeta = +1/sqrt3, -1/sqrt3):
///  - thickness-linear part (V/2) Dl : LCl(v), Dl = R^T (sig+ - sig-)/sqrt3 R
///    (symmetric), on the modes zeta*xi (C_1) and eta*zeta (C_0);
///  - the hourglass forces R Q on the modes xi*eta (C_2) and xi*eta*zeta (C_3).
/// With gamma_alpha,a = h_alpha,a - hx_alpha . B_a, f_a = -(Mf B_a + sum_alpha C_alpha h_alpha,a),
/// Mf = V sigma_mean - sum_alpha C_alpha (x) hx_alpha.
template <class T>
DRAWBEND_STEP void mode_forces(const T (*R)[3], const T& V, const T* sp, const T* sm, const T Q[6], const T hxa[4][3],
                               const T zi8h[2], const T& c, T Mf[3][3], T C[4][3]) {
  T dg[6];
  for (int k = 0; k < 6; ++k) dg[k] = sp[k] - sm[k];  // the 1/sqrt3 goes into kx, ky below
  const T DG[3][3] = {{dg[0], dg[3], dg[5]}, {dg[3], dg[1], dg[4]}, {dg[5], dg[4], dg[2]}};
  T GR[3][3];  // dg R
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) GR[i][j] = DG[i][0] * R[0][j] + DG[i][1] * R[1][j] + DG[i][2] * R[2][j];
  constexpr int kDi[6] = {0, 0, 1, 0, 1, 2}, kDj[6] = {0, 1, 1, 2, 2, 2};  // Dl's upper triangle
  T Dl[6];  // R^T dg R: 00, 01, 11, 02, 12, 22
  for (int k = 0; k < 6; ++k) {
    const int i = kDi[k], j = kDj[k];
    Dl[k] = R[0][i] * GR[0][j] + R[1][i] * GR[1][j] + R[2][i] * GR[2][j];
  }
  const T &Dl00 = Dl[0], &Dl01 = Dl[1], &Dl11 = Dl[2], &Dl02 = Dl[3], &Dl12 = Dl[4], &Dl22 = Dl[5];
  const T hv = 0.5 * V;
  const T kx = hv * zi8h[0], ky = hv * zi8h[1];
  // Local force vectors of the modes zeta*xi (on gamma_1 / 8h_x) and eta*zeta (gamma_0 / 8h_y).
  const T K1[3] = {kx * (Dl00 - c * Dl22), kx * Dl01, kx * Dl02};
  const T K0[3] = {ky * Dl01, ky * (Dl11 - c * Dl22), ky * Dl12};
  for (int i = 0; i < 3; ++i) {
    C[0][i] = R[i][0] * K0[0] + R[i][1] * K0[1] + R[i][2] * K0[2];
    C[1][i] = R[i][0] * K1[0] + R[i][1] * K1[1] + R[i][2] * K1[2];
    C[2][i] = R[i][0] * Q[0] + R[i][1] * Q[1] + R[i][2] * Q[2];
    C[3][i] = R[i][0] * Q[3] + R[i][1] * Q[4] + R[i][2] * Q[5];
  }
  T smean[6];
  for (int k = 0; k < 6; ++k) smean[k] = 0.5 * (sp[k] + sm[k]);
  const T SM[3][3] = {{smean[0], smean[3], smean[5]}, {smean[3], smean[1], smean[4]}, {smean[5], smean[4], smean[2]}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      Mf[i][j] = V * SM[i][j] - (C[0][i] * hxa[0][j] + C[1][i] * hxa[1][j] + C[2][i] * hxa[2][j] + C[3][i] * hxa[3][j]);
}

/// The element's stable time step, len / c sqrt(mass factor), on the lanes.
template <class T>
DRAWBEND_STEP void stable_time_step(const ElementView& ev, int e0, const HexWalshT<T>& g, T& dte) {
  T smf, len;
  load_records<1>(ev.sqrt_mass_factor + e0, &smf);
  hex_stable_length_t(g.h, len);
  dte = len / ev.wave_speed * smf;
}

/// Elements e0 .. e0+W-1: gather, geometry, the points' strain rates, the
/// material, the hourglass modes, the forces into the corner slots and the
/// stable time step (the steps above).  Returns the lowest inverted one, or -1.
template <int W>
int element_block(const ElementView& ev, int e0) {
  using T = typename Lanes<W>::type;
  T x[8], y[8], z[8], v[3][8];
  gather_corners<W>(ev, e0, x, y, z, v);
  HexWalshT<T> g;
  if (!hex_walsh_t(x, y, z, g)) {
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
  // Everything runs on Walsh sums (fe/hex8_geometry.hpp): with the
  // velocities' sums Vw_k = sum_a h_k(a) v_a and B_a = inv sum_k h_k(a) G_k,
  //   L_mean = sum_a v_a (x) B_a = inv sum_{k=1..6} Vw_k (x) G_k,
  // and the hourglass vectors gamma_alpha,a = h_alpha,a - (h_alpha . x) . B_a
  // are never formed (Flanagan & Belytschko 1981): a mode's velocity is
  //   sum_a v_a gamma_alpha,a = Vw_alpha - L_mean hx_alpha,
  // with the mode's coordinates hx_alpha = sum_b h_alpha,b x_b = X_alpha.
  T hxa[4][3], Ln[3][3], gl[4][3];
  velocity_gradient(g, v, hxa, Ln, gl);
  // The thickness-linear gradient, its thickness strain blended between
  // elastic (c_elastic) and isochoric (1) by the relaxed tangent ratio rbar.
  const T i8h[2] = {0.125 / g.h[0], 0.125 / g.h[1]};
  const T zi8h[2] = {kZg * i8h[0], kZg * i8h[1]};
  T rbar;
  load_records<1>(ev.hg_ratio + e0, &rbar);
  const T c = rbar * ev.c_elastic + (1.0 - rbar);
  T LC[3][3];
  thickness_gradient(g.R, gl, zi8h, c, LC);
  T s[2][6], deps[2][6], spin[2][3];
  point_rates(ev, e0, Ln, LC, s, deps, spin);
  T ratio, snew[2][6];
  material_points<W>(ev, e0, s, deps, spin, V, ratio, snew);
  const T rnew = rbar + kRelax * (ratio - rbar);
  store_records<1>(ev.hg_ratio + e0, &rnew);
  T Q[6], ehg;
  hourglass_modes(ev, e0, g, V, gl, Q, ehg);
  T Mf[3][3], C[4][3];
  mode_forces(g.R, V, snew[0], snew[1], Q, hxa, zi8h, c, Mf, C);
  scatter_forces<W>(ev, e0, g, Mf, C);
  T dte;
  stable_time_step(ev, e0, g, dte);
  store_records<1>(ev.hg_inc + e0, &ehg);
  store_records<1>(ev.dt_elem + e0, &dte);
  return -1;
}
#undef DRAWBEND_STEP
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
