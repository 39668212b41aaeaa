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

 private:
  static constexpr std::size_t kN = 312, kM = 156;
  static constexpr std::uint64_t kF = 6364136223846793005ULL, kA = 0xB5026F5AA96619E9ULL;
  static constexpr std::uint64_t kUpper = ~std::uint64_t{0} << 31, kLower = ~kUpper;
  static std::uint64_t twist(std::uint64_t hi, std::uint64_t lo, std::uint64_t far) {
    const std::uint64_t y = (hi & kUpper) | (lo & kLower);
    return far ^ (y >> 1) ^ (kA & (std::uint64_t{0} - (y & 1)));
  }
  void refill() {
    for (std::size_t k = 0; k < kN - kM; ++k) x_[k] = twist(x_[k], x_[k + 1], x_[k + kM]);
    for (std::size_t k = kN - kM; k < kN - 1; ++k) x_[k] = twist(x_[k], x_[k + 1], x_[k + kM - kN]);
    x_[kN - 1] = twist(x_[kN - 1], x_[0], x_[kM - 1]);
    // The tempering of the 312 outputs in one loop (vector lanes), not one
    // number per call (the shuffle's draws wait on it otherwise).
    for (std::size_t k = 0; k < kN; ++k) {
      std::uint64_t z = x_[k];
      z ^= (z >> 29) & 0x5555555555555555ULL;
      z ^= (z << 17) & 0x71D67FFFEDA60000ULL;
      z ^= (z << 37) & 0xFFF7EEE000000000ULL;
      z ^= z >> 43;
      y_[k] = z;
    }
    p_ = 0;
  }
  std::uint64_t x_[kN];
  std::uint64_t y_[kN];  // the tempered outputs of x_
  std::size_t p_;
};

}  // namespace drawbend::loop
