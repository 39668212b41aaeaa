// The quick draw-bend deck's wall time on 1 and 2 threads: the case a user
// meets first (`drawbend drawbend-deck --run`), which on 2 threads used to
// fork tiny node loops every cycle and run many times slower than on 1
// (issue 22; fe/parallel_policy.hpp now decides from the modelled cost).
#include "bench_deck.hpp"

#include <omp.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "sim/drawbend_case.hpp"
#include "sim/fe_options.hpp"

using namespace drawbend;

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown";
}

bool bench_deck(const std::string& dir, CsvWriter& w) {
  // The defaults of `drawbend drawbend-deck` (sim::quick_deck_spec): the
  // quick tier's mesh (400 elements, 765 nodes), its mass scaling at the
  // default speed, the RD curve.  Before 2026-11-27 this took DrawBendSpec's
  // own mesh, a finer deck than the one users meet first.
  const sim::DrawBendSpec s = sim::quick_deck_spec();
  double wall[3] = {0, 0, 0};
  const int maxt = std::min(2, omp_get_num_procs());
  for (int threads = 1; threads <= maxt; ++threads) {
    const std::string run_dir = dir + "/deck_" + std::to_string(threads) + "t";
    std::filesystem::remove_all(run_dir);
    omp_set_num_threads(threads);
    const auto t0 = std::chrono::steady_clock::now();
    sim::run_drawbend(s, run_dir, false, true);
    wall[threads] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::filesystem::remove_all(run_dir);
    std::cout << "drawbend deck (quick, defaults): " << threads << " thread(s): " << fmt(wall[threads], 4) << " s wall\n";
    w.row({"drawbend_deck_wall_s", "", std::to_string(threads), fmt(wall[threads], 5)});
  }
  if (maxt < 2) return true;
  const bool ok = wall[2] <= 1.10 * wall[1];
  std::cout << (ok ? "ok   " : "FAIL ") << "drawbend deck, 2 threads not slower than 1: 2 threads / 1 thread = "
            << fmt(wall[2] / wall[1], 3) << (ok ? " (within 10 % noise)\n" : " (SLOWER on 2 threads)\n");
  return ok;
}
