#pragma once
// make bench: what the machine gives two threads at the time of a 2-thread
// timing (bench_host.cpp), so that a reader can tell a slow parallel solver
// from a host that did not give the second core.
//
// Why.  This project's machines are virtual (KVM guests with 2 vCPUs).  On
// the Zen 4 guest (2026-11-29) the strip's forked cycles ran for seconds at a
// time at 470-540 us against 227-240 us at other times, in the same process
// and on the same data, while its serial cycles stayed at 406-430 us; in those
// stretches each thread's share of the element loop took 180-240 us against
// 148-156 us.  The fork governor (fe/fork_governor.hpp) then rightly holds the
// run serial, and the 2-thread figure drops towards the 1-thread one.  Right
// after one such run (element loop forked in 44 % of the cycles, 84.8 ns per
// element-cycle against 92.5 on one thread), two independent 1-thread runs
// of the same strip did 2.07 times the work of one: the host then had two
// cores for work that shares nothing (after the stretch, not in it; what the
// forked threads share made later stretches worse, but did not explain them
// all: docs/performance-log.md).  This probe tells a low 2-thread figure with the
// cores there from one without them.
//
// What.  The case's own model is run on one thread alone, then as two
// independent one-thread runs at the same time (two std::threads, no shared
// data, no synchronisation).  capacity = 2 x (one alone) / (two at once): 2.0
// when the host gives two full cores, 1.0 when it gives one.  Each wall time
// is the shortest of `repeats` runs (interference only adds time).  It is a
// reference for the forked run, not a bound (forked threads split the data,
// which can fit the caches better: bar 64,000 ran 2.08 times faster on 2
// threads, 2026-11-29) and not a target.
#include "fe/model.hpp"

/// Host capacity for two threads on model `m` over `cycles` cycles (see above);
/// restores the caller's OpenMP thread count.
double two_core_capacity(const drawbend::fe::Model& m, long cycles, int repeats);
