#pragma once
// Per-element records on the lanes: the solver stores each element's values
// as one record (12 stresses, 6 hourglass forces, the points' states, one
// ratio or energy), and the element kernel (fe/element_kernel.hpp) and the
// materials' lane twins (material/lanes/) read W consecutive elements'
// records as vectors, one element per lane, and write them back.  (The
// corner slots' stores, which know the solver's slot layout: fe/corner_slots.hpp.)
#include <cstring>

#include "core/lanes.hpp"

namespace drawbend {

/// Records: W consecutive records of N doubles (record l at p + N l, as the
/// solver stores each element's stresses, hourglass forces and states) as N
/// vectors, out[k] = (p[k], p[N + k], ..., p[N (W-1) + k]), and back.  Pure
/// data movement, so no bit changes; in the AVX2 and AVX-512 kernels it is a
/// few row loads and an in-register transpose (4x4 or 8x8 blocks) instead of
/// one element load and insert per lane (N W loads and about as many
/// shuffles), and the same for the stores.  Always inlined, as lane_sqrt.
namespace records_detail {
#if defined(__AVX512F__)
/// The 8x8 transpose of r[0..7] (rows) in place: r[k] lane l = old r[l] lane k.
/// (The zero-masked forms with every lane set: the plain intrinsics draw a
/// GCC 12 false "used uninitialized" warning; the same instructions.)
__attribute__((always_inline)) inline void transpose8(__m512d r[8]) {
  constexpr __mmask8 kAll = 0xff;
  __m512d t[8], u[8];
  for (int i = 0; i < 4; ++i) {
    t[2 * i] = _mm512_maskz_unpacklo_pd(kAll, r[2 * i], r[2 * i + 1]);
    t[2 * i + 1] = _mm512_maskz_unpackhi_pd(kAll, r[2 * i], r[2 * i + 1]);
  }
  // u: 128-bit lanes 0 and 2 (columns 0/4 of the pair), 1 and 3 (columns 2/6) ...
  u[0] = _mm512_maskz_shuffle_f64x2(kAll, t[0], t[2], 0x88);
  u[1] = _mm512_maskz_shuffle_f64x2(kAll, t[0], t[2], 0xdd);
  u[2] = _mm512_maskz_shuffle_f64x2(kAll, t[1], t[3], 0x88);
  u[3] = _mm512_maskz_shuffle_f64x2(kAll, t[1], t[3], 0xdd);
  u[4] = _mm512_maskz_shuffle_f64x2(kAll, t[4], t[6], 0x88);
  u[5] = _mm512_maskz_shuffle_f64x2(kAll, t[4], t[6], 0xdd);
  u[6] = _mm512_maskz_shuffle_f64x2(kAll, t[5], t[7], 0x88);
  u[7] = _mm512_maskz_shuffle_f64x2(kAll, t[5], t[7], 0xdd);
  r[0] = _mm512_maskz_shuffle_f64x2(kAll, u[0], u[4], 0x88);
  r[4] = _mm512_maskz_shuffle_f64x2(kAll, u[0], u[4], 0xdd);
  r[2] = _mm512_maskz_shuffle_f64x2(kAll, u[1], u[5], 0x88);
  r[6] = _mm512_maskz_shuffle_f64x2(kAll, u[1], u[5], 0xdd);
  r[1] = _mm512_maskz_shuffle_f64x2(kAll, u[2], u[6], 0x88);
  r[5] = _mm512_maskz_shuffle_f64x2(kAll, u[2], u[6], 0xdd);
  r[3] = _mm512_maskz_shuffle_f64x2(kAll, u[3], u[7], 0x88);
  r[7] = _mm512_maskz_shuffle_f64x2(kAll, u[3], u[7], 0xdd);
}
#endif
#if defined(__AVX__)
/// Stores the first w (1 .. 4) doubles of v at q.
__attribute__((always_inline)) inline void store_part(double* q, __m256d v, int w) {
  if (w == 4) {
    _mm256_storeu_pd(q, v);
    return;
  }
  const __m128d lo = _mm256_castpd256_pd128(v);
  if (w >= 2) _mm_storeu_pd(q, lo);
  if (w == 1) _mm_store_sd(q, lo);
  if (w == 3) _mm_store_sd(q + 2, _mm256_extractf128_pd(v, 1));
}
/// The 4x4 transpose of r[0..3] in place.
__attribute__((always_inline)) inline void transpose4(__m256d r[4]) {
  const __m256d t0 = _mm256_unpacklo_pd(r[0], r[1]), t1 = _mm256_unpackhi_pd(r[0], r[1]);
  const __m256d t2 = _mm256_unpacklo_pd(r[2], r[3]), t3 = _mm256_unpackhi_pd(r[2], r[3]);
  r[0] = _mm256_permute2f128_pd(t0, t2, 0x20);
  r[1] = _mm256_permute2f128_pd(t1, t3, 0x20);
  r[2] = _mm256_permute2f128_pd(t0, t2, 0x31);
  r[3] = _mm256_permute2f128_pd(t1, t3, 0x31);
}
#endif
#if defined(__AVX512F__)
/// Columns C .. C+7 of the 8 x N block of records at p (row l: record l) into
/// out[C ..], then the next columns.  Unrolled at compile time (a template per
/// column block): as a run-time loop GCC moved each block's vectors through a
/// stack buffer and a `rep movsq` into out[], whose later vector reads then
/// missed store forwarding.
template <int N, int C, class T>
__attribute__((always_inline)) inline void load_columns8(const double* p, T out[N]) {
  if constexpr (C < N) {
    constexpr int w = N - C < 8 ? N - C : 8;
    __m512d r[8];
    for (int l = 0; l < 8; ++l)
      r[l] = w == 8 ? _mm512_loadu_pd(p + N * l + C)
                    : _mm512_maskz_loadu_pd(static_cast<__mmask8>((1u << w) - 1), p + N * l + C);
    transpose8(r);
    for (int k = 0; k < w; ++k) out[C + k] = r[k];
    load_columns8<N, C + 8>(p, out);
  }
}
/// in[C .. C+7] into columns C .. C+7 of the 8 x N block at p, then the next
/// columns (compile-time unrolled, as load_columns8).
template <int N, int C, class T>
__attribute__((always_inline)) inline void store_columns8(double* p, const T in[N]) {
  if constexpr (C < N) {
    constexpr int w = N - C < 8 ? N - C : 8;
    __m512d r[8];
    for (int k = 0; k < 8; ++k) r[k] = k < w ? static_cast<__m512d>(in[C + k]) : _mm512_setzero_pd();
    transpose8(r);
    for (int l = 0; l < 8; ++l) {  // row l: element l's w values, without masked stores
      double* q = p + N * l + C;
      if constexpr (w == 8) {
        _mm512_storeu_pd(q, r[l]);
      } else {
        const __m256d lo = _mm512_maskz_extractf64x4_pd(0xf, r[l], 0);  // (the masked form: as transpose8)
        store_part(q, lo, w < 4 ? w : 4);
        if constexpr (w > 4) store_part(q + 4, _mm512_maskz_extractf64x4_pd(0xf, r[l], 1), w - 4);
      }
    }
    store_columns8<N, C + 8>(p, in);
  }
}
#endif
}  // namespace records_detail

template <int N>
__attribute__((always_inline)) inline void load_records(const double* p, double out[N]) {
  for (int k = 0; k < N; ++k) out[k] = p[k];
}
template <int N, class T>
__attribute__((always_inline)) inline void load_records(const double* p, T out[N]) {
  [[maybe_unused]] constexpr int W = sizeof(T) / sizeof(double);
  if constexpr (N == 1) {  // one vector load
    std::memcpy(&out[0], p, sizeof(T));
    return;
  }
#if defined(__AVX512F__)
  if constexpr (W == 8 && N == 2) {  // two loads, two two-source permutes
    const __m512d r0 = _mm512_loadu_pd(p), r1 = _mm512_loadu_pd(p + 8);
    out[0] = _mm512_permutex2var_pd(r0, _mm512_set_epi64(14, 12, 10, 8, 6, 4, 2, 0), r1);
    out[1] = _mm512_permutex2var_pd(r0, _mm512_set_epi64(15, 13, 11, 9, 7, 5, 3, 1), r1);
    return;
  }
#endif
#if defined(__AVX512F__)
  if constexpr (W == 8) {
    records_detail::load_columns8<N, 0>(p, out);
    return;
  }
#endif
#if defined(__AVX__)
  if constexpr (W == 4) {
    for (int c = 0; c < N; c += 4) {
      const int w = N - c < 4 ? N - c : 4;
      __m256d r[4];
      for (int l = 0; l < 4; ++l) {
        const double* q = p + N * l + c;
        if (w == 4) r[l] = _mm256_loadu_pd(q);
        else if (w == 2) r[l] = _mm256_castpd128_pd256(_mm_loadu_pd(q));  // lanes 2, 3: unused
        else r[l] = _mm256_set_pd(0.0, w > 2 ? q[2] : 0.0, w > 1 ? q[1] : 0.0, q[0]);
      }
      records_detail::transpose4(r);
      for (int k = 0; k < w; ++k) out[c + k] = r[k];
    }
    return;
  }
#endif
  for (int k = 0; k < N; ++k) from_lanes(out[k], [&](int l) { return p[N * l + k]; });
}

template <int N>
__attribute__((always_inline)) inline void store_records(double* p, const double in[N]) {
  for (int k = 0; k < N; ++k) p[k] = in[k];
}
template <int N, class T>
__attribute__((always_inline)) inline void store_records(double* p, const T in[N]) {
  [[maybe_unused]] constexpr int W = sizeof(T) / sizeof(double);
  if constexpr (N == 1) {
    std::memcpy(p, &in[0], sizeof(T));
    return;
  }
#if defined(__AVX512F__)
  if constexpr (W == 8 && N == 2) {
    const __m512d a = in[0], b = in[1];
    _mm512_storeu_pd(p, _mm512_permutex2var_pd(a, _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0), b));
    _mm512_storeu_pd(p + 8, _mm512_permutex2var_pd(a, _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4), b));
    return;
  }
#endif
#if defined(__AVX512F__)
  if constexpr (W == 8) {
    records_detail::store_columns8<N, 0>(p, in);
    return;
  }
#endif
#if defined(__AVX__)
  if constexpr (W == 4) {
    for (int c = 0; c < N; c += 4) {
      const int w = N - c < 4 ? N - c : 4;
      __m256d r[4];
      for (int k = 0; k < 4; ++k) r[k] = k < w ? static_cast<__m256d>(in[c + k]) : _mm256_setzero_pd();
      records_detail::transpose4(r);
      for (int l = 0; l < 4; ++l) records_detail::store_part(p + N * l + c, r[l], w);
    }
    return;
  }
#endif
  for (int k = 0; k < N; ++k)
    for (int l = 0; l < W; ++l) p[N * l + k] = in[k][l];
}

}  // namespace drawbend
