#pragma once
// make bench: an independent peer, CalculiX's explicit solver (ccx, Debian
// package calculix-ccx, installed by scripts/install-deps.sh), timed on the
// same bar as ours in the same run (issue 22, item 6; bench_calculix.cpp).
// Optional: without ccx on PATH the bench says so and carries on, and a ccx
// problem is reported, never fatal.
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "core/vec3.hpp"

/// One bar run by ccx and by ours over the same two simulated windows (short
/// and long, so that set-up cancels in the difference), both on 1 thread.
struct PeerResult {
  std::string name;  ///< our case name, "bar_1600"
  long elements = 0;
  std::string note;  ///< empty: ran; else why not (skipped, failed)
  std::string version;
  double window[2] = {0, 0};  ///< simulated times of the short and long runs [s]
  long ccx_incs[2] = {0, 0}, ours_cycles[2] = {0, 0};
  double ccx_wall[2] = {0, 0}, ccx_cpu[2] = {0, 0}, ours_wall[2] = {0, 0}, ours_cpu[2] = {0, 0};  ///< [s]
  double ccx_dt = 0, ours_dt = 0;  ///< time step at the start [s]
  double ccx_ns = 0, ccx_cpu_ns = 0, ours_ns = 0, ours_cpu_ns = 0;  ///< per element-cycle over long - short
  /// At the end of the long window: reaction on xmin [N] and the displacement
  /// of the probe node (mid-length, corner y = ymax, z = zmax) [mm].
  drawbend::Vec3 ccx_rf{0, 0, 0}, ours_rf{0, 0, 0}, ccx_u{0, 0, 0}, ours_u{0, 0, 0};
  double mismatch = 0;  ///< largest relative difference of |RF_x| and the probe's u (see agree())
  bool agree() const { return note.empty() && mismatch <= 0.05; }
};

/// Runs the peer comparison in scratch folders under `dir` for the bar of
/// 1,600 elements and, if not `quick` and its estimated ccx time is under a
/// minute, of 8,000; prints each as it goes and appends rows to `w` (case
/// "calculix_bar_N": ccx's ns per element-cycle; "bar_N_ccx_window": ours on
/// the same windows) and comments (ratio, steps, increments, results).  An
/// empty list when ccx is not on PATH (the message says so).
std::vector<PeerResult> bench_calculix(const std::string& dir, drawbend::CsvWriter& w, bool quick);

/// The summary lines: per bar "CalculiX ccx V bar N: X ns/element-cycle
/// (1 thread), ours Y ns: ratio R" with the steps and the sanity check; or the
/// line saying ccx is not installed.
void print_calculix_summary(const std::vector<PeerResult>& peers, bool installed);

/// Whether `ccx` is an executable on PATH (its path, or empty).
std::string find_ccx();
