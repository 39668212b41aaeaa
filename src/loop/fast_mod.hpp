// x % k without a division in the loop (Barrett reduction), exact for every
// 64-bit x (FastMod; 32-bit x: FastMod32) and 2 <= k <= kmax.  With R = floor(2^64 / k), q = floor(x R / 2^64)
// is floor(x / k) or one less (R > 2^64/k - 1 and x < 2^64), so x - q k lies in
// [0, 2k) and one conditional subtraction ends it.  The permutation test's
// Fisher-Yates shuffle uses it so that its sequence is that of rng() % k.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drawbend::loop {

class FastMod {
 public:
  explicit FastMod(std::size_t kmax) : r_(kmax + 1, 0) {
    for (std::size_t k = 2; k <= kmax; ++k)
      r_[k] = ~std::uint64_t{0} / k + ((k & (k - 1)) == 0 ? 1 : 0);  // floor(2^64 / k)
  }
  std::uint64_t operator()(std::uint64_t x, std::size_t k) const {
    __extension__ using u128 = unsigned __int128;  // a GCC/Clang extension: no -Wpedantic warning
    const auto q = static_cast<std::uint64_t>((static_cast<u128>(x) * r_[k]) >> 64);
    const std::uint64_t r = x - q * k;
    // By a mask, not a conditional: r >= k in 20-25 % of random x (counted for
    // k up to 5000), and GCC compiled the conditional in the shuffle's loop of
    // reductions as a branch, which mispredicts that often.
    return r - (k & (std::uint64_t{0} - static_cast<std::uint64_t>(r >= k)));
  }

 private:
  std::vector<std::uint64_t> r_;
};

// The same for 32-bit x (the permutation test's draws, Mt64Halves): with
// R = floor(2^32 / k) (< 2^32 for k >= 2), q = floor(x R / 2^32) is
// floor(x / k) or one less, so x - q k lies in [0, 2k): one 64-bit product
// in place of FastMod's 128-bit one.  kmax < 2^32.
class FastMod32 {
 public:
  explicit FastMod32(std::size_t kmax) : r_(kmax + 1, 0) {
    for (std::size_t k = 2; k <= kmax; ++k) r_[k] = (std::uint64_t{1} << 32) / k;  // floor(2^32 / k)
  }
  std::uint32_t operator()(std::uint32_t x, std::size_t k) const {
    const std::uint64_t q = (static_cast<std::uint64_t>(x) * r_[k]) >> 32;
    const std::uint64_t r = x - q * k;
    return static_cast<std::uint32_t>(r - (k & (std::uint64_t{0} - static_cast<std::uint64_t>(r >= k))));
  }

 private:
  std::vector<std::uint64_t> r_;
};

}  // namespace drawbend::loop
