// Chapter 4: the new method.  Steps 1-5 need no finite-element solver: they
// re-derive the derived columns of Tables 4.1 and 4.2 (bending force F_B,
// friction force F_T, pressure ratio c), the back-tension stress of Sec. 4.2,
// and the conventional friction coefficients of Fig. 4.9 (Eq. 2.3) with the
// average pressures of Eq. (2.2) used as the x axis of Fig. 4.10.  Steps 6-10
// (ch4_fe.cpp) run our own draw-bend simulations and the new method on them.
// Forces are half-model simulation forces in N (the thesis models the top half
// of the 25.4 mm wide, 1.04 mm thick strip).
//
// Recipe:
//   1. Load Tables 4.1, 4.2 and the strip geometry.
//   2. Re-derive F_B = F_Y' - F_X' (Table 4.1).
//   3. Re-derive F_T = F_Y - F_X - F_B and c = (F_X+F_Y)/(F_X'+F_Y') (Table 4.2).
//   4. Back-tension stress F_X'/(t w/2) against the printed 57 MPa.
//   5. Conventional mu (Eq. 2.3) and average pressure (Eq. 2.2), Fig. 4.9.
//   6-10. Finite-element part (ch4_fe.cpp).
//
// Sample runs (from the source folder after `make`; the binaries are in build/chapters/):
//   chapter_ch4_new_method --out build/chapters/ch4-new-method
//       (the quick tier, as `ctest -R chapter.ch4-new-method` runs it)
//   chapter_ch4_new_method --tier full --fe-element-length 0.5 --fe-across 4
//       (the full tier's mesh (`make test-full`))
//   chapter_ch4_new_method --fe false
//       (steps 1-5 only: the re-derived tables, no FE run)
#include <cmath>

#include "analysis/pressure_ratio.hpp"
#include "analysis/rope.hpp"
#include "ch4_steps.hpp"
#include "sim/fe_options.hpp"
#include "study/chapter.hpp"
#include "study/thesis_data.hpp"

using namespace drawbend;
using namespace drawbend::analysis;

namespace {

void body(study::Chapter& c, const ch4::FeOptions& fe) {
  // 1. Inputs.
  const CsvTable t41 = read_csv(c.data("thesis/table_4_1.csv"));
  const CsvTable t42 = read_csv(c.data("thesis/table_4_2.csv"));
  const std::string sc = c.data("thesis/scalars.csv");
  const auto t = study::scalar(sc, "ch5_strip_thickness");
  const auto w = study::scalar(sc, "ch5_strip_width");
  const auto sigma_bt = study::scalar(sc, "ch4_back_tension_stress");
  if (t41.rows.size() != t42.rows.size()) throw InputError("Tables 4.1 and 4.2 list different pins");

  int agree = 0;
  auto out = c.table({"pin_mm", "F_B_N", "F_T_N", "c", "P_avg_rotating_MPa", "P_avg_fixed_MPa", "mu_conventional"},
                     "Tables 4.1/4.2 re-derived and the conventional method (half-model forces, N; pressures MPa)");
  for (std::size_t i = 0; i < t41.rows.size(); ++i) {
    const auto& a = t41.rows[i];
    const auto& b = t42.rows[i];
    const double pin = t41.number(a, "pin_diameter_mm");
    if (!study::same(pin, t42.number(b, "pin_diameter_mm"))) throw InputError(t42.where(b, "pin_diameter_mm") + ": pin order differs from Table 4.1");
    const auto FXp = study::printed(t41, a, "FX_prime_N"), FYp = study::printed(t41, a, "FY_prime_N");
    const auto FB = study::printed(t41, a, "FB_N");
    const auto FX = study::printed(t42, b, "FX_N"), FY = study::printed(t42, b, "FY_N");
    const auto FT = study::printed(t42, b, "FT_N"), cc = study::printed(t42, b, "c");
    const std::string id = "ch4.d" + fmt(pin);
    const std::string why = "thesis computed from its printed forces: half a unit in the last printed place";
    // 2. Bending force.
    const double FB_ours = FYp.value - FXp.value;
    agree += c.checks().rederive(id + ".T4.1.FB", "T4.1 F_B = F_Y' - F_X'", FB.value, FB_ours, FB.half_ulp, "N", why).status ==
             study::Status::pass;
    // 3. Friction force and pressure ratio.
    const double FT_ours = FY.value - FX.value - FB.value;
    agree += c.checks().rederive(id + ".T4.2.FT", "T4.2 F_T = F_Y - F_X - F_B", FT.value, FT_ours, FT.half_ulp, "N", why).status ==
             study::Status::pass;
    const double c_ours = pressure_ratio(FX.value, FY.value, FXp.value, FYp.value);
    agree += c.checks().rederive(id + ".T4.2.c", "T4.2 c = (F_X+F_Y)/(F_X'+F_Y')", cc.value, c_ours, cc.half_ulp, "-", why).status ==
             study::Status::pass;
    // 5. Conventional method on the simulated forces.
    const double r = pin / 2.0;
    const double mu = mu_rope(FX.value, FY.value, FB.value, M_PI / 2);
    const double P_rot = average_pressure(FXp.value, FYp.value, r, w.value, ForceBasis::half_model);
    const double P_fix = average_pressure(FX.value, FY.value, r, w.value, ForceBasis::half_model);
    out.row({fmt(pin), fmt_fixed(FB_ours, 1), fmt_fixed(FT_ours, 1), fmt_fixed(c_ours, 4), fmt_fixed(P_rot, 2),
             fmt_fixed(P_fix, 2), fmt_fixed(mu, 4)});
    c.value("mu_d" + fmt(pin), fmt_fixed(mu, 4));
    c.value("P_d" + fmt(pin), fmt_fixed(P_fix, 1), "MPa");
    // 4. Back-tension stress on the half-model section t x w/2.
    if (i == 0) {
      const auto f = [](const std::vector<double>& x) { return x[0] / (x[1] * x[2] / 2.0); };
      const double s = f({FXp.value, t.value, w.value});
      c.checks().rederive("ch4.back_tension_stress", "back-tension stress F_X'/(t w/2) (Sec. 4.2)", sigma_bt.value, s,
                          sigma_bt.half_ulp, "MPa",
                          "printed to 1 MPa; section t x w/2 with t = 1.04 mm, w = 25.4 mm (Sec. 5.2)");
      c.value("sigma_bt", fmt_fixed(s, 2), "MPa");
    }
  }
  c.save(out, "table_4_rederived");
  c.value("derived_agree", std::to_string(agree));
  c.value("derived_total", std::to_string(3 * t41.rows.size()));
  c.value("t", t.text, "mm");
  c.value("w_half", fmt(w.value / 2), "mm");
  c.plot("fig_4_9", "fig_4_9", {{"datafile", c.out("tables/table_4_rederived.csv")}});

  // 6-10. Our own simulations.
  c.value("fe_ran", fe.run ? "yes" : "no");
  if (fe.run) ch4::fe_study(c, fe);
}

}  // namespace

int main(int argc, char** argv) {
  study::Chapter ch("ch4-new-method", "Chapter 4: the new method, re-derived and with our own simulations");
  ch4::FeOptions fe;  // the chapter's options
  sim::add_fe_options(ch.options(), fe.base, fe.run, fe.reuse);
  return study::run_chapter(ch, argc, argv, [&fe](study::Chapter& c) { body(c, fe); });
}
