// The fork governor's state machine (fe/fork_governor.hpp): settle, then
// trial windows forking and serial, then hold the winner (a doubling hold,
// cut to kBudget times what the trial cost).
#include "fe/fork_governor.hpp"

#include <algorithm>
#include <cmath>
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
      const double m_fork = median(t_fork_), m_serial = median(t_serial_);
      const bool fork = m_fork < m_serial;
      growth_ = fork == fork_ ? std::min(2 * growth_, kMaxInterval) : kMinInterval;
      fork_ = fork;
      // The hold no longer than kBudget x the trial's cost (fe/fork_governor.hpp).
      const double win = std::max(std::min(m_fork, m_serial), 1e-9), lose = std::max(m_fork, m_serial);
      const double budget = kBudget * kWindow * (lose - win) / win;  // cycles of the winner
      interval_ = budget >= static_cast<double>(growth_) ? growth_ : std::max(kMinInterval, std::lround(budget));
      start(Phase::hold);
      break;
    }
    case Phase::hold:
      if (count_ >= interval_) start(Phase::trial_fork);
      break;
  }
}

}  // namespace drawbend::fe
