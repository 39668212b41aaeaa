#pragma once
// The J2 radial return (material/j2_isotropic.cpp) on W elements side by side,
// for the element kernel (fe/element_kernel.hpp): the same arithmetic in the
// same order on vector lanes, so every lane gives the bits of
// J2Isotropic::update_point() and tangent_ratio() (tests/unit/
// test_element_kernel.cpp compares every output).
//
// Branch-free across lanes: each point is elastic or plastic by a mask, both
// results are computed and the mask selects one (a bitwise select, not an
// arithmetic blend, so a NaN or infinity in the unused branch never leaks).
// Only the curve look-up is per lane (a table read by segment index), and the
// segment-by-segment search of the plastic strain loops as long as its
// slowest lane, which is once unless a lane crosses a curve point.
//
// Here too, for every model on the lanes (material/lanes/combined_lanes.hpp):
// the hardening curve's look-ups and the points section (lane_points).
//
// Compiled once per instruction set, in its namespace (as element_kernel.hpp,
// which includes it): nothing here may be an inline function shared with
// other translation units.
#include <cmath>
#include <limits>

#include "core/lane_records.hpp"
#include "core/lanes.hpp"
#include "material/lanes/points_view.hpp"

#ifndef DRAWBEND_ISA
#define DRAWBEND_ISA baseline  // as fe/hex8_geometry.hpp: the kernel's own source sets it
#endif

namespace drawbend::material::lanes::DRAWBEND_ISA {

using J2Params = J2Isotropic::LaneParams;
using CurveTable = HardeningCurve::Table;

/// HardeningCurve::segment(), on its table.
inline int curve_segment(const CurveTable& c, double ep) {
  if (ep >= c.x[c.last]) return c.last;
  if (ep <= 0.0) return 0;
  const double b = ep * c.inv_bin_width;
  int k = c.bins[b < c.max_bin ? static_cast<int>(b) : static_cast<int>(c.max_bin)];
  while (ep >= c.x[k + 1]) ++k;
  while (k > 0 && ep < c.x[k]) --k;
  return k;
}

/// curve_segment(c, ep), searched from segment k instead of the bins: the
/// same segment (the one with x[k] <= ep < x[k+1] inside the table, 0 and last
/// at its ends; a NaN's is curve_segment's), cheaper when k is that of a
/// nearby strain.
inline int curve_segment_from(const CurveTable& c, double ep, int k) {
  if (ep >= c.x[c.last]) return c.last;
  if (ep <= 0.0) return 0;
  if (!(ep == ep)) return curve_segment(c, ep);
  if (k >= c.last) k = c.last - 1;
  while (ep >= c.x[k + 1]) ++k;
  while (k > 0 && ep < c.x[k]) --k;
  return k;
}

/// Lane l's segment k: its start strain, start stress and slope.
template <int W, class T>
inline void gather_segment(const CurveTable& c, const int k[W], T& xk, T& yk, T& hk) {
  from_lanes(xk, [&](int l) { return c.x[k[l]]; });
  from_lanes(yk, [&](int l) { return c.y[k[l]]; });
  from_lanes(hk, [&](int l) { return c.h[k[l]]; });
}

template <int W, class M>
inline bool any_lane(const M& m) {
  return any_set(m);
}

/// Curve segments of W lanes: k and its start strain, start stress, slope
/// and end strain (the next point's strain; infinity on the last segment).
template <int W, class T>
struct LaneSegments {
  int k[W];
  T x, y, h, end;
};

/// seg.end = each lane's segment end: the next point's strain, infinity on the last.
template <int W, class T>
inline void segment_ends(const CurveTable& c, LaneSegments<W, T>& seg) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  from_lanes(seg.end, [&](int l) { return seg.k[l] + 1 <= c.last ? c.x[seg.k[l] + 1] : kInf; });
}

