#pragma once
// The element kernel's corner slots on the lanes (fe/element_view.hpp,
// kCornerStride doubles a slot): W elements' forces at one corner stored into
// their slots.  Pure data movement, so no bit changes.  (The records the
// solver keeps per element: core/lane_records.hpp.)
#include <type_traits>

#include "core/lanes.hpp"
#include "fe/element_view.hpp"

namespace drawbend::fe {

/// Corner slots (fe/element_view.hpp, kCornerStride doubles): lane l's force
/// (f[0], f[1], f[2]) into the slot at out[l], two stores per lane (16 bytes:
/// the pair (f[0], f[1]); 8 bytes: f[2]).  In the AVX2 and AVX-512 kernels the
/// pairs come from one interleave of f[0] and f[1] (unpacklo: the even lanes'
/// pairs, unpackhi: the odd ones'), each stored straight from its 128-bit
/// part; f[2] is stored from its 128-bit parts as low and high halves.  No
/// full transpose: three vectors need none (an 8x8 transpose took 24 shuffles
/// per corner for these three rows).  The scalar kernel stores the three.
template <int W>
__attribute__((always_inline)) inline void store_slots(double* const out[1], const double f[3]) {
  for (int i = 0; i < 3; ++i) out[0][i] = f[i];
}
template <int W, class T>
__attribute__((always_inline)) inline void store_slots(double* const out[W], const T f[3]) {
  static_assert(kCornerStride == 3, "a slot is the three force components");
#if defined(__AVX512F__)
  if constexpr (W == 8) {
    constexpr __mmask8 kAll = 0xff;  // (the masked forms: as transpose8)
    const __m512d even = _mm512_maskz_unpacklo_pd(kAll, f[0], f[1]);  // part k: (f0, f1) of lane 2k
    const __m512d odd = _mm512_maskz_unpackhi_pd(kAll, f[0], f[1]);   // part k: of lane 2k + 1
    const __m512d z = f[2];
    const auto part = [](__m512d v, auto k) {  // 128-bit part k
      return _mm_castps_pd(_mm512_maskz_extractf32x4_ps(0xf, _mm512_castpd_ps(v), decltype(k)::value));
    };
    const auto store3 = [&](auto k) {
      constexpr int l = 2 * decltype(k)::value;
      _mm_storeu_pd(out[l], part(even, k));
      _mm_storeu_pd(out[l + 1], part(odd, k));
      const __m128d zk = part(z, k);
      _mm_storel_pd(out[l] + 2, zk);
      _mm_storeh_pd(out[l + 1] + 2, zk);
    };
    store3(std::integral_constant<int, 0>{});
    store3(std::integral_constant<int, 1>{});
    store3(std::integral_constant<int, 2>{});
    store3(std::integral_constant<int, 3>{});
    return;
  }
#endif
#if defined(__AVX__)
  if constexpr (W == 4) {
    const __m256d even = _mm256_unpacklo_pd(f[0], f[1]), odd = _mm256_unpackhi_pd(f[0], f[1]);
    const __m128d z0 = _mm256_castpd256_pd128(f[2]), z1 = _mm256_extractf128_pd(f[2], 1);
    _mm_storeu_pd(out[0], _mm256_castpd256_pd128(even));
    _mm_storeu_pd(out[1], _mm256_castpd256_pd128(odd));
    _mm_storeu_pd(out[2], _mm256_extractf128_pd(even, 1));
    _mm_storeu_pd(out[3], _mm256_extractf128_pd(odd, 1));
    _mm_storel_pd(out[0] + 2, z0);
    _mm_storeh_pd(out[1] + 2, z0);
    _mm_storel_pd(out[2] + 2, z1);
    _mm_storeh_pd(out[3] + 2, z1);
    return;
  }
#endif
  for (int l = 0; l < W; ++l)
    for (int i = 0; i < 3; ++i) out[l][i] = f[i][l];
}

}  // namespace drawbend::fe
