// make bench: the loop on 50,000 rows (issue 21 goal: under 10 s on one core,
// progress shown), in two forms (issue 50 item 6 / issue 53):
//  - "bench": synthetic data (drawbend synth, hidden test-order drift, noise
//    5 N, 414 fixed-pin tests per pin x 40 rows + rotating tests = 50,040
//    rows), analytic stand-in maps;
//  - "lab-style": the same design with a hidden coil effect, as a lab would
//    send it: 42 coils (the three of the law split into 14 each, drawn per
//    test), lab test ids, strip ids, operators, a time stamp per row, free
//    text, rows in run order.  The coil column has 42 levels, so the loop
//    fits a 41-parameter group factor; before the sparse Jacobian (issue 50
//    item 6) this form took 3.7x the bench form's CPU on one thread.
// One thread (Eigen's products; the loop's default; --threads N screens N
// candidates at once, CPU seconds then summed over threads).  Writes
// build/bench/loop_cost.csv: form, rows, wall seconds, CPU seconds, steps,
// and the Jacobian row evaluations; --data DIR also writes each form's rows
// (FORM.csv) for timing `drawbend loop` itself.  Never a timed test.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <random>

#include "core/csv.hpp"
#include "core/options.hpp"
#include "loop/least_squares.hpp"
#include "loop/loop.hpp"
#include "loop/measured.hpp"
#include "loop/synth.hpp"

using namespace drawbend;
using namespace drawbend::loop;

namespace {
// The rows as a lab sends them (see the header): 42 coils, lab ids, strings,
// a time stamp per row, free text, run order.
void lab_style(Dataset& d) {
  std::mt19937_64 rng(11);
  const int ic = d.extra_index("coil"), io = d.extra_index("test_order");
  std::map<std::string, std::string> sub, strip, op;
  d.extra_columns.insert(d.extra_columns.end(), {"strip_id", "operator", "timestamp", "remark"});
  const char* ops[] = {"A. Jansen", "M. de Vries", "K. Bakker"};
  std::stable_sort(d.rows.begin(), d.rows.end(), [&](const Sample& a, const Sample& b) {
    return std::stoi(a.extra[io]) < std::stoi(b.extra[io]);
  });
  long clock = 0;
  for (auto& s : d.rows) {
    if (!sub.count(s.test_id)) {
      sub[s.test_id] = s.extra[ic] + std::to_string(1 + rng() % 14);
      strip[s.test_id] = "S" + std::to_string(100000 + 7 * sub.size() + rng() % 7);
      op[s.test_id] = ops[rng() % 3];
    }
    clock += 5 + static_cast<long>(rng() % 21);
    const std::string id = s.test_id;
    s.test_id = "DB2026-" + std::to_string(1000 + std::stoi(s.extra[io])) + "-" + id;
    s.extra[ic] = sub[id];
    char ts[32];
    std::snprintf(ts, sizeof ts, "2026-03-%02ldT%02ld:%02ld:%02ld", 1 + clock / 86400 % 28, clock / 3600 % 24,
                  clock / 60 % 60, clock % 60);
    s.extra.insert(s.extra.end(), {strip[id], op[id], ts,
                                   rng() % 5 ? "" : "re-clamped after the first stroke, lubricant re-applied by hand; "
                                                    "see lab book p. " + std::to_string(rng() % 300)});
  }
}
}  // namespace

int main(int argc, char** argv) {
  std::string out = "bench/loop_cost.csv", summaries, forms = "bench,lab-style", data;
  int threads = 1;
  Options opt("bench_loop", "make bench: the measured-data loop on 50,000 synthetic rows (wall and CPU seconds)");
  opt.add(out, "out", "results CSV");
  opt.add(summaries, "summaries", "directory for each form's loop_summary.json (empty: none); compare before/after a speed change");
  opt.add(forms, "forms", "the forms run: bench, lab-style or both (comma-separated)");
  opt.add(threads, "threads", "threads of the loop's screen (LoopOptions::threads; CPU seconds are all threads')");
  opt.add(data, "data", "directory to write each form's rows to as FORM.csv (drawbend loop's input; empty: none)");
  try {
    if (!opt.parse(argc, argv)) return 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "bench_loop: " << e.what() << "\n";
    return 2;
  }
  std::filesystem::create_directories(std::filesystem::path(out).parent_path().empty()
                                          ? std::filesystem::path(".")
                                          : std::filesystem::path(out).parent_path());
  const MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  CsvWriter w({"form", "rows", "wall_s", "cpu_s", "steps", "first_step", "jacobian_row_evals", "goal_s"});
  w.comment(" drawbend loop on 50,000 synthetic rows, one thread; goal from issue 21 (10 s on one core)");
  Eigen::setNbThreads(1);
  for (const std::string form : {"bench", "lab-style"}) {
    if (("," + forms + ",").find("," + form + ",") == std::string::npos) continue;
    SynthOptions so;
    so.effect = form == "bench" ? "drift" : "batch";
    so.noise_N = 5;
    so.seed = 7;
    so.tests_per_pin = 414;
    so.rows_per_test = 40;
    SynthTruth truth;
    Dataset d = synthesize(so, maps, truth);
    if (form == "lab-style") lab_style(d);
    if (!data.empty()) {
      std::filesystem::create_directories(data);
      write_measured((std::filesystem::path(data) / (form + ".csv")).string(), d);
    }
    LoopOptions lo;
    lo.threads = threads;
    lo.progress = true;
    const long long e0 = lm_jacobian_row_evaluations();
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    const Design des = make_design(d, maps);
    const LoopResult r = run_loop(des, lo);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    const long long evals = lm_jacobian_row_evaluations() - e0;
    if (!summaries.empty()) {
      std::filesystem::create_directories(summaries);
      std::ofstream(std::filesystem::path(summaries) / (form + "_loop_summary.json")) << summary_json(r);
    }
    w.row({form, std::to_string(d.rows.size()), fmt(wall, 4), fmt(cpu, 4), std::to_string(r.steps.size()),
           r.steps.empty() ? "none" : r.steps[0].variable + " -> " + r.steps[0].effect, std::to_string(evals), "10"});
    std::cout << "loop on " << d.rows.size() << " rows (" << form << "): " << fmt(wall, 4) << " s wall, " << fmt(cpu, 4)
              << " s CPU, " << evals << " Jacobian row evaluations\n";
  }
  w.save(out);
  std::cout << "-> " << out << "\n";
  return 0;
}
