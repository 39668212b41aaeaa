// Chapter 3, Sec. 3.5: draw-bend simulations on three pins (12.7, 25.4 and
// 38.1 mm) at the same 10 MPa average contact pressure, with Coulomb (mu = 0.1),
// Stribeck (Table 3.3) and frictionless contact, drawn at 50 mm/s.  The
// conventional method (Eq. 2.3, forces averaged over the last third of step 3)
// retrieves mu; the pressure profiles explain why the Stribeck mu falls with
// the pin diameter (Figs. 3.10-3.18).  Forces: half model, N; MPa; mm; mm/s.
//
// Back tension per pin: Eq. (2.2) with the rope estimate F_Y = F_X e^(0.1 pi/2)
// + F_B (F_B by Swift's Eq. 2.1 with the 0.2 % yield stress of Table 5.1)
// solved for F_X at 10 MPa; the same F_X for the three friction cases, as in
// the thesis.  The average pressures the runs reach are reported.
#include <chrono>
#include <cmath>
#include <iostream>

#include "analysis/rope.hpp"
#include "ch3_steps.hpp"
#include "sim/case_pool.hpp"
#include "sim/drawbend_case.hpp"
#include "sim/fe_options.hpp"
#include "sim/map_tools.hpp"
#include "study/run_health.hpp"
#include "study/thesis_data.hpp"

