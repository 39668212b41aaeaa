// Chapter 4, finite-element part: our own draw-bend simulations of the three
// pins of Tables 4.1/4.2 (12.7, 25.4 and 42 mm) at the back tension of Sec. 4.2
// (756.2 N on the half model = 57 MPa), frictionless (the rotating pin, F_B and
// the pressure maps P') and with the Stribeck law (the fixed pin, F_T and c),
// then the new method (Eqs. 4.2-4.5) back-predicting the input Stribeck curve
// from our forces and maps (Fig. 4.10), the conventional method's bias
// (Fig. 4.9) and the areas per pressure range (Fig. 4.11).
// Forces: half model, N.  Pressures MPa, lengths mm, speeds mm/s.
//
// Recipe (fe_study, one named step a line):
//   1. run_pins: six runs, three pins x {frictionless, Stribeck (Table 3.3)}
//      at 50 mm/s, and the 42 mm pin frictionless on the alternative Swift fit.
//   2. tables_4_fe: our Tables 4.1/4.2 beside the thesis's; checks and trends.
//   3. maps_and_histories: pressure maps (Figs. 4.2-4.5; exported for
//      Chapter 7), row profiles and force histories.
//   4. new_method: the new method on our maps and forces, orders 1 and 2
//      (Fig. 4.10), and the conventional method's bias.
//   5. pressure_areas: areas per pressure range (Fig. 4.11).
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <cmath>
#include <iostream>

#include "analysis/pressure_ratio.hpp"
#include "analysis/rope.hpp"
#include "analysis/stribeck.hpp"
#include "core/run_output.hpp"
#include "fe/mesh.hpp"
#include "io/deck.hpp"
#include "material/swift_fit.hpp"
#include "ch4_steps.hpp"
#include "sim/case_pool.hpp"
#include "sim/fe_options.hpp"
#include "sim/map_tools.hpp"
#include "study/run_health.hpp"
#include "study/thesis_data.hpp"

