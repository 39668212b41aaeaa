#pragma once
// Combined isotropic-kinematic hardening with a von Mises or Hill'48 yield
// function (material/combined_plasticity.cpp) on W elements side by side, for
// the element kernel (fe/element_kernel.hpp): CombinedPlasticity::update() and
// tangent_ratio() with the same arithmetic in the same order on vector lanes,
// so that every lane gives the scalar bits (tests/unit/test_element_kernel.cpp
// compares every output).
//
// Branch-free across lanes: a point is elastic or plastic by a mask, both
// results are computed and the mask selects one (a bitwise select: a NaN or
// infinity in the unused branch never leaks).  The return mapping iterates on
// dl, first doubling the bracket while the residual is positive, then the
// Illinois secant until a tolerance; on the lanes each loop runs until every
// lane has left it, a lane that has left it (or never entered) is masked, and
// the iteration count is the scalar one for each lane.  The back stresses and
// the sheet axes turn with the point's spin as in the scalar code, elastic
// points included.  Curve look-ups are per lane (material/lanes/j2_lanes.hpp).
//
// Compiled once per instruction set, in its namespace (as element_kernel.hpp):
// nothing here may be an inline function shared with other translation units.
#include <cstddef>

#include "core/lanes.hpp"
#include "material/lanes/hill48_lanes.hpp"
#include "material/lanes/j2_lanes.hpp"
#include "material/lanes/points_view.hpp"

