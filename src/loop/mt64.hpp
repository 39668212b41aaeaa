// std::mt19937_64's sequence (the same seeding, the same numbers) with a
// branch-free twist: libstdc++ picks the twist's matrix term with a branch on
// a random bit (mispredicted half the time) and so spent ~10 % of the loop's
// screen in its refill of 312 numbers; here (y & 1) selects it by a mask, so
// the refill also runs in vector lanes, and the 312 outputs are tempered in
// one loop after it (vector lanes too) instead of one per call.  The
// permutation test draws its shuffles from it; tests/unit/test_loop_residuals.cpp
// checks that it equals std::mt19937_64 number for number.
#pragma once

#include <cstddef>
#include <cstdint>

namespace drawbend::loop {

/// The twist of the 312 numbers x and their tempered outputs y (mt64.cpp:
/// integer operations only, built for AVX-512, AVX2 and the baseline and
/// chosen at run time, the same numbers on each).
void mt64_refill(std::uint64_t* x, std::uint64_t* y);

class Mt64 {
 public:
  using result_type = std::uint64_t;
  explicit Mt64(std::uint64_t seed) {
    x_[0] = seed;
    for (std::size_t i = 1; i < kN; ++i) x_[i] = kF * (x_[i - 1] ^ (x_[i - 1] >> 62)) + i;
    p_ = kN;
  }
  std::uint64_t operator()() {
    if (p_ >= kN) refill();
    return y_[p_++];
  }
  /// How many outputs can be taken at once (at least 1: refills when none is
  /// left, as operator() would before its draw), and the next n <= that many,
  /// in order: take(n)[t] is what the t-th of n calls of operator() returns.
  std::size_t available() {
    if (p_ >= kN) refill();
    return kN - p_;
  }
  /// The most that available() returns (the stream's buffer).
  static constexpr std::size_t kBlock = 312;
  const std::uint64_t* take(std::size_t n) {
    const std::uint64_t* y = y_ + p_;
    p_ += n;
    return y;
  }

 private:
  static constexpr std::size_t kN = 312;
  static_assert(kN == kBlock, "available() returns at most kBlock");
  static constexpr std::uint64_t kF = 6364136223846793005ULL;
  void refill() {
    mt64_refill(x_, y_);
    p_ = 0;
  }
  std::uint64_t x_[kN];
  std::uint64_t y_[kN];  // the tempered outputs of x_
  std::size_t p_;
};

/// 32-bit draws from Mt64: each 64-bit output gives two, its low half and
/// then its high half (the permutation test's shuffles: a Fisher-Yates draw
/// modulo a group of at most a few thousand units needs no more than 32 bits,
/// the modulo bias k / 2^32 is below 1e-6, and each refill serves twice the
/// draws).  The same interface as Mt64: operator(), available(), take().
class Mt64Halves {
 public:
  using result_type = std::uint32_t;
  explicit Mt64Halves(std::uint64_t seed) : g_(seed) {}
  std::uint32_t operator()() {
    if (p_ >= kBlock) refill();
    return y_[p_++];
  }
  std::size_t available() {
    if (p_ >= kBlock) refill();
    return kBlock - p_;
  }
  static constexpr std::size_t kBlock = 2 * Mt64::kBlock;
  const std::uint32_t* take(std::size_t n) {
    const std::uint32_t* y = y_ + p_;
    p_ += n;
    return y;
  }

 private:
  void refill() {  // g_ is read only here, a whole block at a time (available() is kBlock / 2 after a refill)
    const std::size_t n = g_.available();
    const std::uint64_t* x = g_.take(n);
    for (std::size_t i = 0; i < n; ++i)
      y_[2 * i] = static_cast<std::uint32_t>(x[i]), y_[2 * i + 1] = static_cast<std::uint32_t>(x[i] >> 32);
    p_ = 0;
  }
  Mt64 g_;
  std::uint32_t y_[kBlock];
  std::size_t p_ = kBlock;
};

}  // namespace drawbend::loop
