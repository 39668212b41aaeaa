#pragma once
// Whether the solver's loops may fork into threads now, from their measured
// cost (issue 22: "decide whether a loop forks from its measured or modelled
// cost").  The model (fe/parallel_policy.hpp) says which loops are large
// enough to fork on an idle machine; this governor measures whether forking
// them pays on the machine as it is, and lets them fork only while it does.
//
// Why.  On a shared 2-core machine whose other core runs another job, every
// join waits for a worker the scheduler has put aside: with a long job on the
// other core, the 1,600-element bar ran 25 times slower on 2 threads than on
// 1 (4,946 against 201 ns per element-cycle, 2026-11-26).  No fixed model can
// see that; a measurement can.
//
// How.  Windows of kWindow cycles are timed alternately with forking allowed
// and forbidden; the window with the shorter median cycle wins (not the
// shorter sum: one cycle in which the host takes a core for milliseconds,
// seen in this guest at 13 times a normal cycle, would otherwise decide the
// trial) and holds until the next trial.  The hold is the shorter of two:
// a doubling hold, which doubles (up to kMaxInterval) each time the same
// mode wins again and falls back to kMinInterval when the other one does, so
// a wrong trial costs a few cycles in thousands; and a cut, kBudget times
// what the trial cost.  A trial runs kWindow cycles in the losing mode, so it
// costs kWindow x (loser's median - winner's median) over holding; the cut
// is kBudget times that, in cycles of the winner's median (at least
// kMinInterval).  Both are worked out afresh at each trial.  Where the two
// modes are close, a wrong decision costs little and trials stay frequent;
// where one mode is more than 21.5 times slower (kBudget x kWindow x 20.5 >
// kMaxInterval), the cut is above kMaxInterval and the doubling hold decides
// alone, as it did before the cut; in between, trials take 1 % of the run.
//
// Why the cut (2026-11-29).  On the Zen 4 guest the strip of `make bench`
// had stretches of seconds in which its forked cycles took 470-540 us
// against 406-430 serial, and 227-240 forked at other times, in the same
// process and on the same data.  Serial rightly won those trials, but the
// doubling hold had grown to 4,096 cycles (1.7 s) after a few, so the run
// went on serially for that long after forking paid again.  Those trials
// cost 8 x 70 us; the cut holds for 136 cycles (56 ms).  Where forking pays
// (227 against 410 us) the cut is 645 cycles (0.15 s; the doubling hold grew
// to 16,384), so trials cost 1 % of a forked run.  Where forking was 110
// times slower (45 against 0.41 ms a cycle, with `make` running on this
// machine) the cut is above kMaxInterval.  The first kSettle cycles (first
// touch of the arrays) are not timed.
//
// Results never depend on it: every parallel loop of the solver gives the
// same bits on any number of threads.  Not used when parallel::mode() is not
// `model` (tests that force every loop to fork, or none), nor on one thread.
namespace drawbend::fe {

class ForkGovernor {
 public:
  static constexpr int kSettle = 8;        ///< cycles before the first trial
  static constexpr int kWindow = 8;        ///< cycles per trial window
  static constexpr long kMinInterval = 64;     ///< cycles between trials, at first
  static constexpr long kMaxInterval = 16384;  ///< ... at most
  static constexpr double kBudget = 100;       ///< a hold lasts at most kBudget times its trial's cost

  /// May the loops fork in the coming cycle (as far as the measurement goes)?
  bool allowed() const { return phase_ == Phase::trial_serial ? false : (phase_ == Phase::trial_fork || fork_); }

  /// The wall time [s] of the cycle just run, with allowed() as it was.
  void after_cycle(double seconds);

  long interval() const { return interval_; }  ///< cycles until the next trial (for tests)

 private:
  enum class Phase { settle, trial_fork, trial_serial, hold };
  Phase phase_ = Phase::settle;
  bool fork_ = true;  // the mode that won the last trial (forking, before any)
  int count_ = 0;     // cycles into the current phase
  double t_fork_[kWindow] = {}, t_serial_[kWindow] = {};  // the trial windows' cycle times [s]
  long growth_ = kMinInterval;    // the doubling hold (before the cut)
  long interval_ = kMinInterval;  // the hold: growth_, cut to kBudget x the last trial's cost
};

}  // namespace drawbend::fe
