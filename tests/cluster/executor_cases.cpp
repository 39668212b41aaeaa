// Three small draw-bend cases through the case pool, written to OUT/cases.csv
// (every result to 17 significant digits), then a small block slide and strip
// draw (OUT/kinds.csv, the same way) and the first 2 mm of Chapter 6's cup
// (OUT/cups.csv), with their run folders under
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
#include "sim/block_case.hpp"
#include "sim/case_pool.hpp"
#include "sim/cup_case.hpp"
#include "sim/fe_options.hpp"
#include "sim/strip_draw_case.hpp"

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
      if (k == 2) s.friction = io::coulomb_friction(0.1);
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
    // The other file-level kinds (sim/deck_job.hpp), small: a block slide and a
    // strip draw, reduced from their folders' reduction.csv.
    sim::BlockSpec b = sim::default_block_spec(DRAWBEND_DATA_DIR);
    b.name = "block0";
    b.elements = 2;
    b.direction_deg = 30;
    sim::StripDrawSpec st = sim::default_strip_draw_spec(DRAWBEND_DATA_DIR);
    st.name = "strip0";
    st.nx = 4, st.ny = 2, st.nz = 2;
    st.slide = 0.1;
    const sim::BlockResult rb = sim::run_blocks({b}, out + "/runs", true).at(0);
    const sim::StripDrawResult rs = sim::run_strip_draws({st}, out + "/runs", true).at(0);
    CsvWriter k({"case", "mu_x", "mu_y", "mu", "v_mean_mm_s", "p_mean_MPa", "cycles"});
    auto g = [](double v) {
      char t[40];
      std::snprintf(t, sizeof t, "%.17g", v);
      return std::string(t);
    };
    k.row({b.name, g(rb.mu_x), g(rb.mu_y), "", g(rb.v_mean), "", std::to_string(rb.cycles)});
    k.row({st.name, "", "", g(rs.mu), g(rs.v_mean), g(rs.p_mean), std::to_string(rs.cycles)});
    // A cup (sim/cup_case, kind cup_draw), its first 2 mm: curve, end state and fields from its folder.
    sim::CupSpec cup;
    cup.deck = std::string(DRAWBEND_DATA_DIR) + "/cases/cup_draw.toml";
    cup.stroke = 2;
    cup.cycles = 2000;
    const sim::CupResult rc = sim::draw_cup_job(cup, out + "/runs/cup0", true);
    k.row({"cup0", "", "", "", "", "", std::to_string(rc.cycles)});
    CsvWriter cw({"case", "punch_force_N", "die_force_N", "size_rd_mm", "max_strain", "max_strain_angle_deg", "points"});
    cw.row({"cup0", g(rc.curve.back().second), g(rc.die_force), g(rc.size_rd), g(rc.max_strain), g(rc.max_strain_angle),
            std::to_string(rc.curve.size())});
    cw.save(out + "/cups.csv");
    k.save(out + "/kinds.csv");
    return 0;
  });
}
