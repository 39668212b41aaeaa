#pragma once
// Lanes of elements: the same source computes one element (T = double) or W
// elements side by side (T = a GCC vector of W doubles, one element per lane).
// The primitives of the element kernel (fe/element_kernel.hpp) and of the
// materials' lane twins (material/lanes/), which both build on them.
//
// Why this keeps the results bit for bit.  A vector add, subtract, multiply,
// divide or square root is the IEEE operation on each lane, so lane l of a
// vector expression equals the scalar expression evaluated in the same order.
// The kernels are written once, as templates, so the order is the same by
// construction.  Two things could still break it, and both are excluded:
//  - fused multiply-add (a*b + c rounded once): the vector ISA files are built
//    with -ffp-contract=off and without -mfma (AVX-512F has its own FMA
//    instructions; -ffp-contract=off keeps the compiler from using them);
//  - reassociation (-ffast-math, -fassociative-math): never used.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#if defined(__AVX__)
#include <immintrin.h>
#endif

namespace drawbend {

template <int W>
struct Lanes;
template <>
struct Lanes<1> {
  using type = double;
};
template <>
struct Lanes<4> {
  using type = double __attribute__((vector_size(32)));
};
template <>
struct Lanes<8> {  // AVX-512 only (fe/element_kernel_avx512.cpp): on AVX2 eight lanes spill
  using type = double __attribute__((vector_size(64)));
};

/// Lane l of a value (a double has one lane), and setting it (a setter, not
/// a reference: Clang binds no reference to a vector element).
inline double lane(double v, int) { return v; }
inline void set_lane(double& v, int, double x) { v = x; }
template <class T>
inline double lane(const T& v, int l) {
  return v[l];
}
template <class T>
inline void set_lane(T& v, int l, double x) {
  v[l] = x;
}

/// v = (f(0), f(1), ..., f(W-1)): a vector built in registers from W scalars
/// (element loads and inserts).  Setting the lanes one by one with set_lane()
/// makes GCC write W scalars to the stack and read them back as one vector, a
/// load that store forwarding cannot serve: it stalls for every vector so
/// gathered (the node gather, the stresses, the hourglass forces).  Use this,
/// not a set_lane() loop, for every vector the kernel gathers.
template <class F>
__attribute__((always_inline)) inline void from_lanes(double& v, F&& f) {
  v = f(0);
}
template <class T, class F, std::size_t... L>
__attribute__((always_inline)) inline void from_lanes_seq(T& v, F& f, std::index_sequence<L...>) {
  v = T{f(static_cast<int>(L))...};
}
template <class T, class F>
__attribute__((always_inline)) inline void from_lanes(T& v, F&& f) {
  from_lanes_seq(v, f, std::make_index_sequence<sizeof(T) / sizeof(double)>{});
}

/// r = the square root of each lane of v (IEEE, correctly rounded: as
/// std::sqrt).  Written through a reference: returning a 32-byte vector by
/// value would change the ABI between the baseline and AVX builds.  In the
/// AVX2 and AVX-512 kernels one vector instruction (vsqrtpd) does all lanes:
/// a correctly rounded square root has one answer, so the bits are those of
/// std::sqrt lane by lane, which GCC otherwise emits as one vsqrtsd per lane.
/// Always inlined, so the kernels' objects define no copy of it (a copy with
/// AVX instructions must never be the one the baseline code calls).
inline void lane_sqrt(const double& v, double& r) { r = std::sqrt(v); }
template <class T>
__attribute__((always_inline)) inline void lane_sqrt(const T& v, T& r) {
#if defined(__AVX512F__)
  if constexpr (sizeof(T) == 64) {
    r = _mm512_mask_sqrt_pd(v, static_cast<__mmask8>(0xff), v);  // all lanes (_mm512_sqrt_pd: a GCC 12 false warning)
    return;
  }
#endif
#if defined(__AVX__)
  if constexpr (sizeof(T) == 32) {
    r = _mm256_sqrt_pd(v);
    return;
  }
#endif
  for (int l = 0; l < static_cast<int>(sizeof(T) / sizeof(double)); ++l) r[l] = std::sqrt(v[l]);
}

/// r = std::exp of each lane of v (the same libm call as the scalar code).
inline void lane_exp(const double& v, double& r) { r = std::exp(v); }
template <class T>
inline void lane_exp(const T& v, T& r) {
  for (int l = 0; l < static_cast<int>(sizeof(T) / sizeof(double)); ++l) r[l] = std::exp(v[l]);
}

/// True when some lane of a mask (a lane comparison: all ones or zero per
/// lane) is set: one test of the sign bits in the AVX2 and AVX-512 kernels,
/// not a branch per lane.  Always inlined, as lane_sqrt.
template <class M>
__attribute__((always_inline)) inline bool any_set(const M& m) {
#if defined(__AVX512F__)
  if constexpr (sizeof(M) == 64) return _mm512_test_epi64_mask((__m512i)m, (__m512i)m) != 0;
#endif
#if defined(__AVX__)
  if constexpr (sizeof(M) == 32) return _mm256_movemask_pd((__m256d)m) != 0;
#endif
  bool any = false;
  for (int l = 0; l < static_cast<int>(sizeof(M) / sizeof(m[0])); ++l) any = any || m[l] != 0;
  return any;
}

/// True when every lane is positive (false for a NaN lane).
inline bool all_positive(double v) { return v > 0.0; }
template <class T>
__attribute__((always_inline)) inline bool all_positive(const T& v) {
  return !any_set(~(v > 0.0));
}

}  // namespace drawbend
