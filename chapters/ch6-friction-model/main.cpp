// Chapter 6: the new friction model mu(p, v) (thesis Eqs. 6.1-6.3, Table 6.1).
// It re-derives all 18 nodal values of Table 6.1 from the lines of Table 5.16,
// tests the printed shape functions and natural-coordinate map, and draws the
// RD surface with its nodes (Fig. 6.2); then it verifies the law in our solver
// by block sliding (Sec. 6.5, Tables 6.2-6.4, Figs. 6.8-6.10).
// Units: p MPa, v mm/s; domain p 0-80 MPa, v 6.35-101.6 mm/s (Sec. 6.3).
//
// Recipe:
//   1. Load Tables 5.16 and 6.1 and the domain (Sec. 6.3).
//   2. Build the nine nodal values per direction (Sec. 6.2, Fig. 6.2).
//   3. Check them against Table 6.1 with printed-digit tolerances.
//   4. Errata checks: printed Eq. (6.1) and Eq. (6.3).
//   5. Figure 6.2: the surface, its lines and its nodes.
//   6. Statements of Secs. 6.6.2-6.6.3 re-derived from other printed numbers.
//   7. Block sliding with the law in our solver (ch6_block.cpp).
//   8. Cup drawing (ch6_cup.cpp): coarse cases 1 and 9; --full: all nine, refined.
//
// Sample runs (from the source folder after `make`; the binaries are in build/chapters/):
//   chapter_ch6_friction_model --out build/chapters/ch6-friction-model
//       (as `ctest -R chapter.ch6-friction-model` runs it: cup cases 1 and 9)
//   chapter_ch6_friction_model --full
//       (all nine cups of Table 6.5 on the refined mesh; slow)
//   chapter_ch6_friction_model --full --cup-cases 1,9
//       (the end cases on the refined mesh: about 20 min on 2 cores)
//   chapter_ch6_friction_model --cup-material data/materials/aa5754_o_hill48_hou2020.toml
//       (the cups with Hill'48 instead of the thesis's isotropic J2)
#include <cmath>

#include "analysis/friction_surface.hpp"
#include "ch6_steps.hpp"
#include "study/chapter.hpp"
#include "study/thesis_data.hpp"

using namespace drawbend;
using namespace drawbend::analysis;

