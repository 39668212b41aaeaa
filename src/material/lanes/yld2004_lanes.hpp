#pragma once
// Yld2004-18p plasticity with combined hardening (material/yld2004_plasticity.cpp)
// on W elements side by side, for the element kernel (fe/element_kernel.hpp):
// Yld2004Plasticity::update() and tangent_ratio() with the same arithmetic in
// the same order on vector lanes (the yield function: yld2004_function_lanes.hpp),
// so that every lane gives the scalar bits (tests/unit/test_yld2004_lanes.cpp
// compares every output on random and degenerate strain paths).
//
// Branch-free across lanes: a point is elastic or plastic by a mask, both
// results are computed and the mask selects one.  The return map iterates on
// the normal (update()'s backward Euler); on the lanes the loop runs until
// every plastic lane has converged or failed, a lane that has left it is
// masked, and each lane's iteration count is the scalar one.  A lane whose
// return on the whole increment fails (60 iterations, a non-finite residual
// or denominator: update() then splits the increment) is handed, with its
// stress and state as they came in, to Yld2004Plasticity::update() itself,
// which does the same first return again and goes on to the sub-increments and
// the fallback: the same bits, with the scalar code's own counters.  Elsewhere
// the lanes count their plastic updates (count_lane_returns), so that a run's
// plastic_updates, split_updates and fallback_updates are the scalar ones.
// The back stresses and the sheet axes turn with the point's spin as in the
// scalar code, elastic points included.  Curve look-ups are per lane
// (material/lanes/j2_lanes.hpp).
//
// Compiled once per instruction set, in its namespace (as element_kernel.hpp):
// nothing here may be an inline function shared with other translation units.
#include <cstddef>

#include "core/lanes.hpp"
#include "material/lanes/hill48_lanes.hpp"
#include "material/lanes/j2_lanes.hpp"
#include "material/lanes/points_view.hpp"
#include "material/lanes/yld2004_function_lanes.hpp"

