// The fork governor's state machine (fe/fork_governor.hpp): settle, then
// trial windows forking and serial, then hold the winner.
#include "fe/fork_governor.hpp"

#include <algorithm>
#include <iterator>

namespace drawbend::fe {

namespace {
/// The median of a window's cycle times (the mean of the middle two).
double median(const double (&t)[ForkGovernor::kWindow]) {
  double v[ForkGovernor::kWindow];
  std::copy(std::begin(t), std::end(t), v);
  std::sort(std::begin(v), std::end(v));
  constexpr int n = ForkGovernor::kWindow;
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

void ForkGovernor::after_cycle(double seconds) {
  auto start = [this](Phase p) {
    phase_ = p;
    count_ = 0;
  };
  ++count_;
  switch (phase_) {
    case Phase::settle:
      if (count_ >= kSettle) start(Phase::trial_fork);
      break;
    case Phase::trial_fork:
      t_fork_[count_ - 1] = seconds;
      if (count_ >= kWindow) start(Phase::trial_serial);
      break;
    case Phase::trial_serial: {
      t_serial_[count_ - 1] = seconds;
      if (count_ < kWindow) break;
      const bool fork = median(t_fork_) < median(t_serial_);
      interval_ = fork == fork_ ? std::min(2 * interval_, kMaxInterval) : kMinInterval;
      fork_ = fork;
      start(Phase::hold);
      break;
    }
    case Phase::hold:
      if (count_ >= interval_) start(Phase::trial_fork);
      break;
  }
}

}  // namespace drawbend::fe