namespace {

// The chapter's options (main registers them; the body reads them).
struct Config {
  bool full = false;         ///< --full: the paper-fidelity cup-drawing runs (CTest label `full`)
  std::string cup_material;  ///< --cup-material: the cup's material (sim/material_choice.hpp); empty: the deck's
  std::string cup_cases;     ///< --cup-cases: which Table 6.5 cases (default: 1 and 9, all nine with --full)
  bool reuse_runs = false;   ///< --reuse-runs: block and cup runs whose deck is unchanged are read, not rerun
};

struct Lines {
  std::vector<double> v;
  std::vector<Printed> a0, a1;
  std::vector<SpeedLine> build(const std::vector<double>& x) const {  // x = a0..., a1...
    std::vector<SpeedLine> s;
    for (std::size_t k = 0; k < v.size(); ++k) s.push_back({v[k], Polynomial{{x[k], x[v.size() + k]}}});
    return s;
  }
  std::vector<Printed> printed() const {
    auto p = a0;
    p.insert(p.end(), a1.begin(), a1.end());
    return p;
  }
};

// 1. Inputs: Tables 5.16 and 6.1 and the domain (Sec. 6.3).
struct Inputs {
  CsvTable t516, t61;
  std::string scalars;
  double p_min = 0, p_max = 0;
};

Inputs load_inputs(const study::Chapter& c) {
  Inputs in{read_csv(c.data("thesis/table_5_16.csv")), read_csv(c.data("thesis/table_6_1.csv")),
            c.data("thesis/scalars.csv")};
  in.p_min = study::scalar(in.scalars, "ch6_p_min").value;
  in.p_max = study::scalar(in.scalars, "ch6_p_max").value;
  if (in.t61.rows.size() != 9) throw InputError(in.t61.path + ": expected 9 nodes");
  return in;
}

/// Table 5.16's three speed lines of one direction, as printed.
Lines lines_of(const CsvTable& t516, const std::string& dir) {
  Lines L;
  for (const auto& r : t516.rows)
    if (t516.text(r, "direction") == dir) {
      L.v.push_back(t516.number(r, "speed_mm_s"));
      L.a0.push_back(study::printed(t516, r, "a0"));
      L.a1.push_back(study::printed(t516, r, "a1_per_MPa"));
    }
  return L;
}

/// 3. The nine nodal values of one direction against Table 6.1; fills that
/// direction's columns of the Table 6.1 rows.
void check_nodes(study::Chapter& c, const Inputs& in, const FrictionSurface& S, const std::string& dir,
                 std::vector<std::vector<std::string>>& rows) {
  for (int k = 0; k < 9; ++k) {
    const auto& row = in.t61.rows[static_cast<std::size_t>(k)];
    const Printed thesis = study::printed(in.t61, row, "mu_" + dir);
    c.checks().rederive("ch6.T6.1." + dir + ".node" + std::to_string(k + 1),
                        "T6.1 mu at node " + std::to_string(k + 1) + ", " + dir, thesis.value, S.mu[k],
                        thesis.half_ulp, "-",
                        "thesis computed from the printed Table 5.16: half a unit in the last printed place");
    const double p = in.p_min + (in.p_max - in.p_min) * (k / 3) / 2.0;
    const double v = S.v_min + (S.v_max - S.v_min) * (k % 3) / 2.0;
    if (dir == "RD") rows[k] = {std::to_string(k + 1), fmt(p), fmt(v, 6), thesis.text, fmt_fixed(S.mu[k], 4)};
    else {
      rows[k].push_back(thesis.text);
      rows[k].push_back(fmt_fixed(S.mu[k], 4));
    }
  }
}

/// 4. The printed Eq. (6.3) maps the middle speed elsewhere; does it give Table 6.1?
void check_printed_eta(study::Chapter& c, const Inputs& in, const std::vector<SpeedLine>& lines,
                       const std::string& dir) {
  const FrictionSurface P = surface_from_lines(lines, in.p_min, in.p_max, /*use_printed_eta=*/true);
  bool printed_reproduces = true;
  for (int k = 0; k < 9; ++k)
    printed_reproduces =
        printed_reproduces && std::abs(P.mu[k] - study::printed(in.t61, in.t61.rows[k], "mu_" + dir).value) <= 1e-4;
  c.checks().claim(study::Kind::rederived, "ch6.eq6_3_as_printed_reproduces_T6.1." + dir,
                   "Table 6.1 follows from Eq. (6.3) as printed, eta = 2v/(v_max - v_min) - 1, " + dir,
                   printed_reproduces, "all nine nodes within 1e-4");
  c.value("node2_printed_" + dir, fmt_fixed(P.mu[1], 4));
  if (dir == "RD") c.value("eta_vmin_printed", fmt_fixed(P.eta_as_printed(P.v_min), 3));
}

/// 5. Figure 6.2 (and its TD companion): the surface, its lines and its nodes.
void figure_6_2(study::Chapter& c, const Inputs& in, const FrictionSurface& S, const std::vector<SpeedLine>& sl,
                const std::string& dir) {
  std::vector<double> ps, vs;
  for (int i = 0; i <= 20; ++i) ps.push_back(in.p_min + (in.p_max - in.p_min) * i / 20.0);
  for (int j = 0; j <= 20; ++j) vs.push_back(S.v_min + (S.v_max - S.v_min) * j / 20.0);
  c.save_grid("surface_" + dir, "mu(p [MPa], v [mm/s]) nine-node surface from Table 6.1 nodes, " + dir, ps, vs,
              [&S](double p, double v) { return S(p, v); });
  auto lines = c.table({"p_MPa", "v6.35", "v25.4", "v101.6"}, "Table 5.16 lines, " + dir);
  for (double p = in.p_min; p <= in.p_max + 1e-9; p += 2.0)
    lines.row({fmt(p), fmt(sl[0].mu(p), 5), fmt(sl[1].mu(p), 5), fmt(sl[2].mu(p), 5)});
  c.save(lines, "lines_" + dir);
  c.plot("mu_surface", dir == "RD" ? "fig_6_2" : "fig_6_2_TD",
         {{"dir", dir}, {"gridfile", c.out("tables/surface_" + dir + ".dat")},
          {"linesfile", c.out("tables/lines_" + dir + ".csv")}});
}

/// 4. Eq. (6.1) as printed (N5 = N4) is not a partition of unity.  That the
/// corrected set is one is an identity of our own code, tested in
/// tests/unit/test_friction_surface.cpp, not a check of the thesis.
void check_printed_shape_functions(study::Chapter& c) {
  double sum_p = 0;
  for (double n : nine_node_shape_as_printed(0.0, 0.0)) sum_p += n;
  c.checks().rederive("ch6.eq6_1_as_printed.partition_of_unity", "sum of Eq. (6.1) as printed at the centre", 1.0,
                      sum_p, 1e-12, "-", "exact arithmetic identity");
  c.value("sum_printed_centre", fmt(sum_p));
}

/// 6. Statements of Secs. 6.6.2-6.6.3 derived from other printed numbers.
void rederive_cup_statements(study::Chapter& c, const Inputs& in) {
  using V = std::vector<double>;
  c.rederive_scalar("ch6.force_drop_sim", "simulated max punch force change, case 1 to 9 (Sec. 6.6.2)",
                    "ch6_force_drop_sim", {"ch6_punch_force_sim_case9", "ch6_punch_force_sim_case1"},
                    [](const V& x) { return x[0] - x[1]; }, "kN");
  c.rederive_scalar("ch6.force_drop_exp", "measured max punch force change, case 1 to 9 (Sec. 6.6.2)",
                    "ch6_force_drop_exp", {"ch6_punch_force_exp_case9", "ch6_punch_force_exp_case1"},
                    [](const V& x) { return x[0] - x[1]; }, "kN");
  const auto excess = [](const V& x) { return 100.0 * (x[0] / x[1] - 1.0); };
  c.rederive_scalar("ch6.force_excess_case1", "simulated over measured max punch force, case 1 (Sec. 6.6.3)",
                    "ch6_force_excess_case1", {"ch6_punch_force_sim_case1", "ch6_punch_force_exp_case1"}, excess, "%");
  c.rederive_scalar("ch6.force_excess_case9", "simulated over measured max punch force, case 9 (Sec. 6.6.3)",
                    "ch6_force_excess_case9", {"ch6_punch_force_sim_case9", "ch6_punch_force_exp_case9"}, excess, "%");
  // The text's case-9 speed against Table 6.5.
  const CsvTable t65 = read_csv(c.data("thesis/table_6_5.csv"));
  const auto text_speed = study::scalar(in.scalars, "ch6_case9_speed_text");
  const auto table_speed = study::printed(t65, t65.rows.back(), "punch_speed_mm_s");
  c.checks().rederive("ch6.case9_speed", "case 9 punch speed: Sec. 6.6.2 text against Table 6.5", text_speed.value,
                      table_speed.value, 0.0, "mm/s",
                      "the same quantity printed twice to 0.1 mm/s must read the same");
}

void body(study::Chapter& c, const Config& cfg) {
  const Inputs in = load_inputs(c);  // 1.
  auto nodes = c.table({"node", "p_MPa", "v_mm_s", "mu_RD_thesis", "mu_RD_ours", "mu_TD_thesis", "mu_TD_ours"},
                       "Table 6.1 re-derived from Table 5.16 (Sec. 6.2)");
  std::vector<std::vector<std::string>> rows(9);
  for (const std::string dir : {"RD", "TD"}) {
    const Lines L = lines_of(in.t516, dir);
    std::vector<double> x;
    for (const auto& p : L.printed()) x.push_back(p.value);
    const auto lines = L.build(x);
    const FrictionSurface S = surface_from_lines(lines, in.p_min, in.p_max);  // 2.
    check_nodes(c, in, S, dir, rows);                                           // 3.
    check_printed_eta(c, in, lines, dir);                                       // 4.
    figure_6_2(c, in, S, lines, dir);                                           // 5.
  }
  for (auto& r : rows) nodes.row(r);
  c.save(nodes, "table_6_1");
  check_printed_shape_functions(c);  // 4.
  rederive_cup_statements(c, in);    // 6.
  ch6::block_sliding(c, cfg.reuse_runs);                                                 // 7. Sec. 6.5
  ch6::cup_drawing(c, cfg.full, cfg.cup_cases, cfg.cup_material, cfg.reuse_runs);       // 8. Sec. 6.6
}

}  // namespace

