// The time-stamp counter's rate (fe/phase_times.hpp): ticks counted over a
// busy wait of 20 ms on the steady clock.  The counter runs at a constant rate
// on the CPUs this project meets (constant_tsc); a rough figure is enough for
// a per-phase split.
#include "fe/phase_times.hpp"

#include <chrono>

namespace drawbend::fe {

double seconds_per_tick() {
#if defined(__x86_64__)
  static const double s = [] {
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    const std::uint64_t c0 = __builtin_ia32_rdtsc();
    while (clock::now() - t0 < std::chrono::milliseconds(20)) {
    }
    const std::uint64_t c1 = __builtin_ia32_rdtsc();
    const double sec = std::chrono::duration<double>(clock::now() - t0).count();
    return c1 > c0 ? sec / static_cast<double>(c1 - c0) : 0.0;
  }();
  return s;
#else
  return 0.0;
#endif
}

}  // namespace drawbend::fe
