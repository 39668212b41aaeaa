// The fork governor's state machine (fe/fork_governor.hpp): settle, then
// trial windows forking and serial, then hold the winner.
#include "fe/fork_governor.hpp"

#include <algorithm>

namespace drawbend::fe {

void ForkGovernor::after_cycle(double seconds) {
  auto start = [this](Phase p) {
    phase_ = p;
    count_ = 0;
  };
  ++count_;
  switch (phase_) {
    case Phase::settle:
      if (count_ >= kSettle) start(Phase::trial_fork), t_fork_ = 0;
      break;
    case Phase::trial_fork:
      t_fork_ += seconds;
      if (count_ >= kWindow) start(Phase::trial_serial), t_serial_ = 0;
      break;
    case Phase::trial_serial: {
      t_serial_ += seconds;
      if (count_ < kWindow) break;
      const bool fork = t_fork_ < t_serial_;
      interval_ = fork == fork_ ? std::min(2 * interval_, kMaxInterval) : kMinInterval;
      fork_ = fork;
      start(Phase::hold);
      break;
    }
    case Phase::hold:
      if (count_ >= interval_) start(Phase::trial_fork), t_fork_ = 0;
      break;
  }
}

}  // namespace drawbend::fe
