// Chapter 3: the Stribeck friction model (thesis Eqs. 3.1, 3.2; Tables 3.1-3.3).
// This part needs no finite-element solver: it draws the input curves of
// Fig. 3.1 for both parameter sets, locates the strip-draw verification cases
// of Table 3.2 and the draw-bend condition of Sec. 3.5 on them, and checks the
// text's numerical statements.  Units: v mm/s, p MPa, R_a um, eta Pa s.
//
// Recipe:
//   1. Load Tables 3.1-3.3.
//   2. Tabulate mu(L) for both sets (Eq. 3.2) and the log-base alternative.
//   3. Table 3.2 cases: L (Eq. 3.1) and the input mu the solver must reproduce.
//   4. The draw-bend condition of Sec. 3.5 (10 MPa, 50 mm/s).
//   5. Checks of the text's statements.
//   6. The strip-draw verification in our solver (Table 3.2, Fig. 3.8) and the
//      update interval (Figs. 3.5-3.7), Coulomb friction (Fig. 3.6), from
//      the strip-draw builder (src/sim/strip_draw_case).
//   7. Draw-bend on three pins at 10 MPa (Sec. 3.5, Figs. 3.10-3.18),
//      ch3_drawbend.cpp.
//
// Sample runs (from the source folder after `make`; the binaries are in build/chapters/):
//   chapter_ch3_stribeck --out build/chapters/ch3-stribeck
//       (the quick tier, as `ctest -R chapter.ch3-stribeck` runs it)
//   chapter_ch3_stribeck --tier full --fe-element-length 0.5 --fe-across 4
//       (the full tier's mesh (`make test-full`))
//   chapter_ch3_stribeck --fe false
//       (the tables and curves only, no FE run)
#include <cmath>

#include "analysis/stribeck.hpp"
#include "ch3_steps.hpp"
#include "sim/fe_options.hpp"
#include "study/chapter.hpp"
#include "study/thesis_data.hpp"

using namespace drawbend;
using namespace drawbend::analysis;