/// seg = the segments of W plastic strains (curve_segment of each lane) with
/// their table values.  Where every lane lies in lane 0's segment k
/// (x[k] <= ep < x[k+1], or ep >= x[last] on the last), the usual case in a
/// block of neighbouring elements, that is one search and four broadcasts;
/// otherwise a search and a table read per lane.  The same values either way.
template <int W, class T>
inline void find_segments(const CurveTable& c, const T& ep, LaneSegments<W, T>& seg) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int k0 = curve_segment(c, ep[0]);
  const double x0 = c.x[k0], end0 = k0 < c.last ? c.x[k0 + 1] : kInf;
  if (!any_set(~((ep >= x0) & (ep < end0)))) {
    for (int l = 0; l < W; ++l) seg.k[l] = k0;
    from_lanes(seg.x, [&](int) { return x0; });
    from_lanes(seg.y, [&](int) { return c.y[k0]; });
    from_lanes(seg.h, [&](int) { return c.h[k0]; });
    from_lanes(seg.end, [&](int) { return end0; });
    return;
  }
  for (int l = 0; l < W; ++l) seg.k[l] = curve_segment(c, ep[l]);
  gather_segment<W>(c, seg.k, seg.x, seg.y, seg.h);
  segment_ends(c, seg);
}

/// seg = the segments of W strains e (the values find_segments gives), from
/// seg = the segments of nearby strains (of find_segments or of this
/// function): where every lane lies in its segment (x[k] <= e < x[k+1], or
/// e >= x[last] on the last), seg stays as it is, with no search and no table
/// read; otherwise each lane is searched from its k (curve_segment_from, the
/// same segment).
template <int W, class T>
inline void find_segments_near(const CurveTable& c, const T& e, LaneSegments<W, T>& seg) {
  if (!any_set(~((e >= seg.x) & (e < seg.end)))) return;
  for (int l = 0; l < W; ++l) seg.k[l] = curve_segment_from(c, e[l], seg.k[l]);
  gather_segment<W>(c, seg.k, seg.x, seg.y, seg.h);
  segment_ends(c, seg);
}

/// sy = HardeningCurve::stress(ep) and hk = slope(ep) on ep's segments seg.
template <int W, class T>
inline void curve_value(const LaneSegments<W, T>& seg, const T& ep, T& sy, T& hk) {
  hk = seg.h;
  sy = seg.y + hk * (ep - seg.x);
}

/// sy = HardeningCurve::stress(ep) and hk = slope(ep) of W plastic strains.
template <int W, class T>
inline void curve_at(const CurveTable& c, const T& ep, T& sy, T& hk) {
  LaneSegments<W, T> seg;
  find_segments<W>(c, ep, seg);
  curve_value(seg, ep, sy, hk);
}

/// curve_at(c, ep, sy, hk) with seg (in: the segments of nearby strains, out:
/// ep's own; find_segments_near): the same values.
template <int W, class T>
inline void curve_at_near(const CurveTable& c, const T& ep, LaneSegments<W, T>& seg, T& sy, T& hk) {
  find_segments_near<W>(c, ep, seg);
  curve_value(seg, ep, sy, hk);
}

/// ratio = material::yield_proximity_ratio(f, plastic), by masks, with
/// plastic = H / (E + H).  The divisions only where a lane needs them: plastic
/// if some f is above 0.90, the blend if some f lies between 0.90 and 0.98
/// (or is NaN); a lane's bits are the same either way.
template <class T>
inline void proximity_ratio(const T& f, const T& H, double E, T& ratio) {
  using M = decltype(T{} < T{});
  const T one = T{} + 1.0;
  const M low = f <= 0.90, high = f >= 0.98;
  if (!any_set(~low)) {
    ratio = one;
    return;
  }
  const T plastic = H / (E + H);
  if (!any_set(~(low | high))) {
    ratio = low ? one : plastic;
    return;
  }
  const T between = 1.0 + (plastic - 1.0) * (f - 0.90) / 0.08;
  ratio = low ? one : (high ? plastic : between);
}

/// H += sum_k C[k] exp(-gamma[k] ep), the Chaboche terms' part of the monotonic
/// uniaxial tangent (CombinedPlasticity::tangent_ratio, Yld2004Plasticity's),
/// the exponentials lane by lane and only in the lanes that use them (f above
/// 0.90, or NaN): proximity_ratio selects 1 where f <= 0.90 whatever H is.
template <int W, class T>
inline void add_chaboche_tangent(int nterms, const double C[], const double gamma[], const T& ep, const T& f, T& H) {
  for (int k = 0; k < nterms; ++k) {
    const T v = -gamma[k] * ep;
    T e = {};
    for (int l = 0; l < W; ++l)
      if (!(lane(f, l) <= 0.90)) set_lane(e, l, std::exp(lane(v, l)));
    H += C[k] * e;
  }
}