namespace ch4 {

using namespace drawbend;
using namespace drawbend::analysis;

namespace {

/// The thesis's inputs of the finite-element part.
struct Inputs {
  std::string sc;  ///< data/thesis/scalars.csv
  CsvTable t41, t42;
  StribeckParams law;  ///< Table 3.3
  double v = 0;        ///< outlet speed [mm/s]
  double w_half = 0;   ///< half the strip width [mm] (the half model)
  double t_strip = 0;  ///< strip thickness [mm]
};

struct PinRuns {
  double D = 0;
  sim::DrawBendResult free, strib;
};

/// The runs of step 1: per pin frictionless and Stribeck, and the 42 mm
/// frictionless run on the alternative Swift fit.
struct Runs {
  std::vector<PinRuns> pins;
  sim::DrawBendResult alt42;
};

/// Step 2's derived quantities per pin, in the order of Tables 4.1/4.2.
struct Derived {
  std::vector<PinTest> pins;
  std::vector<double> FB, FT, cs, mu_conv, P_avg;
};

Inputs load_inputs(const study::Chapter& c) {
  Inputs in;
  in.sc = c.data("thesis/scalars.csv");
  in.t41 = read_csv(c.data("thesis/table_4_1.csv"));
  in.t42 = read_csv(c.data("thesis/table_4_2.csv"));
  in.law = study::load_stribeck(c.data("thesis/table_3_3.csv"));
  in.v = study::scalar(in.sc, "ch4_outlet_speed").value;
  in.w_half = study::scalar(in.sc, "ch5_strip_width").value / 2;
  in.t_strip = study::scalar(in.sc, "ch5_strip_thickness").value;
  return in;
}

/// Draw-step force histories of two runs on one time base, for the figure.
void save_histories(study::Chapter& c, const PinRuns& r, const std::string& name) {
  auto w = c.table({"time_s", "F_back_N", "F_out_frictionless_N", "F_out_stribeck_N"},
                   "draw-step tension forces, pin " + fmt(r.D) + " mm (half model, N)");
  const auto a = r.free.draw_series(sim::Signal::outlet_force, -1), b = r.strib.draw_series(sim::Signal::outlet_force, -1);
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    w.row({fmt(a[i].first, 6), fmt(r.free.F_back, 6), fmt(a[i].second, 6), fmt(b[i].second, 6)});
  c.save(w, name);
}

/// Step 1's jobs: per pin of Table 4.1, frictionless and Stribeck.  Mass
/// scaling keeps the inertia of the draw (rho v^2) equal to that of the
/// reference run (1e4 at 100 mm/s), so the step-3 dynamics do not change with
/// the thesis's 50 mm/s; the Stribeck law sees the real speed.
std::vector<sim::CaseJob> pin_jobs(const study::Chapter& c, const FeOptions& o, const Inputs& in) {
  std::vector<sim::CaseJob> jobs;  // per pin: frictionless, Stribeck; run side by side
  for (const auto& row : in.t41.rows) {
    sim::DrawBendSpec s = o.base;
    s.pin_diameter = in.t41.number(row, "pin_diameter_mm");
    s.thickness = in.t_strip;
    s.width = in.w_half;
    s.back_tension = in.t41.number(row, "FX_prime_N");
    s.speed = in.v;
    s.mass_scaling = sim::mass_scaling_for_speed(o.base.mass_scaling, in.v);
    s.hardening = c.data("materials/aa5754_o_rd.csv");
    s.name = "ch4_d" + fmt(s.pin_diameter) + "_frictionless";
    jobs.push_back({s, c.out("runs/" + s.name)});
    s.name = "ch4_d" + fmt(s.pin_diameter) + "_stribeck";
    s.friction = io::stribeck_friction(c.data("thesis/table_3_3.csv"), 100);
    jobs.push_back({s, c.out("runs/" + s.name)});
  }
  return jobs;
}

/// The stated cause of ch4.fe.d42.FB (the low-strain part of the flow curve),
/// tested: the 42 mm frictionless run (`free42`) again on the other reading
/// of Table 5.1's 0.2 % yield stress.  The shipped tables take it as the
/// proof stress, the flow stress at eps_p = 0.002 (issue 51); the
/// alternative is the reading they held until then, the curve's initial
/// flow stress at eps_p = 0 (fit_swift(..., 0): an initial yield about 8 %
/// higher, under 1 % change beyond eps_p = 0.05).  Writes the fit's table.
sim::CaseJob swift_alternative_job(const study::Chapter& c, const sim::CaseJob& free42) {
  const CsvTable t51 = read_csv(c.data("thesis/table_5_1.csv"));
  const auto& rd = t51.rows.front();
  const material::SwiftLaw alt =
      material::fit_swift(t51.number(rd, "YS02_MPa"), t51.number(rd, "UTS_MPa"), t51.number(rd, "n"), 0.0);
  CsvWriter w({"plastic_strain", "true_stress_MPa"});
  w.comment("AA5754-O RD, Swift fit with the 0.2 % yield stress at eps_p = 0 (fit_swift(..., 0), the shipped "
            "tables' reading until issue 51): K = " +
            fmt(alt.K, 10) + " MPa, eps0 = " + fmt(alt.eps0, 10) + ", n = " + fmt(alt.n));
  w.comment("units: plastic_strain: -; true_stress_MPa: MPa");
  for (double e : material::swift_table_strains())
    w.row({fmt(e, 6), fmt_fixed(alt.stress(e), material::swift_table_stress_decimals)});
  const std::string path = c.out("tables/aa5754_o_rd_swift_eps_y_0.csv");
  w.save(path);
  sim::DrawBendSpec s = free42.spec;
  s.hardening = std::filesystem::absolute(path).string();  // the deck resolves relative paths from its own dir
  s.name += "_swift_eps_y_0";
  return {s, c.out("runs/" + s.name)};
}

/// Re-analysis of a run's kinetic energy at the end of the draw (the
/// quasi-static check's KE/IE): how much of it is the whole strip moving at
/// the draw speed, 1/2 m v^2, with m the strip's scaled mass read from the
/// run's own deck (element volumes x density x mass scaling).  A steady draw
/// carries that energy whatever its forces; only the rest is vibration.
/// Values ke_ie_<key>, ke_uniform_<key> (1/2 m v^2 over KE) and
/// ke_rest_ie_<key> ((KE - 1/2 m v^2) / IE), all in %.
void kinetic_reanalysis(study::Chapter& c, const sim::DrawBendResult& r, const std::string& key) {
  const io::Deck deck = io::read_deck(r.dir + "/deck.toml");
  const fe::Mesh& m = deck.model.mesh;
  double volume = 0;
  for (const auto& h : m.hex) {
    double x[8], y[8], z[8];
    for (int k = 0; k < 8; ++k) x[k] = m.x[h[k]], y[k] = m.y[h[k]], z[k] = m.z[h[k]];
    volume += fe::hex_volume(x, y, z);
  }
  const double mass = volume * deck.model.material->density() * deck.model.mass_scaling;  // [t]
  const double ke_uniform = 0.5 * mass * r.spec.speed * r.spec.speed;                    // [mJ]
  const double ke = r.draw_series(sim::Signal::kinetic).back().second;
  const double ie = r.draw_series(sim::Signal::internal).back().second;
  c.value("ke_ie_" + key, fmt_fixed(100 * ke / ie, 2), "%");
  c.value("ke_uniform_" + key, fmt_fixed(100 * ke_uniform / ke, 1), "%");
  c.value("ke_rest_ie_" + key, fmt_fixed(100 * (ke - ke_uniform) / ie, 2), "%");
}

/// Step 1: the runs side by side, their wall time, the alternative fit's
/// F_B against the thesis's, and the mesh of the runs.
Runs run_pins(study::Chapter& c, const FeOptions& o, const Inputs& in) {
  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<sim::CaseJob> jobs = pin_jobs(c, o, in);
  jobs.push_back(swift_alternative_job(c, jobs[jobs.size() - 2]));  // the 42 mm frictionless run
  std::vector<sim::DrawBendResult> all = sim::run_drawbend_all(jobs, o.reuse);
  Runs runs;
  runs.alt42 = std::move(all.back());
  all.pop_back();
  for (std::size_t i = 0; i + 1 < all.size(); i += 2) {
    PinRuns r;
    r.D = all[i].spec.pin_diameter;
    r.free = std::move(all[i]);
    r.strib = std::move(all[i + 1]);
    runs.pins.push_back(std::move(r));
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  c.value("fe_wall", fmt_fixed(wall / 60.0, 1), "min");
  const sim::DrawBendResult& alt42 = runs.alt42;
  const double fb_base = runs.pins.back().free.tension_rise(), fb_alt = alt42.tension_rise();
  const double fb_thesis = in.t41.number(in.t41.rows.back(), "FB_N");
  c.value("FB_d42_alt", fmt_fixed(fb_alt, 1), "N");
  c.value("FB_d42_alt_change", fmt_fixed(100 * (fb_alt - fb_base) / fb_base, 1), "%");
  c.value("FB_d42_alt_vs_thesis", fmt_fixed(100 * (fb_alt - fb_thesis) / fb_thesis, 1), "%");
  const std::string rid = "ch4.fe.d42.frictionless_swift_eps_y_0";
  study::check_run_health(c.checks(), rid, alt42.spec.name,
                          {alt42.balance_error, alt42.kinetic_ratio, alt42.hourglass_ratio});
  kinetic_reanalysis(c, alt42, "d42_alt");
  c.value("fe_speed", fmt(in.v), "mm/s");
  c.value("fe_h", fmt(o.base.element_length), "mm");
  c.value("fe_across", std::to_string(o.base.across));
  c.value("fe_through", std::to_string(o.base.through));
  c.value("fe_ms", fmt(sim::mass_scaling_for_speed(o.base.mass_scaling, in.v)));
  return runs;
}

/// Step 2: Tables 4.1/4.2, ours beside the thesis's; checks per pin and the
/// trends the chapter states.
Derived tables_4_fe(study::Chapter& c, const Inputs& in, const std::vector<PinRuns>& runs) {
  const CsvTable &t41 = in.t41, &t42 = in.t42;
  auto tab = c.table({"pin_mm", "FXp_N", "FYp_thesis_N", "FYp_ours_N", "FB_thesis_N", "FB_ours_N", "FY_thesis_N",
                      "FY_ours_N", "FT_thesis_N", "FT_ours_N", "c_thesis", "c_ours", "mu_conv_ours", "P_avg_ours_MPa"},
                     "Tables 4.1/4.2: thesis and our FE (half-model forces, N)");
  Derived d;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& r = runs[i];
    const auto& a = t41.rows[i];
    const auto& b = t42.rows[i];
    const double FXp = r.free.F_back, FYp = r.free.F_out, FX = r.strib.F_back, FY = r.strib.F_out;
    d.FB.push_back(FYp - FXp);
    d.FT.push_back(FY - FX - d.FB.back());
    d.cs.push_back(pressure_ratio(FX, FY, FXp, FYp));
    d.mu_conv.push_back(mu_rope(FX, FY, d.FB.back(), M_PI / 2));
    d.P_avg.push_back(average_pressure(FX, FY, r.D / 2, 2 * in.w_half, ForceBasis::half_model));
    const std::string id = "ch4.fe.d" + fmt(r.D);
    const std::string dm = fmt(r.D);
    // F_B: our flow curve is a Swift fit to the NGTC tensile data (Table 5.1);
    // the thesis's input curve is not printed, and F_B scales with the flow
    // stress at the bending strain (about 8 % on the 12.7 mm pin).
    c.checks().agree(study::Kind::simulated, id + ".FB", "T4.1 bending force F_B, pin " + dm + " mm", t41.number(a, "FB_N"),
                     d.FB.back(), 0.10 * t41.number(a, "FB_N"), "N",
                     "10 %: different hardening input (Swift fit of Table 5.1) and code (H3DMAP vs ours)");
    c.checks().agree(study::Kind::simulated, id + ".FT", "T4.2 friction force F_T, pin " + dm + " mm", t42.number(b, "FT_N"),
                     d.FT.back(), 0.15 * t42.number(b, "FT_N"), "N",
                     "15 %: F_T is a difference of forces, and mu(p) of Table 3.3 weighs the pressure peaks, "
                     "which depend on mesh and contact algorithm");
    // c: with F_X = F_X' (the same back tension), c - 1 = F_T/(F_X' + F_Y')
    // exactly, so c carries F_T's relative uncertainty on c - 1 only (stated
    // before the run): 15 % of the thesis's c - 1, plus half its printed digit.
    const auto c_printed = study::printed(t42, b, "c");
    c.checks().agree(study::Kind::simulated, id + ".c", "T4.2 pressure ratio c, pin " + dm + " mm", c_printed.value,
                     d.cs.back(), 0.15 * (c_printed.value - 1) + c_printed.half_ulp, "-",
                     "c - 1 = F_T/(F_X'+F_Y'): F_T's 15 % on c - 1, + half the printed digit");
    tab.row({dm, fmt_fixed(FXp, 1), t41.text(a, "FY_prime_N"), fmt_fixed(FYp, 1), t41.text(a, "FB_N"),
             fmt_fixed(d.FB.back(), 1), t42.text(b, "FY_N"), fmt_fixed(FY, 1), t42.text(b, "FT_N"),
             fmt_fixed(d.FT.back(), 1), t42.text(b, "c"), fmt_fixed(d.cs.back(), 4), fmt_fixed(d.mu_conv.back(), 4),
             fmt_fixed(d.P_avg.back(), 2)});
    c.value("FB_d" + dm, fmt_fixed(d.FB.back(), 1), "N");
    c.value("FB_vs_thesis_d" + dm, fmt_fixed(100 * (d.FB.back() / t41.number(a, "FB_N") - 1), 1), "%");
    c.value("FT_d" + dm, fmt_fixed(d.FT.back(), 1), "N");
    c.value("FT_vs_thesis_d" + dm, fmt_fixed(100 * (d.FT.back() / t42.number(b, "FT_N") - 1), 1), "%");
    // The friction the law applies on the Stribeck run's end-of-draw map,
    // sum of mu(v, p) p A over its nodes, beside F_T (a difference of forces).
    double ft_map = 0, pmax_strib = 0;
    for (const auto& q : r.strib.map) {
      if (q.pressure > 0) ft_map += stribeck_mu(in.v, q.pressure, in.law) * q.pressure * q.area;
      pmax_strib = std::max(pmax_strib, q.pressure);
    }
    c.value("FT_map_d" + dm, fmt_fixed(ft_map, 1), "N");
    c.value("pmax_stribeck_d" + dm, fmt_fixed(pmax_strib, 1), "MPa");
    c.value("c_d" + dm, fmt_fixed(d.cs.back(), 3));
    c.value("mufe_d" + dm, fmt_fixed(d.mu_conv.back(), 4));
    // Quasi-static invariants of the runs (printed by each run, checked here).
    for (const auto* x : {&r.free, &r.strib}) {
      const std::string rid = id + (x == &r.free ? ".frictionless" : ".stribeck");
      study::check_run_health(c.checks(), rid, x->spec.name, {x->balance_error, x->kinetic_ratio, x->hourglass_ratio});
      kinetic_reanalysis(c, *x, "d" + dm + (x == &r.free ? "_frictionless" : "_stribeck"));
    }
    PinTest pt;
    pt.map = r.free.pressure_map("pin " + dm + " mm, frictionless");
    pt.c = d.cs.back();
    pt.friction_force_N = d.FT.back();
    d.pins.push_back(pt);
  }
  c.save(tab, "table_4_fe");
  // Trends the chapter states: F_B, F_T and c fall as the pin grows (Tables
  // 4.1/4.2) and so does the conventional mu (Fig. 4.9, Sec. 4.3).
  auto falls = [](const std::vector<double>& x) { return x[0] > x[1] && x[1] > x[2]; };
  c.checks().claim(study::Kind::simulated, "ch4.fe.FB_falls", "F_B falls with pin diameter (Table 4.1)", falls(d.FB), "ours");
  c.checks().claim(study::Kind::simulated, "ch4.fe.FT_falls", "F_T falls with pin diameter (Table 4.2)", falls(d.FT), "ours");
  c.checks().claim(study::Kind::simulated, "ch4.fe.c_falls", "c falls with pin diameter (Table 4.2)", falls(d.cs), "ours");
  c.checks().claim(study::Kind::simulated, "ch4.fe.mu_conv_falls", "conventional mu falls with pin diameter (Fig. 4.9)",
                   falls(d.mu_conv),
                   "ours: " + fmt(d.mu_conv[0], 4) + ", " + fmt(d.mu_conv[1], 4) + ", " + fmt(d.mu_conv[2], 4));
  return d;
}

/// Step 3: maps, profiles, histories.  The frictionless maps are also
/// exported in the format of `drawbend loop --maps` (Chapter 7):
/// maps/pin_<D>mm.csv, the solver's contact map with the full-strip reference
/// back tension stated.
void maps_and_histories(study::Chapter& c, const std::vector<PinRuns>& runs) {
  std::filesystem::create_directories(c.out("maps"));
  for (const auto& r : runs) {
    const std::string d = fmt(r.D);
    {
      std::ifstream in(r.free.map_file);
      std::stringstream text;
      text << run_output::pin_map_header(2 * r.free.F_back,
                                         "full strip; the map is the half model's, frictionless, pin " + d + " mm")
           << in.rdbuf();
      write_file_atomic(c.out("maps/" + run_output::pin_map_name(d)), text.str());
    }
    for (const auto* x : {&r.free, &r.strib}) {
      const bool fr = x == &r.free;
      const std::string stem = "map_d" + d + (fr ? "_frictionless" : "_stribeck");
      sim::save_map_grid(x->map, c.out("tables/" + stem + ".dat"),
                         "contact pressure map [MPa], pin " + d + " mm, " + (fr ? "frictionless" : "Stribeck"));
      c.plot("pressure_map", stem,
             {{"gridfile", c.out("tables/" + stem + ".dat")},
              {"title_text", "Pressure map, " + d + " mm pin, " + (fr ? "frictionless" : "Stribeck (Table 3.3)")}});
      sim::save_row_profiles(x->map, c.out("tables/rows_" + stem + ".csv"), "row profiles, " + stem);
    }
    c.plot("row_profiles", "rows_d" + d,
           {{"datafile", c.out("tables/rows_map_d" + d + "_frictionless.csv")},
            {"title_text", "Row profiles, " + d + " mm pin, frictionless"}});
    save_histories(c, r, "forces_d" + d);
    c.plot("force_history", "forces_d" + d,
           {{"datafile", c.out("tables/forces_d" + d + ".csv")}, {"title_text", "Tension forces, " + d + " mm pin"}});
    const auto rows = sim::rows_of(r.free.map);
    c.value("pmax_d" + d, fmt_fixed(sim::max_pressure(rows.front()), 1), "MPa");
    double pmax = 0;
    for (const auto& q : r.free.map) pmax = std::max(pmax, q.pressure);
    c.value("pmaxall_d" + d, fmt_fixed(pmax, 1), "MPa");
  }
}

/// Step 4: the new method on our maps and forces (Eqs. 4.2-4.5), orders 1 and
/// 2, against the input Stribeck curve at the draw speed; the conventional
/// method's bias.
void new_method(study::Chapter& c, const Inputs& in, const std::vector<PinRuns>& runs, const Derived& d) {
  const double v = in.v;
  const NewMethodResult n1 = solve_new_method(d.pins, 1), n2 = solve_new_method(d.pins, 2);
  const double p_split = study::scalar(in.sc, "ch4_valid_pressure_range_max").value;  // 40 MPa
  auto curve = c.table({"p_MPa", "mu_input", "mu_new_order1", "mu_new_order2"},
                       "input Stribeck mu(p) at " + fmt(v) + " mm/s and the new method's back-prediction");
  double err_lo = 0, err_hi = 0, p_top = 0;
  for (const auto& q : runs[0].free.map) p_top = std::max(p_top, q.pressure);
  for (double p = 1; p <= std::max(p_top, 60.0) + 1e-9; p += 1.0) {
    const double mu_in = stribeck_mu(v, p, in.law);
    curve.row({fmt(p), fmt(mu_in, 5), fmt(n1.mu(p), 5), fmt(n2.mu(p), 5)});
    const double e = std::abs(n2.mu(p) - mu_in) / mu_in;
    (p <= p_split ? err_lo : err_hi) = std::max(p <= p_split ? err_lo : err_hi, e);
  }
  c.save(curve, "new_method_curve");
  auto pts = c.table({"pin_mm", "P_avg_MPa", "mu_conventional"}, "conventional mu (Eq. 2.3) at Eq. (2.2) pressure");
  for (std::size_t i = 0; i < runs.size(); ++i)
    pts.row({fmt(runs[i].D), fmt_fixed(d.P_avg[i], 2), fmt_fixed(d.mu_conv[i], 4)});
  c.save(pts, "conventional_points");
  c.plot("fig_4_10", "fig_4_10",
         {{"curvefile", c.out("tables/new_method_curve.csv")}, {"pointsfile", c.out("tables/conventional_points.csv")}});
  c.value("err_lo", fmt_fixed(100 * err_lo, 1), "%");
  c.value("err_hi", fmt_fixed(100 * err_hi, 1), "%");
  c.value("p_split", fmt(p_split), "MPa");
  c.value("p_top", fmt_fixed(p_top, 1), "MPa");
  c.value("n2_a0", fmt(n2.mu.a[0], 4));
  c.value("n2_a1", fmt(n2.mu.a[1], 4));
  c.value("n2_a2", fmt(n2.mu.a[2], 4));
  c.value("n2_cond", fmt(n2.condition, 3));
  // The deviation of the second-order back-prediction from the input at
  // 1 MPa and at the 12.7 mm map's peak (the ends of the data).
  c.value("n2_dev_1", fmt_fixed(n2.mu(1.0) - stribeck_mu(v, 1.0, in.law), 4));
  c.value("n2_dev_top", fmt_fixed(n2.mu(p_top) - stribeck_mu(v, p_top, in.law), 4));
  c.value("mu_in_1", fmt_fixed(stribeck_mu(v, 1.0, in.law), 4));
  // Sec. 4.4: "The new method well predicted the input Stribeck friction curve
  // in the range from 0 MPa to 40 MPa": within 5 % of the input there.
  c.checks().claim(study::Kind::simulated, "ch4.fe.new_method_0_40", "new method (2nd order) within 5 % of the input over 0-40 MPa (Sec. 4.4)",
                   err_lo < 0.05, "largest relative error " + fmt(100 * err_lo, 3) + " %");
  // Sec. 4.4: "the conventional method overestimates the friction coefficients":
  // mu_conv above the input mu at its own average pressure, every pin.
  bool over = true;
  for (std::size_t i = 0; i < runs.size(); ++i) over = over && d.mu_conv[i] > stribeck_mu(v, d.P_avg[i], in.law);
  c.checks().claim(study::Kind::simulated, "ch4.fe.conventional_overestimates", "conventional mu above the input mu at P_avg, all pins (Fig. 4.10)",
                   over, "ours");
}

/// Step 5: contact area per pressure range, all pins (Fig. 4.11: 12.7 mm pin).
void pressure_areas(study::Chapter& c, const Inputs& in, const std::vector<PinRuns>& runs) {
  const double p_split = study::scalar(in.sc, "ch4_valid_pressure_range_max").value;  // 40 MPa
  const std::vector<double> edges{0, 10, 20, 30, 40, 50, 60, 70, 80};
  std::vector<std::string> head{"range_MPa"};
  std::vector<std::vector<double>> areas;
  for (const auto& r : runs) {
    head.push_back("area_d" + fmt(r.D) + "_mm2");
    areas.push_back(sim::area_by_pressure(r.free.map, edges));
  }
  auto ar = c.table(head, "contact area [mm^2] per pressure range, frictionless maps (half model)");
  for (std::size_t k = 0; k < edges.size(); ++k) {
    std::vector<std::string> row{k + 1 < edges.size() ? fmt(edges[k]) + "-" + fmt(edges[k + 1]) : ">" + fmt(edges[k])};
    for (const auto& a : areas) row.push_back(fmt_fixed(a[k], 2));
    ar.row(row);
  }
  c.save(ar, "pressure_areas");
  c.plot("pressure_areas", "fig_4_11",
         {{"datafile", c.out("tables/pressure_areas.csv")}, {"title_text", "Contact area per pressure range"}});
  double above = 0, total = 0;
  for (std::size_t k = 0; k < edges.size(); ++k) (edges[k] >= p_split ? above : total) += areas[0][k];
  total += above;
  c.value("area_above_split", fmt_fixed(100 * above / std::max(total, 1e-12), 1), "%");
  // Sec. 4.4: "Pressures over 40 MPa exist only at small areas of 12.7 mm pin":
  // some area above 40 MPa, but less than 10 % of the contact.  A map without
  // any area above 40 MPa does not test the claim and fails it.
  c.checks().claim(study::Kind::simulated, "ch4.fe.small_area_above_40",
                   "some, but under 10 %, of the 12.7 mm pin's contact above 40 MPa (Sec. 4.4)",
                   above > 0 && above < 0.10 * total,
                   fmt(100 * above / std::max(total, 1e-12), 3) + " % above 40 MPa");
}

}  // namespace

void fe_study(study::Chapter& c, const FeOptions& o) {
  const Inputs in = load_inputs(c);
  const Runs runs = run_pins(c, o, in);                    // 1. the runs
  const Derived d = tables_4_fe(c, in, runs.pins);         // 2. Tables 4.1/4.2, ours beside the thesis's
  maps_and_histories(c, runs.pins);                        // 3. maps, profiles, histories
  new_method(c, in, runs.pins, d);                         // 4. the new method (Fig. 4.10)
  pressure_areas(c, in, runs.pins);                        // 5. areas per pressure range (Fig. 4.11)
}

}  // namespace ch4