namespace ch3 {

using namespace drawbend;
using namespace drawbend::analysis;

namespace {

const std::string laws[3] = {"frictionless", "coulomb", "stribeck"};

/// The chapter's numbers the runs use (data/thesis/scalars.csv, Table 5.1).
struct Inputs {
  std::string sc;
  double p_target = 0, v = 0, mu_c = 0, w_half = 0, t = 0, ys = 0;  ///< MPa, mm/s, -, mm, mm, MPa
  study::Printed ret_lo, ret_hi;                                     ///< the thesis's retrieved-mu range [%]
  std::vector<double> pins;                                          ///< [mm]
};

/// The nine runs: per pin frictionless, Coulomb, Stribeck; the back tension per pin.
struct Runs {
  std::vector<double> FXs;
  std::vector<sim::DrawBendResult> all;
};

/// What the claims compare across the pins.
struct PinTrends {
  std::vector<double> mu_c_ret, mu_s_ret, arc, peak_ratio;
};

Inputs read_inputs(study::Chapter& c) {
  Inputs in;
  in.sc = c.data("thesis/scalars.csv");
  const std::string& sc = in.sc;
  in.p_target = study::scalar(sc, "ch3_target_pressure").value;
  in.v = study::scalar(sc, "ch3_outlet_speed").value;
  in.mu_c = study::scalar(sc, "ch3_coulomb_mu_input").value;
  in.w_half = study::scalar(sc, "ch5_strip_width").value / 2;
  in.t = study::scalar(sc, "ch5_strip_thickness").value;
  in.ret_lo = study::scalar(sc, "ch3_coulomb_retrieval_min"), in.ret_hi = study::scalar(sc, "ch3_coulomb_retrieval_max");
  const CsvTable t51 = read_csv(c.data("thesis/table_5_1.csv"));
  in.ys = t51.number(t51.rows.front(), "YS02_MPa");  // RD
  in.pins = {study::scalar(sc, "ch3_pin_diameter_small").value,
            study::scalar(sc, "ch3_pin_diameter_mid").value,
            study::scalar(sc, "ch3_pin_diameter_large").value};
  return in;
}

/// The nine runs side by side (sim/case_pool.hpp).
Runs run_pins(study::Chapter& c, const Inputs& in, const sim::DrawBendSpec& base, bool reuse) {
  const double p_target = in.p_target, v = in.v, mu_c = in.mu_c, w_half = in.w_half, t = in.t, ys = in.ys;
  const std::vector<double>& pins = in.pins;
  Runs r;
  std::vector<double>& FXs = r.FXs;
  std::vector<sim::CaseJob> jobs;
  for (const double D : pins) {
    const double FB_est = swift_bending_force(ys, t, 2 * w_half, D / 2, M_PI / 2, ForceBasis::half_model);
    const double FX = (p_target * D * w_half - FB_est) / (1 + std::exp(mu_c * M_PI / 2));
    FXs.push_back(FX);
    for (int k = 0; k < 3; ++k) {
      sim::DrawBendSpec s = base;
      s.pin_diameter = D;
      s.thickness = t;
      s.width = w_half;
      s.back_tension = FX;
      s.speed = v;
      s.mass_scaling = sim::mass_scaling_for_speed(base.mass_scaling, v);  // same rho v^2 as the reference
      s.hardening = c.data("materials/aa5754_o_rd.csv");
      s.name = "ch3_d" + fmt(D) + "_" + laws[k];
      if (k == 1) s.friction = io::coulomb_friction(mu_c);
      if (k == 2) s.friction = io::stribeck_friction(c.data("thesis/table_3_3.csv"), 100);
      jobs.push_back({s, c.out("runs/" + s.name)});
    }
  }
  r.all = sim::run_drawbend_all(jobs, reuse);
  return r;
}

/// One pin's reduction: health, forces, retrieved mu, pressure profiles, its checks and figures.
void reduce_pin(study::Chapter& c, const Inputs& in, const Runs& r, std::size_t ip, const StribeckParams& s33,
                CsvWriter& tab, PinTrends& out) {
  const double D = in.pins[ip], FX = r.FXs[ip];
  const sim::DrawBendResult* res = &r.all[3 * ip];
  const double v = in.v, mu_c = in.mu_c, w_half = in.w_half;
  const auto &ret_lo = in.ret_lo, &ret_hi = in.ret_hi;
  for (int k = 0; k < 3; ++k) {
    const sim::DrawBendSpec& s = res[k].spec;
    const std::string rid = "ch3.fe.d" + fmt(D) + "." + laws[k];
    // Energy and kinetic ratio only: this chapter never claimed the hourglass ratio (its gold has no such id).
    study::check_run_health(c.checks(), rid, s.name,
                            {res[k].balance_error, res[k].kinetic_ratio, res[k].hourglass_ratio}, false);
  }
  const double FB = res[0].tension_rise();
  const double mu_cc = mu_rope(FX, res[1].F_out, FB, M_PI / 2), mu_ss = mu_rope(FX, res[2].F_out, FB, M_PI / 2);
  const double Pc = average_pressure(FX, res[1].F_out, D / 2, 2 * w_half, ForceBasis::half_model);
  const double Ps = average_pressure(FX, res[2].F_out, D / 2, 2 * w_half, ForceBasis::half_model);
  const auto rows = sim::rows_of(res[2].map);
  const auto a = sim::contact_arc(rows.front(), 0.5);
  const double ratio = sim::max_pressure(rows.front()) / std::max(res[2].mean_pressure(), 1e-12);
  out.mu_c_ret.push_back(mu_cc);
  out.mu_s_ret.push_back(mu_ss);
  out.arc.push_back(a.angle());
  out.peak_ratio.push_back(ratio);
  const double mu_curve = stribeck_mu(v, Ps, s33);
  tab.row({fmt(D), fmt_fixed(FX, 1), fmt_fixed(FB, 1), fmt_fixed(res[1].F_out, 1), fmt_fixed(res[2].F_out, 1),
           fmt_fixed(Pc, 2), fmt_fixed(Ps, 2), fmt_fixed(mu_cc, 4), fmt_fixed(mu_ss, 4), fmt_fixed(mu_curve, 4),
           fmt_fixed(a.angle(), 1), fmt_fixed(ratio, 2)});
  const std::string d = fmt(D);
  c.value("db_FX_d" + d, fmt_fixed(FX, 1), "N");
  c.value("db_P_d" + d, fmt_fixed(Ps, 1), "MPa");
  c.value("db_muc_d" + d, fmt_fixed(mu_cc, 4));
  c.value("db_mus_d" + d, fmt_fixed(mu_ss, 4));
  c.value("db_retrieved_d" + d, fmt_fixed(100 * mu_cc / mu_c, 1), "%");
  c.value("db_curve_d" + d, fmt_fixed(mu_curve, 4));               // the input curve at P_avg
  c.value("db_over_curve_d" + d, fmt_fixed(mu_ss / mu_curve, 2));  // retrieved over that (the disagreement note)
  c.value("db_peak_ratio_d" + d, fmt_fixed(ratio, 2));            // largest centre-row pressure over the mean
  c.value("db_arc_d" + d, fmt_fixed(a.angle(), 0), "deg");
  // Sec. 3.5.2: "the input friction coefficient of 0.1 was well retrieved (95
  // to 97%)".  Tolerance from the thesis's own numbers (stated before the
  // run): the printed range over its three pins, 95-97 %, widened by half a
  // printed unit at each end.
  c.checks().agree(study::Kind::simulated, "ch3.fe.d" + d + ".coulomb_retrieved",
                   "Coulomb mu retrieved by Eq. (2.3), percent of input, pin " + d + " mm",
                   0.5 * (ret_lo.value + ret_hi.value), 100 * mu_cc / mu_c,
                   0.5 * (ret_hi.value - ret_lo.value) + ret_lo.half_ulp, "%",
                   "the thesis's printed range 95-97 % over its pins + half a printed unit");
  // Fig. 3.14: the retrieved Stribeck mu "comes close to the coefficient based
  // on the Stribeck curve" at the test's average pressure and speed.
  c.checks().agree(study::Kind::simulated, "ch3.fe.d" + d + ".stribeck_vs_curve", "Stribeck mu by Eq. (2.3) vs the input curve at P_avg, pin " + d + " mm",
                   mu_curve, mu_ss, 0.15 * mu_curve, "-",
                   "15 %: Fig. 3.14 shows the retrieved values near, not on, the curve; the pressure peaks raise them");
  for (int k = 0; k < 3; ++k) {
    const std::string stem = "ch3_map_d" + d + "_" + laws[k];
    sim::save_row_profiles(res[k].map, c.out("tables/" + stem + ".csv"), "row profiles, " + stem);
  }
  sim::save_map_grid(res[2].map, c.out("tables/ch3_grid_d" + d + "_stribeck.dat"),
                     "contact pressure [MPa], pin " + d + " mm, Stribeck, 10 MPa average");
  c.plot("row_profiles", "fig_3_profiles_d" + d,
         {{"datafile", c.out("tables/ch3_map_d" + d + "_stribeck.csv")},
          {"title_text", "Row pressure profiles, " + d + " mm pin, Stribeck, 10 MPa average"}});
  if (D == in.pins.front())
    c.plot("pressure_map", "fig_3_15",
           {{"gridfile", c.out("tables/ch3_grid_d" + d + "_stribeck.dat")},
            {"title_text", "Pressure map, " + d + " mm pin, Stribeck (Fig. 3.15)"}});
}

/// Sec. 3.5.3's trends with the pin diameter.
void pin_claims(study::Chapter& c, const PinTrends& tr) {
  const std::vector<double> &mu_s_ret = tr.mu_s_ret, &arc = tr.arc, &peak_ratio = tr.peak_ratio;
  auto falls = [](const std::vector<double>& x) { return x[0] > x[1] && x[1] > x[2]; };
  auto rises = [](const std::vector<double>& x) { return x[0] < x[1] && x[1] < x[2]; };
  c.checks().claim(study::Kind::simulated, "ch3.fe.stribeck_mu_falls", "Stribeck mu by Eq. (2.3) falls with pin diameter (Fig. 3.13)",
                   falls(mu_s_ret), fmt(mu_s_ret[0], 4) + ", " + fmt(mu_s_ret[1], 4) + ", " + fmt(mu_s_ret[2], 4));
  c.checks().claim(study::Kind::simulated, "ch3.fe.contact_arc_grows", "real contact angle grows with pin diameter (Sec. 3.5.3)", rises(arc),
                   fmt(arc[0], 3) + ", " + fmt(arc[1], 3) + ", " + fmt(arc[2], 3) + " deg");
  c.checks().claim(study::Kind::simulated, "ch3.fe.pressure_evens_out", "peak/mean pressure falls with pin diameter (Sec. 3.5.3)",
                   falls(peak_ratio), fmt(peak_ratio[0], 3) + ", " + fmt(peak_ratio[1], 3) + ", " + fmt(peak_ratio[2], 3));
}

}  // namespace

void drawbend_pins(study::Chapter& c, const StribeckParams& s33, const sim::DrawBendSpec& base, bool reuse) {
  const Inputs in = read_inputs(c);
  const auto wall0 = std::chrono::steady_clock::now();
  auto tab = c.table({"pin_mm", "F_X_N", "F_B_N", "F_Y_coulomb_N", "F_Y_stribeck_N", "P_avg_coulomb_MPa",
                      "P_avg_stribeck_MPa", "mu_coulomb", "mu_stribeck", "mu_stribeck_curve_at_P_avg",
                      "contact_deg_centre_row", "p_max_over_mean"},
                     "draw-bend at 10 MPa average pressure (Sec. 3.5): forces on the half model [N], Eq. (2.3) mu");
  const Runs r = run_pins(c, in, base, reuse);
  PinTrends trends;
  for (std::size_t ip = 0; ip < in.pins.size(); ++ip) reduce_pin(c, in, r, ip, s33, tab, trends);
  c.save(tab, "drawbend_10mpa");
  c.plot("mu_vs_pin", "fig_3_13", {{"datafile", c.out("tables/drawbend_10mpa.csv")}});
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  c.value("db_wall", fmt_fixed(wall / 60.0, 1), "min");
  pin_claims(c, trends);
}

}  // namespace ch3