namespace drawbend::material::lanes::DRAWBEND_ISA {

/// One point's state of W elements: [eps_p, alpha_1 .. alpha_nback (6 each), RD (3), ND (3)].
template <class T>
struct YldState {
  T ep, back[3][6], rd[3], nd[3];
};

/// The state of point gp of elements e0 .. e0+W-1, from ev.state (to_state
/// false) or to it (true; only the lanes with keep[l]).
template <int W, bool to_state, class T, class View>
inline void yld_move_state(const View& ev, int e0, int gp, YldState<T>& st, const bool* keep = nullptr) {
  const YldParams& P = ev.yld2004;
  double* p[W];
  for (int l = 0; l < W; ++l) p[l] = ev.state + (2 * static_cast<std::size_t>(e0 + l) + gp) * ev.ns;
  auto move = [&](T& v, int i) {
    if constexpr (to_state) {
      for (int l = 0; l < W; ++l)
        if (keep[l]) p[l][i] = lane(v, l);
    } else {
      from_lanes(v, [&](int l) { return p[l][i]; });
    }
  };
  move(st.ep, 0);
  for (int k = 0; k < P.nback; ++k)
    for (int c = 0; c < 6; ++c) move(st.back[k][c], 1 + 6 * k + c);
  for (int i = 0; i < 3; ++i) {
    move(st.rd[i], 1 + 6 * P.nback + i);
    move(st.nd[i], 4 + 6 * P.nback + i);
  }
}

/// r = contract(a, b): a : b with tensor shears.
template <class T>
inline void yld_contract(const T a[6], const T b[6], T& r) {
  r = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

/// R = isotropic_stress from the curve's stress s.
template <class T>
inline void yld_isotropic(const YldParams& P, const T& s, T& R) {
  R = P.beta > 0 ? P.s0 + (1.0 - P.beta) * (s - P.s0) : s;
}

/// kinematic_rate(n, an, ep, dl, out): the back stresses for dl and n, and n : d alpha / d dl.
/// seg: the curve segments of a nearby strain (split form only).
template <int W, class T>
inline void yld_kinematic_rate(const YldParams& P, const T n[6], const T an[3][6], const T& ep, const T& dl,
                               LaneSegments<W, T>& seg, T out[3][6], T& rate) {
  rate = T{};
  if (P.beta > 0) {
    T s1, s0, h1, h0;
    curve_at_near<W>(P.curve, ep + dl, seg, s1, h1);
    curve_at_near<W>(P.curve, ep, seg, s0, h0);
    const T ds = s1 - s0;
    for (int c = 0; c < 6; ++c) out[0][c] = an[0][c] + (2.0 / 3.0) * P.beta * ds * n[c];
    T nn;
    yld_contract(n, n, nn);
    rate = (2.0 / 3.0) * P.beta * h1 * nn;
  } else {
    for (int k = 0; k < P.nback; ++k) {
      const double C = P.C[k], g = P.gamma[k];
      const T a = 1.0 / (1.0 + g * dl);
      for (int c = 0; c < 6; ++c) out[k][c] = a * (an[k][c] + (2.0 / 3.0) * C * dl * n[c]);
      T nn, na;
      yld_contract(n, n, nn);
      yld_contract(n, out[k], na);
      rate += (2.0 / 3.0) * C * nn - g * na;
    }
  }
}

/// return_map() on the whole increment (dl = 0 before it) of the lanes in
/// `plastic`: ts and an (sheet axes) become the returned stress and back
/// stresses and x the multiplier where a lane converged (`done`); `failed`:
/// the plastic lanes that did not.
template <int W, class T, class M>
inline void yld_return(const YldParams& P, T ts[6], T an[3][6], const T& ep, const T& sb0, const T n_trial[6],
                       const M& plastic, LaneSegments<W, T>& seg, T& xdone, M& done, M& failed) {
  constexpr int kMaxIter = 60;
  constexpr double kTol = 1e-6;
  const double G2 = 2.0 * P.G;
  const T epd = ep + 0.0;  // ep + dl, dl = 0
  T n[6], nn[6], sg[6] = {}, ac[3][6], sb = sb0;
  for (int c = 0; c < 6; ++c) nn[c] = n_trial[c];
  T x = {};
  T kin;
  yld_kinematic_rate<W>(P, nn, an, epd, T{}, seg, ac, kin);
  for (int c = 0; c < 6; ++c) n[c] = nn[c];
  M active = plastic;
  done = plastic & ~plastic;
  failed = done;
  const double hfac = P.beta > 0 ? 1.0 - P.beta : 1.0;
  for (int it = 0; it < kMaxIter && any_set(active); ++it) {
    T sR, hR;
    curve_at_near<W>(P.curve, epd + x, seg, sR, hR);
    T R;
    yld_isotropic(P, sR, R);
    const T f = sb - R;
    const M bad_f = active & ~((f - f) == 0.0);  // !isfinite(f)
    T dn = {};
    for (int c = 0; c < 6; ++c) lane_max_abs(dn, nn[c] - n[c]);
    T fa;
    lane_abs(f, fa);
    M conv = active & ~bad_f & (fa <= kTol * R) & (G2 * x * dn <= kTol * R);
    if (it == 0) conv = conv & ~conv;
    for (int c = 0; c < 6; ++c) {
      ts[c] = conv ? sg[c] : ts[c];
      for (int k = 0; k < P.nback; ++k) an[k][c] = conv ? ac[k][c] : an[k][c];
    }
    xdone = conv ? x : xdone;
    done |= conv;
    failed |= bad_f;
    active = active & ~bad_f & ~conv;
    if (!any_set(active)) break;
    const T hiso = hfac * hR;  // slope(ep + dl + x): the segment of R's strain
    T nn2;
    yld_contract(nn, nn, nn2);
    const T denom = G2 * nn2 + hiso + kin;
    const M bad_d = active & ~((denom > 0.0) & ((denom - denom) == 0.0));
    failed |= bad_d;
    active = active & ~bad_d;
    const T xn = x + f / denom;
    x = active ? (0.0 < xn ? xn : T{}) : x;  // std::max(0.0, x + f / denom)
    for (int c = 0; c < 6; ++c) n[c] = nn[c];
    yld_kinematic_rate<W>(P, n, an, epd, x, seg, ac, kin);
    T xi[6];
    for (int c = 0; c < 6; ++c) {
      sg[c] = ts[c] - G2 * x * n[c];
      xi[c] = sg[c];
      for (int k = 0; k < P.nback; ++k) xi[c] -= ac[k][c];
    }
    yld_gradient(P, xi, nn, sb);
    const M bad_s = active & ~((sb - sb) == 0.0);
    failed |= bad_s;
    active = active & ~bad_s;
  }
  failed |= active;  // 60 iterations
}

/// Yld2004Plasticity::update() of one point of W elements, but for the lanes
/// it hands back (`scalar`: their stress and state are left as they came in):
/// s (in: the rotated stress) and st updated in place; Q: the sheet axes.
/// seg: out, curve segments of strains near the new plastic strains.
template <int W, class T>
inline void yld_update(const YldParams& P, const T d[6], const T w[3], double dt, bool turn, T s[6], YldState<T>& st,
                       T Q[3][3], LaneSegments<W, T>& seg, bool scalar[W]) {
  using M = decltype(T{} < T{});
  const int nb = P.nback;
  if (turn)
    for (int k = 0; k < nb; ++k) material::rotate_symmetric(w[0], w[1], w[2], dt, st.back[k]);
  sheet_frame(w, dt, turn, st.rd, st.nd, Q);
  const T lt = P.lambda * (d[0] + d[1] + d[2]);
  const double g2 = 2.0 * P.G;
  T tr[6];
  for (int c = 0; c < 3; ++c) tr[c] = s[c] + (lt + g2 * d[c]);
  for (int c = 3; c < 6; ++c) tr[c] = s[c] + P.G * d[c];
  T ts[6], an[3][6], xi[6], nt[6];
  sheet_transform<true>(Q, tr, ts);
  for (int k = 0; k < nb; ++k) sheet_transform<true>(Q, st.back[k], an[k]);
  for (int c = 0; c < 6; ++c) {
    xi[c] = ts[c];
    for (int k = 0; k < nb; ++k) xi[c] -= an[k][c];
  }
  T sbt;
  yld_gradient(P, xi, nt, sbt);
  T s_ep, h;
  find_segments<W>(P.curve, st.ep, seg);
  curve_value(seg, st.ep, s_ep, h);
  T R0;
  yld_isotropic(P, s_ep, R0);
  const M plastic = (sbt - R0) > 0.0;
  for (int l = 0; l < W; ++l) scalar[l] = false;
  if (!any_set(plastic)) {
    for (int c = 0; c < 6; ++c) s[c] = tr[c];
    return;
  }
  T x = {};
  M done, failed;
  yld_return<W>(P, ts, an, st.ep, sbt, nt, plastic, seg, x, done, failed);
  long count = 0;
  for (int l = 0; l < W; ++l) {
    scalar[l] = failed[l] != 0;
    count += done[l] != 0;
  }
  P.self->count_lane_returns(count);
  T sg[6], bg[3][6];
  sheet_transform<false>(Q, ts, sg);
  for (int k = 0; k < nb; ++k) sheet_transform<false>(Q, an[k], bg[k]);
  for (int c = 0; c < 6; ++c) s[c] = done ? sg[c] : tr[c];
  for (int k = 0; k < nb; ++k)
    for (int c = 0; c < 6; ++c) st.back[k][c] = done ? bg[k][c] : st.back[k][c];
  st.ep = done ? st.ep + (0.0 + x) : st.ep;  // ep + dl, dl = 0 + x
}

/// ratio = Yld2004Plasticity::tangent_ratio() of W points (stress s, state st,
/// sheet axes Q after the update); seg: curve segments of nearby strains.
template <int W, class T>
inline void yld_tangent_ratio(const YldParams& P, const T s[6], const YldState<T>& st, const T Q[3][3],
                              LaneSegments<W, T>& seg, T& ratio) {
  T xi[6], l[6];
  for (int c = 0; c < 6; ++c) {
    T alpha = {};
    for (int k = 0; k < P.nback; ++k) alpha += st.back[k][c];
    xi[c] = s[c] - alpha;
  }
  sheet_transform<true>(Q, xi, l);
  T sy, H;
  curve_at_near<W>(P.curve, st.ep, seg, sy, H);
  T q;
  yld_equivalent(P, l, q);
  T R;
  yld_isotropic(P, sy, R);
  const T f = q / R;
  add_chaboche_tangent<W>(P.nterms, P.C, P.gamma, st.ep, f, H);
  proximity_ratio(f, H, P.E, ratio);
}

/// The material section of element_block<W> for Yld2004Plasticity
/// (lane_points): states from and to ev.state, each point turned with its spin.
template <int W, class T, class View>
inline void yld2004_points(const View& ev, int e0, const T s[2][6], const T deps[2][6], const T spin[2][3],
                           const T& V, T& ratio, T snew[2][6]) {
  const bool turn = ev.spin && ev.dtp != 0.0;
  YldState<T> st[2];
  T Q[2][3][3];
  LaneSegments<W, T> seg[2];
  lane_points<W>(
      ev, e0, s, deps, V, ratio, snew,
      [&](int gp, T* sn) {
        const YldParams& P = ev.yld2004;
        yld_move_state<W, false>(ev, e0, gp, st[gp]);
        bool scalar[W], keep[W], any = false;
        yld_update<W>(P, deps[gp], spin[gp], ev.dtp, turn, sn, st[gp], Q[gp], seg[gp], scalar);
        for (int l = 0; l < W; ++l) keep[l] = !scalar[l], any = any || scalar[l];
        yld_move_state<W, true>(ev, e0, gp, st[gp], keep);
        if (!any) return;
        // The lanes handed back: update() on the stress and state as they came in.
        for (int l = 0; l < W; ++l) {
          if (!scalar[l]) continue;
          double* sp = ev.state + (2 * static_cast<std::size_t>(e0 + l) + gp) * ev.ns;
          double sg[6], d[6];
          for (int c = 0; c < 6; ++c) sg[c] = lane(s[gp][c], l), d[c] = lane(deps[gp][c], l);
          const Spin w{lane(spin[gp][0], l), lane(spin[gp][1], l), lane(spin[gp][2], l), ev.dtp};
          P.self->update(d, w, sg, sp);
          for (int c = 0; c < 6; ++c) set_lane(sn[c], l, sg[c]);
        }
        yld_move_state<W, false>(ev, e0, gp, st[gp]);  // their new states, for the ratio
        find_segments<W>(P.curve, st[gp].ep, seg[gp]);
      },
      [&](int gp, const T* sn, T& r) { yld_tangent_ratio<W>(ev.yld2004, sn, st[gp], Q[gp], seg[gp], r); });
}

}  // namespace drawbend::material::lanes::DRAWBEND_ISA
