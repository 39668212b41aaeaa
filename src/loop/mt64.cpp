// Mt64's refill (mt64.hpp): the twist with the matrix term selected by a mask
// (no branch on a random bit), then the tempering of the 312 outputs in one
// loop.  Both loops run in vector lanes; integer operations give the same
// numbers on any instruction set, so the refill is built for AVX-512 and AVX2
// as well and the widest the processor has is chosen at run time (issue 50
// item 6: the refill was about a quarter of the permutation test's shuffles).
#include "loop/mt64.hpp"

namespace drawbend::loop {

namespace mt64_detail {

constexpr std::size_t kN = 312, kM = 156;
constexpr std::uint64_t kA = 0xB5026F5AA96619E9ULL;
constexpr std::uint64_t kUpper = ~std::uint64_t{0} << 31, kLower = ~kUpper;

inline std::uint64_t twist(std::uint64_t hi, std::uint64_t lo, std::uint64_t far) {
  const std::uint64_t y = (hi & kUpper) | (lo & kLower);
  return far ^ (y >> 1) ^ (kA & (std::uint64_t{0} - (y & 1)));
}

}  // namespace mt64_detail

__attribute__((target_clones("avx512f", "avx2", "default"))) void mt64_refill(std::uint64_t* x, std::uint64_t* y) {
  using namespace mt64_detail;
  for (std::size_t k = 0; k < kN - kM; ++k) x[k] = twist(x[k], x[k + 1], x[k + kM]);
  for (std::size_t k = kN - kM; k < kN - 1; ++k) x[k] = twist(x[k], x[k + 1], x[k + kM - kN]);
  x[kN - 1] = twist(x[kN - 1], x[0], x[kM - 1]);
  for (std::size_t k = 0; k < kN; ++k) {
    std::uint64_t z = x[k];
    z ^= (z >> 29) & 0x5555555555555555ULL;
    z ^= (z << 17) & 0x71D67FFFEDA60000ULL;
    z ^= (z << 37) & 0xFFF7EEE000000000ULL;
    z ^= z >> 43;
    y[k] = z;
  }
}

}  // namespace drawbend::loop
