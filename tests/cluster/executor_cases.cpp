// Three small draw-bend cases through the case pool, written to OUT/cases.csv
// (every result to 17 significant digits) with their run folders under
// OUT/runs/: the driver of tests/cluster/executor_check.sh, which runs it with
// each executor (local, command, slurm; sim/executor.hpp) and compares the
// outputs byte for byte.  The cases are the quick tier's draw-bend deck
// (sim::quick_deck_spec) on a shorter draw: different pins and back tensions,
// one with Coulomb friction, so that a case mixed up with another would show.
//
//   executor_cases --out DIR [--draw MM]
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "cli/exit_codes.hpp"
#include "core/csv.hpp"
#include "core/options.hpp"
#include "sim/case_pool.hpp"
#include "sim/fe_options.hpp"

using namespace drawbend;

int main(int argc, char** argv) {
  return cli::with_exit_codes([&] {
    std::string out;
    double draw = 3;
    Options opt("executor_cases", "three short draw-bend cases through the case pool and DRAWBEND_EXECUTOR");
    opt.add(out, "out", "output folder");
    opt.add(draw, "draw", "slide of the draw step [mm]");
    if (!opt.parse(argc, argv)) return 0;
    if (out.empty()) throw InputError("--out is required");
    std::vector<sim::CaseJob> jobs;
    const double pins[3] = {12.7, 25.4, 12.7};
    const double back[3] = {756.2, 900, 600};
    for (int k = 0; k < 3; ++k) {
      sim::DrawBendSpec s = sim::quick_deck_spec();
      s.name = "case" + std::to_string(k);
      s.pin_diameter = pins[k];
      s.back_tension = back[k];
      s.draw_length = draw;
      s.snapshots = 2;
      if (k == 2) s.friction = "{ law = \"coulomb\", mu = 0.1 }";
      jobs.push_back({s, out + "/runs/" + s.name});
    }
    const auto res = sim::run_drawbend_all(jobs, true);
    CsvWriter w({"case", "F_back_N", "F_out_N", "F_out_regression_N", "F_out_std_N", "balance_error",
                 "hourglass_ratio", "max_penetration_mm", "cycles", "map_nodes", "mean_pressure_MPa"});
    for (const auto& r : res) {
      char b[10][40];
      const double v[9] = {r.F_back, r.F_out, r.F_out_regression, r.F_out_std, r.balance_error, r.hourglass_ratio,
                           r.max_penetration, static_cast<double>(r.cycles), r.mean_pressure()};
      for (int i = 0; i < 9; ++i) std::snprintf(b[i], sizeof b[i], "%.17g", v[i]);
      w.row({r.spec.name, b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7], std::to_string(r.map.size()), b[8]});
    }
    w.save(out + "/cases.csv");
    return 0;
  });
}
