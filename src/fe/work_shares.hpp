#pragma once
// Static shares with stealing at the end, for a parallel loop whose items are
// independent and write only their own outputs (the element loop: every block
// of elements writes its own corner slots and records, fe/element_forces.cpp).
//
// The loop's range [0, n) is cut into one contiguous share per thread (as a
// static schedule cuts it, give or take one item at each boundary), and each
// share into chunks.  Thread t claims the chunks of share t in order, from
// the share's counter, so it runs the same items cycle after cycle and their
// data stay in its core's cache (a dynamic schedule over the whole range lost
// that: see docs/performance-log.md).  A thread done with its own share goes on to
// claim the next share's unclaimed chunks.
// So when a worker enters the region late, or runs slowly for a while on a
// shared host, the other thread runs the chunks it has not started, and
// waits at the join for at most the chunk the worker is in.
//
// Results never depend on which thread runs a chunk: the items write their
// own outputs, and nothing is summed across them here.  With one thread (the
// region not forked) the chunks run in order, share after share: 0 .. n-1.
// run() returns when nothing is left to claim, not when every chunk is done:
// a caller that reads the loop's outputs waits at a barrier first.
#include <algorithm>
#include <atomic>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>

namespace drawbend::fe::parallel {

class WorkShares {
 public:
  /// Cut [0, n) into `shares` contiguous shares, each into chunks of about
  /// 1/kChunksPerShare of it (at least one item).  Serially, before the region.
  /// n is at most INT_MAX / 2: a counter runs past its share's end by at most
  /// one chunk per thread, and must not overflow.
  void reset(int n, int shares) {
    if (n < 0 || n > INT_MAX / 2) throw std::length_error("WorkShares: n must be in 0 .. INT_MAX / 2");
    shares = std::max(1, shares);
    if (shares > capacity_) {
      share_ = std::make_unique<Share[]>(static_cast<std::size_t>(shares));
      capacity_ = shares;
    }
    num_shares_ = shares;
    for (int s = 0; s < shares; ++s) {
      const std::int64_t b = std::int64_t{n} * s / shares, e = std::int64_t{n} * (s + 1) / shares;
      share_[s].next.store(static_cast<int>(b), std::memory_order_relaxed);
      share_[s].end = static_cast<int>(e);
    }
    chunk_ = std::max(1, (n / shares) / kChunksPerShare);
  }

  /// Run body(begin, end) on chunks until none is left: thread t of the team
  /// starts on share t (mod the shares), then takes from the shares after it.
  template <class F>
  void run(int t, F&& body) {
    for (int k = 0; k < num_shares_; ++k) {
      Share& s = share_[(t + k) % num_shares_];
      for (;;) {
        const int b = s.next.fetch_add(chunk_, std::memory_order_relaxed);
        if (b >= s.end) break;
        body(b, std::min(b + chunk_, s.end));
      }
    }
  }

  /// Chunks per share: an uncontended claim costs a few nanoseconds, and a
  /// thread left without work waits at most one chunk (1/32 of a share).
  static constexpr int kChunksPerShare = 32;

 private:
  struct alignas(64) Share {  // one cache line each: a thread's claims do not disturb the other's line
    std::atomic<int> next{0};
    int end = 0;
  };
  std::unique_ptr<Share[]> share_;
  int capacity_ = 0, num_shares_ = 0, chunk_ = 1;
};

}  // namespace drawbend::fe::parallel