namespace {

// The chapter's options (main registers them; the body reads them).
struct Config {
  sim::DrawBendSpec fe;  ///< mesh and numerics of the draw-bend runs
  bool run_fe = true;    ///< --fe: step 7
  bool reuse_runs = false;
};

void body(study::Chapter& c, const Config& cfg) {
  const sim::DrawBendSpec& fe = cfg.fe;
  // 1. Inputs.
  const StribeckParams s31 = study::load_stribeck(c.data("thesis/table_3_1.csv"));
  const StribeckParams s33 = study::load_stribeck(c.data("thesis/table_3_3.csv"));
  const CsvTable t32 = read_csv(c.data("thesis/table_3_2.csv"));

  // 2. mu(L) over six decades.  The third column mixes bases as Eq. (3.2) is
  // printed (log10 over ln) to show what that reading would do to the curve.
  auto curve = c.table({"L", "mu_table_3_1", "mu_table_3_3", "mu_table_3_1_mixed_base"},
                       "Stribeck curves, Eq. (3.2); L dimensionless");
  for (double e = -6.0; e <= -0.999; e += 0.05) {
    const double L = std::pow(10.0, e);
    const double arg_mixed = std::log10(L * L / (s31.L_BL * s31.L_EHL)) / std::log(s31.L_BL / s31.L_EHL);
    const double mixed = 0.5 * ((s31.mu_BL + s31.mu_EHL) + (s31.mu_BL - s31.mu_EHL) * std::tanh(arg_mixed));
    curve.row({fmt(L, 6), fmt(stribeck_mu(L, s31), 6), fmt(stribeck_mu(L, s33), 6), fmt(mixed, 6)});
  }
  c.save(curve, "stribeck_curves");

  // 3. The strip-draw verification cases (Table 3.2) on the Table 3.1 curve.
  auto cases = c.table({"case", "pressure_MPa", "velocity_mm_s", "L", "mu_input"},
                       "Table 3.2 cases located on the Table 3.1 Stribeck curve (Eq. 3.1, 3.2)");
  double Lmin = INFINITY, Lmax = 0;
  for (const auto& r : t32.rows) {
    const double p = t32.number(r, "pressure_MPa"), v = t32.number(r, "velocity_mm_s");
    const double L = lubricant_number(v, p, s31);
    Lmin = std::min(Lmin, L);
    Lmax = std::max(Lmax, L);
    cases.row({t32.text(r, "case"), fmt(p), fmt(v), fmt(L, 4), fmt_fixed(stribeck_mu(L, s31), 4)});
  }
  c.save(cases, "table_3_2_cases");

  // 4. Draw-bend condition of Sec. 3.5: 10 MPa average pressure, 50 mm/s.
  const double p_db = study::scalar(c.data("thesis/scalars.csv"), "ch3_target_pressure").value;
  const double v_db = study::scalar(c.data("thesis/scalars.csv"), "ch3_outlet_speed").value;
  const double L_db = lubricant_number(v_db, p_db, s33);
  auto point = c.table({"L", "mu"}, "Draw-bend condition of Sec. 3.5 on the Table 3.3 curve");
  point.row({fmt(L_db, 6), fmt(stribeck_mu(L_db, s33), 6)});
  c.save(point, "drawbend_condition");
  c.value("L_db", fmt(L_db, 3));
  c.value("mu_db", fmt_fixed(stribeck_mu(L_db, s33), 4));
  c.value("p_db", fmt(p_db), "MPa");
  c.value("v_db", fmt(v_db), "mm/s");
  c.value("mu_at_LBL", fmt_fixed(stribeck_mu(s31.L_BL, s31), 4));
  c.value("mu_at_LEHL", fmt_fixed(stribeck_mu(s31.L_EHL, s31), 4));
  c.value("L_min", fmt(Lmin, 3));
  c.value("L_max", fmt(Lmax, 3));
  c.plot("stribeck", "fig_3_1",
         {{"curvefile", c.out("tables/stribeck_curves.csv")}, {"casefile", c.out("tables/table_3_2_cases.csv")},
          {"pointfile", c.out("tables/drawbend_condition.csv")}});

  // 5. Checks.
  // Properties of the input tables alone (Table 3.2 spans both transitions,
  // mu falls with speed on the Table 3.1 curve, Tables 3.1 and 3.3 differ only
  // in mu_BL) are data-file tests (tests/unit/test_thesis_tables.cpp), not
  // checks of the thesis: they cannot fail while the files stay as printed.
  const auto frac = study::scalar(c.data("thesis/scalars.csv"), "ch3_stribeck_interval_fraction");
  const double steps = study::scalar(c.data("thesis/scalars.csv"), "ch3_total_steps").value;
  const double interval = study::scalar(c.data("thesis/scalars.csv"), "ch3_stribeck_interval_steps").value;
  c.checks().rederive("ch3.interval_fraction", "update interval / total steps, percent (Sec. 3.3.2)", frac.value,
                      100.0 * interval / steps, frac.half_ulp, "%", "printed to 0.01 %: half a unit in the last place");

  // 6. The solver.
  ch3::strip_draw(c, s31, t32, study::scalar(c.data("thesis/scalars.csv"), "ch3_strip_draw_coulomb_mu").value,
                 cfg.reuse_runs);

  // 7. Draw-bend on three pins.
  c.value("db_ran", cfg.run_fe ? "yes" : "no");
  c.value("db_h", fmt(fe.element_length), "mm");
  c.value("db_across", std::to_string(fe.across));
  c.value("db_through", std::to_string(fe.through));
  if (cfg.run_fe) ch3::drawbend_pins(c, s33, fe, cfg.reuse_runs);
}

}  // namespace

int main(int argc, char** argv) {
  study::Chapter ch("ch3-stribeck", "Chapter 3: the Stribeck friction curve, its strip-draw verification and draw-bend");
  Config cfg;
  sim::add_fe_options(ch.options(), cfg.fe, cfg.run_fe, cfg.reuse_runs);
  return study::run_chapter(ch, argc, argv, [&cfg](study::Chapter& c) { body(c, cfg); });
}