/// The material section of element_block<W> shared by the models on the
/// lanes: for each point, update(gp, sn) updates sn (in: the rotated stress
/// s[gp], out: the new stress) and the point's state in ev.state, and
/// ratio_of(gp, sn, r) sets r, its tangent ratio; here the stress power by
/// the midpoint rule into ev.ie_inc, the new stresses into ev.sig and into
/// `snew` (so that the element's forces read them from registers, not back
/// from ev.sig) and the mean ratio.  The bits of the scalar section.  Both
/// points are updated before either's ratio: the updates are independent
/// chains of square roots and divisions, and side by side the processor can
/// overlap them.
template <int W, class T, class Update, class RatioOf, class View>
inline void lane_points(const View& ev, int e0, const T s[2][6], const T deps[2][6], const T& V, T& ratio,
                        T snew[2][6], Update&& update, RatioOf&& ratio_of) {
  T ie = {}, r[2];
  for (int gp = 0; gp < 2; ++gp) {
    for (int k = 0; k < 6; ++k) snew[gp][k] = s[gp][k];
    update(gp, snew[gp]);
  }
  for (int gp = 0; gp < 2; ++gp) ratio_of(gp, snew[gp], r[gp]);
  for (int gp = 0; gp < 2; ++gp) {
    const T* sn = snew[gp];
    T w = {};
    for (int k = 0; k < 6; ++k) w += 0.5 * (s[gp][k] + sn[k]) * deps[gp][k];
    ie += w;
  }
  store_records<12>(ev.sig + 12 * static_cast<std::size_t>(e0), &snew[0][0]);
  const T iev = 0.5 * V * ie;
  store_records<1>(ev.ie_inc + e0, &iev);
  ratio = 0.5 * (r[0] + r[1]);
}

/// One integration point of W elements: trial stress from s and d, radial
/// return; s and ep are updated in place (J2Isotropic::update_point).  Returns
/// whether seg holds each lane's last curve segment (a start for the search of
/// the new strain's segment, curve_segment_from); not when every lane stayed
/// below the initial yield stress, which needs no curve.
template <int W, class T>
inline bool j2_update(const J2Params& P, const T d[6], T s[6], T& ep, LaneSegments<W, T>& seg) {
  int* k = seg.k;
  T& xk = seg.x;
  T& yk = seg.y;
  T& hk = seg.h;
  using M = decltype(T{} < T{});
  const T lt = P.lambda * (d[0] + d[1] + d[2]);
  const double g2 = 2.0 * P.G;
  const T t0 = s[0] + lt + g2 * d[0];
  const T t1 = s[1] + lt + g2 * d[1];
  const T t2 = s[2] + lt + g2 * d[2];
  const T t3 = s[3] + P.G * d[3];
  const T t4 = s[4] + P.G * d[4];
  const T t5 = s[5] + P.G * d[5];
  const T p = (t0 + t1 + t2) * (1.0 / 3.0);
  const T a0 = t0 - p, a1 = t1 - p, a2 = t2 - p;
  const T q2 = 1.5 * (a0 * a0 + a1 * a1 + a2 * a2) + 3.0 * (t3 * t3 + t4 * t4 + t5 * t5);
  const M below_initial = q2 <= P.y0_sq;
  if (!any_lane<W>(~below_initial)) {  // all lanes below the initial yield stress
    s[0] = t0, s[1] = t1, s[2] = t2, s[3] = t3, s[4] = t4, s[5] = t5;
    return false;
  }
  find_segments<W>(P.curve, ep, seg);
  const T sy = yk + hk * (ep - xk);
  const M elastic = below_initial | (q2 <= sy * sy);
  if (!any_lane<W>(~elastic)) {
    s[0] = t0, s[1] = t1, s[2] = t2, s[3] = t3, s[4] = t4, s[5] = t5;
    return true;
  }
  // Plastic lanes: q_tr - 3G (e - ep) = sigma_y(e), segment by segment.
  T q;
  lane_sqrt(q2, q);
  T start = ep, r = q - sy, e = ep;
  M active = ~elastic;
  for (;;) {
    const T et = start + r / (P.g3 + hk);
    const T end = seg.end;
    e = active ? et : e;
    // Never past the last segment (end = +inf): a NaN et would cross forever
    // and read past the table (J2Isotropic::update_point says why; the bits
    // of every finite et are as before).
    const M cross = active & ~(et <= end) & (end < std::numeric_limits<double>::infinity());
    if (!any_lane<W>(cross)) break;
    for (int l = 0; l < W; ++l)
      if (cross[l]) ++k[l];
    T xn, yn, hn;
    gather_segment<W>(P.curve, k, xn, yn, hn);
    segment_ends(P.curve, seg);  // every lane's: k moved only where it crossed
    xk = cross ? xn : xk;
    yk = cross ? yn : yk;
    hk = cross ? hn : hk;
    start = cross ? end : start;
    r = cross ? q - P.g3 * (start - ep) - yk : r;
    active = cross;
  }
  const T f = (yk + hk * (e - xk)) / q;
  s[0] = elastic ? t0 : p + f * a0;
  s[1] = elastic ? t1 : p + f * a1;
  s[2] = elastic ? t2 : p + f * a2;
  s[3] = elastic ? t3 : f * t3;
  s[4] = elastic ? t4 : f * t4;
  s[5] = elastic ? t5 : f * t5;
  ep = elastic ? ep : e;
  return true;
}