namespace drawbend::material::lanes::DRAWBEND_ISA {

using CombinedParams = CombinedPlasticity::LaneParams;

/// One point's state of W elements: [eps_p, alpha_1 .. alpha_nback (6 each),
/// RD (3), ND (3)] (the axes only for Hill'48).
template <class T>
struct CombinedState {
  T ep, back[3][6], rd[3], nd[3];
};

/// The state of point gp of elements e0 .. e0+W-1, from (to_state false) or
/// to (true) ev.state.
template <int W, bool to_state, class T, class View>
inline void move_state(const View& ev, int e0, int gp, CombinedState<T>& st) {
  const CombinedParams& P = ev.combined;
  double* p[W];
  for (int l = 0; l < W; ++l) p[l] = ev.state + (2 * static_cast<std::size_t>(e0 + l) + gp) * ev.ns;
  auto move = [&](T& v, int i) {
    if constexpr (to_state) {
      for (int l = 0; l < W; ++l) p[l][i] = lane(v, l);
    } else {
      from_lanes(v, [&](int l) { return p[l][i]; });
    }
  };
  move(st.ep, 0);
  for (int k = 0; k < P.nback; ++k)
    for (int c = 0; c < 6; ++c) move(st.back[k][c], 1 + 6 * k + c);
  if (P.aniso)
    for (int i = 0; i < 3; ++i) {
      move(st.rd[i], 1 + 6 * P.nback + i);
      move(st.nd[i], 4 + 6 * P.nback + i);
    }
}

/// R = isotropic_stress(ep) from s = the curve's stress at ep.
template <class T>
inline void isotropic_from_curve(const CombinedParams& P, const T& s, T& R) {
  R = P.beta > 0 ? P.s0 + (1.0 - P.beta) * (s - P.s0) : s;
}

/// The residual lambda of update(): f = (sigma_bar(xi(dl)) - R(ep + dl)) (1 +
/// kappa (F + G + H)), with xi and R; ts: the trial stress, an: the back
/// stresses (sheet axes); seg: the curve segments of a nearby strain, on
/// return those of ep + dl (curve_at_near: the values of curve_at).
template <int W, class T>
inline void combined_residual(const CombinedParams& P, const T ts[6], const T an[3][6], const T& ep, const T& s_ep,
                              const T& dl, LaneSegments<W, T>& seg, T xi[6], T& R, T& f) {
  T kin = {}, s_dl, h;
  T xstar[6] = {ts[0], ts[1], ts[2], ts[3], ts[4], ts[5]};
  curve_at_near<W>(P.curve, ep + dl, seg, s_dl, h);
  if (P.beta > 0) {
    for (int c = 0; c < 6; ++c) xstar[c] -= an[0][c];
    kin = P.beta * (s_dl - s_ep);
  } else {
    for (int k = 0; k < P.nback; ++k) {
      const T a = 1.0 / (1.0 + P.gamma[k] * dl);
      for (int c = 0; c < 6; ++c) xstar[c] -= a * an[k][c];
      kin += a * P.C[k] * dl;
    }
  }
  isotropic_from_curve(P, s_dl, R);
  const T kappa = (2.0 * P.G * dl + (2.0 / 3.0) * kin) / R;
  hill_solve_relative(P.hill, kappa, xstar, xi);
  T q;
  hill_equivalent(P.hill, xi, q);
  const double c_lin = P.hill.F + P.hill.G + P.hill.H;  // update() says why
  f = (q - R) * (1.0 + kappa * c_lin);
}

/// dl of the plastic lanes: the bracket, then the Illinois secant, as update();
/// xa and Ra: xi and R at each lane's dl (the residual's last evaluation
/// there, kept by mask as a lane leaves the loop, so that nothing is
/// evaluated again; update() keeps its last evaluation too).  seg: in, the
/// segments of ep; out, those of the last strain evaluated (each evaluation
/// searches from the one before: the iterates close in on the root).
template <int W, class T, class M>
inline void combined_return(const CombinedParams& P, const T ts[6], const T an[3][6], const T& ep, const T& s_ep,
                            const T& f0, const M& plastic, LaneSegments<W, T>& seg, T& dl, T xa[6], T& Ra) {
  T xi[6], R, lo = {}, flo = f0, hi = f0 / (3.0 * P.G), fhi;
  combined_residual<W>(P, ts, an, ep, s_ep, hi, seg, xi, R, fhi);
  M active = plastic & (fhi > 0.0);
  for (int it = 0; it < 200 && any_lane<W>(active); ++it) {
    lo = active ? hi : lo;
    flo = active ? fhi : flo;
    hi = active ? hi * 2.0 : hi;
    T fn;
    combined_residual<W>(P, ts, an, ep, s_ep, hi, seg, xi, R, fn);
    fhi = active ? fn : fhi;
    active = active & (fhi > 0.0);
  }
  dl = hi;  // every lane's xi and R are at its hi: a lane out of the bracket loop kept its hi
  for (int c = 0; c < 6; ++c) xa[c] = xi[c];
  Ra = R;
  active = plastic & (fhi != 0.0);
  const T one = T{} + 1.0, minus_one = T{} - 1.0;
  T side = {};
  for (int it = 0; it < 200 && any_lane<W>(active); ++it) {
    T x = hi - fhi * (hi - lo) / (fhi - flo);
    x = ((x > lo) & (x < hi)) ? x : 0.5 * (lo + hi);
    T fx;
    combined_residual<W>(P, ts, an, ep, s_ep, x, seg, xi, R, fx);
    dl = active ? x : dl;
    for (int c = 0; c < 6; ++c) xa[c] = active ? xi[c] : xa[c];
    Ra = active ? R : Ra;
    const T tol = 1e-13 * R;  // |fx| <= tol as two comparisons (the same for every fx, NaN included)
    const M done = (fx == 0.0) | ((fx <= tol) & (-fx <= tol)) | (hi - lo <= 1e-15 * hi);
    const M go = active & ~done;
    const M pos = go & (fx > 0.0), neg = go & ~(fx > 0.0);
    fhi = (pos & (side == 1.0)) ? fhi * 0.5 : fhi;
    flo = (neg & (side == -1.0)) ? flo * 0.5 : flo;
    lo = pos ? x : lo;
    flo = pos ? fx : flo;
    hi = neg ? x : hi;
    fhi = neg ? fx : fhi;
    side = pos ? one : (neg ? minus_one : side);
    active = go;
  }
}

/// CombinedPlasticity::update() of one point of W elements: s (in: the
/// rotated stress) and st updated in place; Q: the sheet axes (Hill'48).
/// `turn`: the spin w over dt rotates the back stresses and axes.  seg: out,
/// curve segments of strains near the new plastic strains (a hint for
/// combined_tangent_ratio).
template <int W, class T>
inline void combined_update(const CombinedParams& P, const T d[6], const T w[3], double dt, bool turn, T s[6],
                            CombinedState<T>& st, T Q[3][3], LaneSegments<W, T>& seg) {
  using M = decltype(T{} < T{});
  const int nb = P.nback;
  if (turn)
    for (int k = 0; k < nb; ++k) material::rotate_symmetric(w[0], w[1], w[2], dt, st.back[k]);
  if (P.aniso) sheet_frame(w, dt, turn, st.rd, st.nd, Q);
  // Elastic trial stress (IsotropicElasticity::add_elastic), in the sheet axes.
  const T lt = P.lambda * (d[0] + d[1] + d[2]);
  const double g2 = 2.0 * P.G;
  T tr[6];
  for (int c = 0; c < 3; ++c) tr[c] = s[c] + (lt + g2 * d[c]);
  for (int c = 3; c < 6; ++c) tr[c] = s[c] + P.G * d[c];
  T ts[6], an[3][6];
  if (P.aniso) {
    sheet_transform<true>(Q, tr, ts);
    for (int k = 0; k < nb; ++k) sheet_transform<true>(Q, st.back[k], an[k]);
  } else {
    for (int c = 0; c < 6; ++c) ts[c] = tr[c];
    for (int k = 0; k < nb; ++k)
      for (int c = 0; c < 6; ++c) an[k][c] = st.back[k][c];
  }
  T xs[6];
  for (int c = 0; c < 6; ++c) {
    xs[c] = ts[c];
    for (int k = 0; k < nb; ++k) xs[c] -= an[k][c];
  }
  T s_ep, h, R0, q0;
  find_segments<W>(P.curve, st.ep, seg);
  curve_value(seg, st.ep, s_ep, h);  // curve_at, keeping ep's segments
  isotropic_from_curve(P, s_ep, R0);
  hill_equivalent(P.hill, xs, q0);
  const T f0 = q0 - R0;
  const M plastic = f0 > 0.0;
  if (!any_lane<W>(plastic)) {
    for (int c = 0; c < 6; ++c) s[c] = tr[c];
    return;
  }
  T dl, xi[6], Rv;
  combined_return<W>(P, ts, an, st.ep, s_ep, f0, plastic, seg, dl, xi, Rv);  // with xi and R at the accepted dl
  // Back stresses from the flow direction T M xi / R, and the stress.
  const double F = P.hill.F, G = P.hill.G, H = P.hill.H;
  const T n[6] = {((G + H) * xi[0] - H * xi[1] - G * xi[2]) / Rv,
                  (-H * xi[0] + (F + H) * xi[1] - F * xi[2]) / Rv,
                  (-G * xi[0] - F * xi[1] + (F + G) * xi[2]) / Rv,
                  P.hill.N * xi[3] / Rv,
                  P.hill.L * xi[4] / Rv,
                  P.hill.M * xi[5] / Rv};
  T sl[6] = {xi[0], xi[1], xi[2], xi[3], xi[4], xi[5]};
  T s_dl = s_ep;
  if (P.beta > 0) curve_at_near<W>(P.curve, st.ep + dl, seg, s_dl, h);
  for (int k = 0; k < nb; ++k) {
    T a, incr;
    if (P.beta > 0) {
      a = T{} + 1.0;
      incr = (2.0 / 3.0) * P.beta * (s_dl - s_ep);
    } else {
      a = 1.0 / (1.0 + P.gamma[k] * dl);
      incr = (2.0 / 3.0) * P.C[k] * dl;
    }
    for (int c = 0; c < 6; ++c) {
      an[k][c] = a * (an[k][c] + incr * n[c]);
      sl[c] += an[k][c];
    }
  }
  T sg[6], bg[3][6];
  if (P.aniso) {
    sheet_transform<false>(Q, sl, sg);
    for (int k = 0; k < nb; ++k) sheet_transform<false>(Q, an[k], bg[k]);
  } else {
    for (int c = 0; c < 6; ++c) sg[c] = sl[c];
    for (int k = 0; k < nb; ++k)
      for (int c = 0; c < 6; ++c) bg[k][c] = an[k][c];
  }
  for (int c = 0; c < 6; ++c) s[c] = plastic ? sg[c] : tr[c];
  for (int k = 0; k < nb; ++k)
    for (int c = 0; c < 6; ++c) st.back[k][c] = plastic ? bg[k][c] : st.back[k][c];
  st.ep = plastic ? st.ep + dl : st.ep;
}

/// ratio = CombinedPlasticity::tangent_ratio() of W points (stress s, state
/// st, sheet axes Q after the update); seg: curve segments of nearby strains
/// (combined_update's), used up.
template <int W, class T>
inline void combined_tangent_ratio(const CombinedParams& P, const T s[6], const CombinedState<T>& st, const T Q[3][3],
                                   LaneSegments<W, T>& seg, T& ratio) {
  T xi[6];
  for (int c = 0; c < 6; ++c) {
    T alpha = {};
    for (int k = 0; k < P.nback; ++k) alpha += st.back[k][c];
    xi[c] = s[c] - alpha;
  }
  if (P.aniso) {
    T l[6];
    sheet_transform<true>(Q, xi, l);
    for (int c = 0; c < 6; ++c) xi[c] = l[c];
  }
  // Monotonic uniaxial tangent: the curve's slope plus each Chaboche C exp(-gamma eps_p),
  // the exponentials lane by lane and only in the lanes that use them (f above
  // 0.90, or NaN): proximity_ratio selects 1 where f <= 0.90 whatever H is.
  T sy, H, R, q;
  curve_at_near<W>(P.curve, st.ep, seg, sy, H);
  isotropic_from_curve(P, sy, R);
  hill_equivalent(P.hill, xi, q);
  const T f = q / R;
  add_chaboche_tangent<W>(P.nterms, P.C, P.gamma, st.ep, f, H);
  proximity_ratio(f, H, P.E, ratio);
}

/// The material section of element_block<W> for CombinedPlasticity
/// (lane_points): states from and to ev.state, each point turned with its
/// spin (spin[gp]) when the material uses it.
template <int W, class T, class View>
inline void combined_points(const View& ev, int e0, const T s[2][6], const T deps[2][6], const T spin[2][3],
                            const T& V, T& ratio, T snew[2][6]) {
  const bool turn = ev.spin && ev.dtp != 0.0;
  CombinedState<T> st[2];
  T Q[2][3][3];
  LaneSegments<W, T> seg[2];
  lane_points<W>(
      ev, e0, s, deps, V, ratio, snew,
      [&](int gp, T* sn) {
        move_state<W, false>(ev, e0, gp, st[gp]);
        combined_update<W>(ev.combined, deps[gp], spin[gp], ev.dtp, turn, sn, st[gp], Q[gp], seg[gp]);
        move_state<W, true>(ev, e0, gp, st[gp]);
      },
      [&](int gp, const T* sn, T& r) { combined_tangent_ratio<W>(ev.combined, sn, st[gp], Q[gp], seg[gp], r); });
}

}  // namespace drawbend::material::lanes::DRAWBEND_ISA
