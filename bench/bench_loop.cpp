// make bench: the loop on 50,000 rows (issue 21 goal: under 10 s on one core,
// progress shown).  Synthetic data (drawbend synth, hidden test-order drift,
// noise 5 N, 414 fixed-pin tests per pin x 40 rows + rotating tests = 50,040
// rows), analytic stand-in maps.  Writes build/bench/loop_cost.csv: rows,
// wall seconds, CPU seconds, steps.  Never a timed test.
#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>

#include "core/csv.hpp"
#include "loop/loop.hpp"
#include "loop/synth.hpp"

using namespace drawbend;
using namespace drawbend::loop;

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "bench/loop_cost.csv";
  std::filesystem::create_directories(std::filesystem::path(out).parent_path().empty()
                                          ? std::filesystem::path(".")
                                          : std::filesystem::path(out).parent_path());
  const MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  SynthOptions so;
  so.effect = "drift";
  so.noise_N = 5;
  so.seed = 7;
  so.tests_per_pin = 414;
  so.rows_per_test = 40;
  SynthTruth truth;
  const Dataset d = synthesize(so, maps, truth);
  LoopOptions lo;
  lo.progress = true;
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  const Design des = make_design(d, maps);
  const LoopResult r = run_loop(des, lo);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  CsvWriter w({"rows", "wall_s", "cpu_s", "steps", "first_step", "goal_s"});
  w.comment(" drawbend loop on synthetic data (hidden drift, noise 5 N), one thread; goal from issue 21");
  w.row({std::to_string(d.rows.size()), fmt(wall, 4), fmt(cpu, 4), std::to_string(r.steps.size()),
         r.steps.empty() ? "none" : r.steps[0].variable + " -> " + r.steps[0].effect, "10"});
  w.save(out);
  std::cout << "loop on " << d.rows.size() << " rows: " << fmt(wall, 4) << " s wall, " << fmt(cpu, 4)
            << " s CPU -> " << out << "\n";
  return 0;
}