/// ratio = J2Isotropic::tangent_ratio() of W points (stress s, plastic strain
/// ep); hint: the segments j2_update left (nullptr: none), whose table values
/// serve again where no lane's segment changed.  When every lane is well
/// inside the initial yield surface (q^2 <= P.ratio_one_q2, ep >= 0) the
/// ratio is 1 without the curve (J2Isotropic::LaneParams says why).  Through
/// a reference, as lane_sqrt (core/lanes.hpp): no vector return.
template <int W, class T>
inline void j2_tangent_ratio(const J2Params& P, const T s[6], const T& ep, const LaneSegments<W, T>* hint, T& ratio) {
  const T p = (s[0] + s[1] + s[2]) * (1.0 / 3.0);
  const T a0 = s[0] - p, a1 = s[1] - p, a2 = s[2] - p;
  const T q2 = 1.5 * (a0 * a0 + a1 * a1 + a2 * a2) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
  if (!any_set(~((q2 <= P.ratio_one_q2) & (ep >= 0.0)))) {
    ratio = T{} + 1.0;
    return;
  }
  // The hint's segment is ep's own (what curve_segment gives) where
  // x[k] <= ep < x[k+1] (ep >= x[last] on the last): then no lane searches.
  // Without one, find_segments.
  bool same = hint != nullptr && !any_set(~((ep >= hint->x) & (ep < hint->end)));
  T xk, yk, hk;
  if (!same && hint) {
    int k[W];
    same = true;
    for (int l = 0; l < W; ++l) {
      k[l] = curve_segment_from(P.curve, ep[l], hint->k[l]);
      same = same && k[l] == hint->k[l];
    }
    if (!same) gather_segment<W>(P.curve, k, xk, yk, hk);
  } else if (!hint) {
    LaneSegments<W, T> seg;
    find_segments<W>(P.curve, ep, seg);
    xk = seg.x, yk = seg.y, hk = seg.h;
  }
  if (same) xk = hint->x, yk = hint->y, hk = hint->h;
  const T sy = yk + hk * (ep - xk);
  T q;
  lane_sqrt(q2, q);
  const T f = q / sy;
  proximity_ratio(f, hk, P.E, ratio);
}

/// The material section of element_block<W> for J2 isotropic (lane_points):
/// the plastic strains from and to ev.state.
template <int W, class T, class View>
inline void j2_points(const View& ev, int e0, const T s[2][6], const T deps[2][6], const T& V, T& ratio,
                      T snew[2][6]) {
  T ep[2];  // the points' plastic strains (one state value per point)
  load_records<2>(ev.state + 2 * static_cast<std::size_t>(e0), ep);
  LaneSegments<W, T> seg[2];
  bool have_seg[2];
  lane_points<W>(
      ev, e0, s, deps, V, ratio, snew,
      [&](int gp, T* sn) { have_seg[gp] = j2_update<W>(ev.j2, deps[gp], sn, ep[gp], seg[gp]); },
      [&](int gp, const T* sn, T& r) { j2_tangent_ratio<W>(ev.j2, sn, ep[gp], have_seg[gp] ? &seg[gp] : nullptr, r); });
  store_records<2>(ev.state + 2 * static_cast<std::size_t>(e0), ep);
}

}  // namespace drawbend::material::lanes::DRAWBEND_ISA