int main(int argc, char** argv) {
  study::Chapter ch("ch6-friction-model", "Chapter 6: the mu(p, v) friction model, block sliding and cup drawing");
  Config cfg;
  ch.options().add(cfg.reuse_runs, "reuse-runs", "block sliding and cups: reuse runs whose deck is unchanged, for development only");
  ch.options().add_flag(cfg.full, "full", "cup drawing: all nine cases of Table 6.5 on the refined mesh (slow)");
  ch.options().add(cfg.cup_cases, "cup-cases",
                   "cup drawing: comma-separated Table 6.5 case ids to run, with 1 and 9 among them (e.g. 1,9 with "
                   "--full: the end cases on the refined mesh, about 20 min on 2 cores); empty: 1,9, or all with --full");
  ch.options().add(cfg.cup_material, "cup-material",
                   "cup drawing: the material, as drawbend drawbend-deck --material (a TOML inline table of [material] "
                   "keys, e.g. '{ type = \"hill48\", hill48 = { r0 = 0.65, r45 = 0.65, r90 = 0.72 } }', or a TOML file); "
                   "empty: the deck's isotropic J2 on the Table 5.1 RD curve, as the thesis");
  return study::run_chapter(ch, argc, argv, [&cfg](study::Chapter& c) { body(c, cfg); });
}
