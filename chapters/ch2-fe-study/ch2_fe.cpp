// Chapter 2, finite-element part: our draw-bend simulations of the 12.7 mm pin
// with Coulomb mu = 0.1 and frictionless contact (Secs. 2.2-2.4): the contact
// pressure map and row profiles (Figs. 2.6-2.10), the real contact angle, the
// inside and outside strains (Figs. 2.11-2.17), the tension forces and the
// retrieved mu (Figs. 2.19-2.20, Eq. 2.3), the mass-scaling comparison
// (Fig. 2.5) and mesh convergence; the section view and the stress and
// plastic strain along the strip (Figs. 2.8, 2.15, 2.16) in ch2_fields.cpp.
// Half model: forces in N; MPa; mm; s.
//
// Recipe (fe_study: one named step a call):
//   1. runs: Coulomb 0.1 and frictionless at the chapter mesh; frictionless at
//      a lower mass scaling; both at a finer mesh (convergence); penalty variants.
//   2. pressure_map_and_arc, pressure_peaks, max_pressure_difference: the
//      pressure map, row profiles, contact arc and peaks.
//   3. tracked_strains, mid_wrap_strain, steady_strain_distribution,
//      steady_state: strain histories and the steady state.
//   4. forces: F_B against Swift, mu by Eq. (2.3).
//   5. mass_scaling_and_convergence.
#include <array>
#include <chrono>
#include <map>
#include <cmath>
#include <iostream>

#include "analysis/rope.hpp"
#include "ch2_steps.hpp"
#include "sim/case_pool.hpp"
#include "sim/map_tools.hpp"
#include "study/run_health.hpp"
#include "study/thesis_data.hpp"

namespace ch2 {

using namespace drawbend;
using namespace drawbend::analysis;

namespace {

constexpr double threshold = 0.5;  // MPa: contact where the pressure exceeds this

/// The chapter's runs and the inputs the steps share.
struct Runs {
  std::string sc;                     ///< data/thesis/scalars.csv
  double t = 0, w_half = 0;           ///< strip thickness and half width [mm]
  sim::DrawBendSpec s, s_ms, s_fine;  ///< the chapter mesh, the lower mass scaling, the finer mesh
  std::array<double, 2> penalty_scale{0.3, 3.0};
  /// mu = 0.1 (fr), frictionless (ff), frictionless at the lower mass scaling (fm), frictionless
  /// and mu = 0.1 on the finer mesh (gf, gr), then the penalty variants of fr.
  std::vector<sim::DrawBendResult> all;
};

struct Forces {
  double FB = 0, mu = 0;  ///< bending force [N], mu by Eq. (2.3)
};

/// Sliding distance [mm] after which the outlet force stays within `band` of
/// its final level (mean of the last third), from the start of the draw.
double steady_distance(const sim::DrawBendResult& r, double band) {
  double last_out = 0;
  for (const auto& [t, f] : r.draw_series(sim::Signal::outlet_force, -1))  // the grip pulls along -z
    if (std::abs(f - r.F_out) > band * r.F_out) last_out = t;
  return last_out * r.spec.speed;  // the speed ramp is short: slide ~ speed x time
}

// 1. Runs.
Runs runs(study::Chapter& c, const FeOptions& o) {
  Runs R;
  R.sc = c.data("thesis/scalars.csv");
  const std::string& sc = R.sc;
  const CsvTable t41 = read_csv(c.data("thesis/table_4_1.csv"));
  const double mu_in = study::scalar(sc, "ch2_mu_input").value;
  R.w_half = study::scalar(sc, "ch5_strip_width").value / 2;
  R.t = study::scalar(sc, "ch5_strip_thickness").value;
  const double w_half = R.w_half, t = R.t;

  // Chapter 2 states neither pin nor back tension: the 12.7 mm pin
  // and 57 MPa of Chapter 4 (Table 4.1), drawn at 100 mm/s.
  sim::DrawBendSpec& s = R.s;
  s = o.base;
  s.pin_diameter = 12.7;
  s.thickness = t;
  s.width = w_half;
  s.back_tension = t41.number(t41.rows.front(), "FX_prime_N");
  s.speed = 100.0;
  s.hardening = c.data("materials/aa5754_o_rd.csv");
  const auto wall0 = std::chrono::steady_clock::now();
  const io::FrictionSpec coulomb = io::coulomb_friction(mu_in);
  sim::DrawBendSpec& s_ms = R.s_ms;
  s_ms = s;
  s_ms.mass_scaling = o.low_mass_scaling;
  sim::DrawBendSpec& s_fine = R.s_fine;
  s_fine = s;
  s_fine.element_length = o.fine_element_length;
  std::vector<sim::CaseJob> jobs;
  auto job = [&](sim::DrawBendSpec x, const std::string& name, const std::optional<io::FrictionSpec>& friction) {
    x.name = name;
    x.friction = friction;
    jobs.push_back({x, c.out("runs/" + name)});
  };
  job(s, "ch2_coulomb", coulomb);
  job(s, "ch2_frictionless", std::nullopt);
  job(s_ms, "ch2_frictionless_low_mass_scaling", std::nullopt);
  job(s_fine, "ch2_frictionless_fine", std::nullopt);
  job(s_fine, "ch2_coulomb_fine", coulomb);
  // Contact-penalty variants of the mu = 0.1 run (chapter mesh): do the
  // penalty stiffness and the pressure threshold move the contact arc's exit
  // end (ch2.fe.contact_end)?  About 80 s each on the quick mesh.
  const std::array<double, 2>& penalty_scale = R.penalty_scale;
  for (double k : penalty_scale) {
    sim::DrawBendSpec sp = s;
    sp.penalty = s.penalty * k;
    job(sp, "ch2_coulomb_penalty_x" + fmt(k), coulomb);
  }
  R.all = sim::run_drawbend_all(jobs, o.reuse);  // side by side
  const std::vector<sim::DrawBendResult>& all = R.all;
  const sim::DrawBendResult &fr = all[0], &ff = all[1], &fm = all[2], &gf = all[3], &gr = all[4];
  c.value("fe_wall", fmt_fixed(std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count() / 60, 1),
          "min");
  c.value("fe_h", fmt(s.element_length), "mm");
  c.value("fe_h_fine", fmt(s_fine.element_length), "mm");
  c.value("fe_across", std::to_string(s.across));
  c.value("fe_through", std::to_string(s.through));
  c.value("fe_ms", fmt(s.mass_scaling));
  c.value("fe_ms_low", fmt(s_ms.mass_scaling));
  c.value("fe_FX", fmt(s.back_tension), "N");
  for (const auto* r : {&fr, &ff, &fm, &gf, &gr, &all[5], &all[6]})
    study::check_run_health(c.checks(), "ch2.fe." + r->spec.name, r->spec.name,
                            {r->balance_error, r->kinetic_ratio, r->hourglass_ratio});
  return R;
}

// 2. Pressure map, rows and the contact arc; returns the arc on the chapter mesh.
sim::ContactArc pressure_map_and_arc(study::Chapter& c, const Runs& R) {
  const sim::DrawBendSpec &s = R.s, &s_fine = R.s_fine;
  const sim::DrawBendResult &fr = R.all[0], &gr = R.all[4];
  const std::string& sc = R.sc;
  // mu = 0.1, end of the draw.
  sim::save_map_grid(fr.map, c.out("tables/map_coulomb.dat"), "contact pressure [MPa], 12.7 mm pin, mu = 0.1");
  c.plot("pressure_map", "fig_2_6", {{"gridfile", c.out("tables/map_coulomb.dat")},
                                     {"title_text", "Contact pressure, 12.7 mm pin, μ = 0.1 (Fig. 2.6)"}});
  sim::save_row_profiles(fr.map, c.out("tables/rows_coulomb.csv"), "row profiles, 12.7 mm pin, mu = 0.1");
  c.plot("row_profiles", "fig_2_7", {{"datafile", c.out("tables/rows_coulomb.csv")},
                                     {"title_text", "Pressure along the rows, centre (y = 0) to edge (Fig. 2.7)"}});
  const auto rows = sim::rows_of(fr.map);
  const auto& centre = rows.front();
  const sim::ContactArc arc = sim::contact_arc(centre, threshold);
  const double node_deg = s.element_length / (s.pin_diameter / 2) * 180 / M_PI;  // node spacing round the pin
  const double node_deg_fine = s_fine.element_length / (s.pin_diameter / 2) * 180 / M_PI;
  const auto thesis_start = study::scalar(sc, "ch2_contact_start"), thesis_end = study::scalar(sc, "ch2_contact_end");
  const auto thesis_angle = study::scalar(sc, "ch2_contact_angle");
  // The arc is compared on the finer of our two meshes (the mu = 0.1 run at
  // fe-fine-element-length).  Tolerance, stated before the run: the finer
  // value's discretisation error, estimated as its change from the chapter
  // mesh (at least half a node spacing of the finer mesh, since the ends are
  // interpolated between nodes), plus half the thesis's last printed digit.
  const sim::ContactArc arc_f = sim::contact_arc(sim::rows_of(gr.map).front(), threshold);
  auto arc_tol = [&](double coarse, double fine, double half_ulp) {
    return std::max(std::abs(coarse - fine), 0.5 * node_deg_fine) + half_ulp;
  };
  const std::string res = "finer mesh (" + fmt(s_fine.element_length) + " mm) against the thesis; tolerance: its " +
                          "change from the " + fmt(s.element_length) + " mm mesh (at least half a node spacing, " +
                          fmt(0.5 * node_deg_fine, 3) + " deg) + half the printed digit";
  c.checks().agree(study::Kind::simulated, "ch2.fe.contact_start", "real contact start angle, centre row, finer mesh",
                   thesis_start.value, arc_f.start_deg,
                   arc_tol(arc.start_deg, arc_f.start_deg, thesis_start.half_ulp), "deg", res);
  c.checks().agree(study::Kind::simulated, "ch2.fe.contact_end", "real contact end angle, centre row, finer mesh",
                   thesis_end.value, arc_f.end_deg, arc_tol(arc.end_deg, arc_f.end_deg, thesis_end.half_ulp), "deg", res);
  c.checks().agree(study::Kind::simulated, "ch2.fe.contact_angle", "real contact angle, centre row, finer mesh",
                   thesis_angle.value, arc_f.angle(), arc_tol(arc.angle(), arc_f.angle(), thesis_angle.half_ulp), "deg",
                   res);
  // The disagreement's stated cause, tested: the contact arc against the
  // pressure threshold (0.1-2 MPa) and the penalty (x0.3, x1, x3) on the chapter
  // mesh, and against the mesh.
  {
    auto sens = c.table({"run", "penalty", "threshold_MPa", "start_deg", "end_deg", "arc_deg"},
                        "contact arc of the centre row (mu = 0.1) against the pressure threshold, the contact "
                        "penalty and the mesh");
    const std::array<double, 4> thresholds{0.1, 0.5, 1.0, 2.0};
    auto add = [&](const sim::DrawBendResult& r, const std::string& name) {
      for (double th : thresholds) {
        const auto a = sim::contact_arc(sim::rows_of(r.map).front(), th);
        sens.row({name, fmt(r.spec.penalty), fmt(th), fmt_fixed(a.start_deg, 2), fmt_fixed(a.end_deg, 2),
                  fmt_fixed(a.angle(), 2)});
      }
    };
    add(fr, fr.spec.name);
    add(gr, gr.spec.name);
    for (std::size_t k = 0; k < R.penalty_scale.size(); ++k) add(R.all[5 + k], R.all[5 + k].spec.name);
    c.save(sens, "contact_arc_sensitivity");
    c.value("arc_end_penalty_soft", fmt_fixed(sim::contact_arc(sim::rows_of(R.all[5].map).front(), threshold).end_deg, 1),
            "deg");
    c.value("arc_end_penalty_stiff",
            fmt_fixed(sim::contact_arc(sim::rows_of(R.all[6].map).front(), threshold).end_deg, 1), "deg");
    c.value("arc_end_thr_0.1", fmt_fixed(sim::contact_arc(centre, 0.1).end_deg, 1), "deg");
    c.value("arc_end_thr_2", fmt_fixed(sim::contact_arc(centre, 2.0).end_deg, 1), "deg");
  }
  c.value("arc_fine_start", fmt_fixed(arc_f.start_deg, 1), "deg");
  c.value("arc_fine_end", fmt_fixed(arc_f.end_deg, 1), "deg");
  c.value("arc_fine", fmt_fixed(arc_f.angle(), 1), "deg");
  c.value("arc_start", fmt_fixed(arc.start_deg, 1), "deg");
  c.value("arc_end", fmt_fixed(arc.end_deg, 1), "deg");
  c.value("arc", fmt_fixed(arc.angle(), 1), "deg");
  c.value("node_deg", fmt_fixed(node_deg, 1), "deg");
  return arc;
}

// 2. Pressure peaks at entry, exit and mid-wrap; the edge free of contact.
void pressure_peaks(study::Chapter& c, const Runs& R) {
  const sim::DrawBendSpec &s = R.s, &s_fine = R.s_fine;
  const sim::DrawBendResult &fr = R.all[0], &gr = R.all[4];
  const auto rows = sim::rows_of(fr.map);
  const auto& centre = rows.front();
  const auto& edge = rows.back();
  const sim::Peaks pc = sim::peaks(centre), pe = sim::peaks(edge);
  c.value("peak_entry", fmt_fixed(pc.entry, 1), "MPa");
  c.value("peak_entry_deg", fmt_fixed(pc.entry_deg, 1), "deg");
  c.value("peak_exit", fmt_fixed(pc.exit, 1), "MPa");
  c.value("peak_exit_deg", fmt_fixed(pc.exit_deg, 1), "deg");
  c.value("p_middle", fmt_fixed(pc.middle, 1), "MPa");
  c.value("edge_max", fmt_fixed(sim::max_pressure(edge), 1), "MPa");
  c.value("edge_middle", fmt_fixed(pe.middle, 1), "MPa");
  c.value("p_mean", fmt_fixed(fr.mean_pressure(), 1), "MPa");
  // Sec. 2.3.1: peaks at entry and exit above the mid-wrap pressure.
  c.checks().claim(study::Kind::simulated, "ch2.fe.entry_exit_peaks", "pressure peaks at entry and exit above mid-wrap (Sec. 2.3.1)",
                   pc.entry > pc.middle && pc.exit > pc.middle,
                   "entry " + fmt(pc.entry, 3) + ", mid " + fmt(pc.middle, 3) + ", exit " + fmt(pc.exit, 3) + " MPa");
  // Sec. 2.3.1 (Fig. 2.7): "the outlet side pressure peak is somewhat higher
  // than the inlet side peak".  A claim on the centre row; it must hold on
  // both meshes, or the mesh decides it.
  const sim::Peaks pcf = sim::peaks(sim::rows_of(gr.map).front());
  c.value("peak_entry_fine", fmt_fixed(pcf.entry, 1), "MPa");
  c.value("peak_exit_fine", fmt_fixed(pcf.exit, 1), "MPa");
  // The prose states what this tier's meshes found (the full tier's finest mesh reverses it).
  const bool both_above = pc.exit > pc.entry && pcf.exit > pcf.entry;
  c.value("peak_order", both_above ? "The outlet peak is higher than the inlet one on both meshes, as the thesis says (Fig. 2.7)."
                                   : "The outlet peak is not higher than the inlet one on both meshes, against the thesis's "
                                     "Fig. 2.7: the ordering is not mesh-converged (see the check and its documented "
                                     "disagreement).");
  c.checks().claim(study::Kind::simulated, "ch2.fe.outlet_peak_above_inlet",
                   "outlet pressure peak above the inlet peak, centre row, both meshes (Sec. 2.3.1, Fig. 2.7)",
                   both_above,
                   "exit/entry " + fmt(pc.exit, 3) + "/" + fmt(pc.entry, 3) + " MPa (" + fmt(s.element_length) +
                       " mm), " + fmt(pcf.exit, 3) + "/" + fmt(pcf.entry, 3) + " MPa (" +
                       fmt(s_fine.element_length) + " mm)");
  // Sec. 2.3.1 (Fig. 2.8): "the strip edge deforms outward to become free of
  // contact at the edge".  The edge row carries less than the contact
  // threshold over the middle of the wrap (45 deg), on both meshes.
  const sim::Peaks pef = sim::peaks(sim::rows_of(gr.map).back());
  c.checks().claim(study::Kind::simulated, "ch2.fe.edge_free_of_contact",
                   "strip edge free of contact at mid-wrap, both meshes (Sec. 2.3.1, Fig. 2.8)",
                   pe.middle < threshold && pef.middle < threshold,
                   "edge-row pressure at 45 deg " + fmt(pe.middle, 3) + " MPa (" + fmt(s.element_length) + " mm), " +
                       fmt(pef.middle, 3) + " MPa (" + fmt(s_fine.element_length) + " mm); threshold " +
                       fmt(threshold) + " MPa");
}

// 2. Maximum pressure, frictionless against mu = 0.1; returns the mu = 0.1 maximum.
double max_pressure_difference(study::Chapter& c, const Runs& R) {
  const sim::DrawBendResult &fr = R.all[0], &ff = R.all[1], &gf = R.all[3], &gr = R.all[4];
  const std::string& sc = R.sc;
  // Sec. 2.3.1: the frictionless maximum pressure is 1.2 % below the mu = 0.1
  // one.  Compared on the finer mesh; tolerance (stated before the run): the
  // change of the same difference between the two meshes, plus half the
  // printed digit (0.05 %).  A single-node maximum is mesh-sensitive, so this
  // tolerance may exceed the effect: then the check says so (it cannot claim
  // the sign).
  auto max_p = [](const std::vector<sim::MapNode>& m) {
    double p = 0;
    for (const auto& q : m) p = std::max(p, q.pressure);
    return p;
  };
  const double pmax_r = max_p(fr.map), pmax_f = max_p(ff.map);
  const double dmax = 100 * (pmax_r - pmax_f) / pmax_r;
  const double dmax_fine = 100 * (max_p(gr.map) - max_p(gf.map)) / max_p(gr.map);
  const auto dmax_thesis = study::scalar(sc, "ch2_max_pressure_frictionless_diff");
  c.value("pmax_diff", fmt_fixed(dmax, 1), "%");
  c.value("pmax_diff_fine", fmt_fixed(dmax_fine, 1), "%");
  c.value("pmax_coulomb", fmt_fixed(pmax_r, 1), "MPa");
  c.checks().agree(study::Kind::simulated, "ch2.fe.max_pressure_frictionless_diff",
                   "max pressure, mu = 0.1 over frictionless, percent, finer mesh", dmax_thesis.value, dmax_fine,
                   std::abs(dmax - dmax_fine) + dmax_thesis.half_ulp, "%",
                   "change of the difference between the two meshes + half the printed digit");
  return pmax_r;
}

// 3. Strains of the tracked section.
void tracked_strains(study::Chapter& c, const Runs& R) {
  const sim::DrawBendSpec &s = R.s;
  const sim::DrawBendResult &fr = R.all[0], &ff = R.all[1], &gf = R.all[3], &gr = R.all[4];
  const std::string& sc = R.sc;
  const double t = R.t;
  // Inside = contact side, outside = free side.
  auto st = c.table({"slide_mm", "strain_inside", "strain_outside"},
                    "longitudinal log strain of the tracked section vs slide in the draw step (mu = 0.1)");
  double eo_max = 0, ei_min = 0;
  {
    const auto in = fr.draw_series(sim::Signal::strain_inside), out = fr.draw_series(sim::Signal::strain_outside);
    for (std::size_t i = 0; i < in.size(); ++i) {  // same rows: one history
      const double ei = in[i].second, eo = out[i].second;
      eo_max = std::max(eo_max, eo);
      ei_min = std::min(ei_min, ei);
      st.row({fmt(in[i].first * s.speed, 5), fmt(ei, 5), fmt(eo, 5)});
    }
  }
  c.save(st, "strains");
  c.plot("strains", "fig_2_11", {{"datafile", c.out("tables/strains.csv")}});
  // Pure bending of the mid-surface onto the pin: outside strain
  // ln(1 + (t/2)/(R + t/2)); tension moves the neutral axis inwards, so the
  // outside strain must exceed it and the inside strain stay above -it.
  const double eb = std::log(1 + (t / 2) / (s.pin_diameter / 2 + t / 2));
  c.value("eps_out_max", fmt_fixed(100 * eo_max, 2), "%");
  c.value("eps_in_min", fmt_fixed(100 * ei_min, 2), "%");
  c.value("eps_bend", fmt_fixed(100 * eb, 2), "%");
  // Sec. 2.3.2: the frictionless run has a 1.6 % higher maximum strain than
  // the mu = 0.1 run.  Maximum outside strain of the tracked section over the
  // draw, compared on the finer mesh; tolerance (stated before the run): the
  // change of the same difference between the two meshes + half the printed
  // digit (0.05 %).
  auto max_outside = [](const sim::DrawBendResult& r) {
    double m = 0;
    for (const auto& [t, e] : r.draw_series(sim::Signal::strain_outside)) m = std::max(m, e);
    return m;
  };
  const double de = 100 * (max_outside(ff) - max_outside(fr)) / max_outside(fr);
  const double de_fine = 100 * (max_outside(gf) - max_outside(gr)) / max_outside(gr);
  const auto de_thesis = study::scalar(sc, "ch2_max_strain_frictionless_diff");
  c.value("eps_diff", fmt_fixed(de, 2), "%");
  c.value("eps_diff_fine", fmt_fixed(de_fine, 2), "%");
  c.checks().agree(study::Kind::simulated, "ch2.fe.max_strain_frictionless_diff",
                   "max outside strain, frictionless over mu = 0.1, percent, finer mesh (Sec. 2.3.2)", de_thesis.value,
                   de_fine, std::abs(de - de_fine) + de_thesis.half_ulp, "%",
                   "change of the difference between the two meshes + half the printed digit");
  c.checks().claim(study::Kind::simulated, "ch2.fe.outside_strain_above_bending", "peak outside strain above pure bending ln(1+t/(2R+t))",
                   eo_max > eb, fmt(100 * eo_max, 3) + " % vs " + fmt(100 * eb, 3) + " %");
}

// 3. Outside strain at mid-wrap and at the exit tangent against the slide.
void mid_wrap_strain(study::Chapter& c, const Runs& R) {
  const sim::DrawBendResult &fr = R.all[0];
  auto mw = c.table({"slide_mm", "outside_strain_at_mid_wrap", "outside_strain_at_exit"},
                    "outside log strain of the section at mid-wrap and at the exit tangent against the slide in the "
                    "draw (mu = 0.1); empty where no tracked section is there");
  {
    const auto mid = fr.wrap_strain(0.5), ex = fr.wrap_strain(1.0);
    std::map<long, std::array<std::string, 2>> by_slide;  // keyed by slide in um
    for (const auto& [sl, e] : mid) by_slide[std::lround(sl * 1000)][0] = fmt(e, 6);
    for (const auto& [sl, e] : ex) by_slide[std::lround(sl * 1000)][1] = fmt(e, 6);
    for (const auto& [k, v] : by_slide) mw.row({fmt(k / 1000.0, 5), v[0], v[1]});
  }
  c.save(mw, "mid_wrap_strain");
  c.plot("mid_wrap_strain", "fig_2_steady", {{"datafile", c.out("tables/mid_wrap_strain.csv")}});
}

// 3. The steady strain along the strip (Fig. 2.13) and Wilson's linear rise; the field figures.
void steady_strain_distribution(study::Chapter& c, const Runs& R) {
  const sim::DrawBendSpec &s = R.s;
  const sim::DrawBendResult &fr = R.all[0], &gr = R.all[4];
  const double Lw = sim::wrap_length(s);
  // Fig. 2.13: the steady distribution of the outside strain along the strip,
  // from upstream of the entry tangent (fraction < 0) to downstream of the exit
  // (> 1): the last section to pass each place, at the end of the draw, on
  // both meshes.  Only the outside surface is tracked by section.
  {
    auto sd = c.table({"position_mm", "fraction_of_wrap", "outside_strain", "outside_strain_fine"},
                      "steady outside log strain along the strip at the end of the draw (mu = 0.1), position from "
                      "the entry tangent along the strip (wrap length " + fmt(Lw, 4) + " mm)");
    for (int k = -10; k <= 20; ++k) {
      const double f = k / 10.0;
      const auto a = fr.wrap_strain(f), b = gr.wrap_strain(f);
      if (a.empty() || b.empty()) continue;
      sd.row({fmt(f * Lw, 5), fmt(f, 3), fmt(a.back().second, 6), fmt(b.back().second, 6)});
    }
    c.save(sd, "steady_strain_distribution");
    // Sec. 2.3.2 against Wilson et al. (1991): the strain rises at the inlet
    // and stays "rather constant" in the contact, where Wilson assumed a
    // linear rise from inlet to outlet.  A linear rise would put 60 % of the
    // rise (upstream at -0.5 wrap to the middle) across the middle 60 % of the
    // contact (0.2 to 0.8 of the wrap); the claim: less than a quarter there,
    // on both meshes.
    auto steady = [](const sim::DrawBendResult& r, double f) {
      const auto e = r.wrap_strain(f);
      return e.empty() ? NAN : e.back().second;
    };
    auto share = [&](const sim::DrawBendResult& r) {
      double lo = 1e300, hi = -1e300;  // range over 0.2, 0.3, ..., 0.8 of the wrap
      for (int k = 2; k <= 8; ++k) {
        lo = std::min(lo, steady(r, k / 10.0));
        hi = std::max(hi, steady(r, k / 10.0));
      }
      return (hi - lo) / std::abs(steady(r, 0.5) - steady(r, -0.5));
    };
    const double sh = share(fr), sh_f = share(gr);
    c.value("wilson_share", fmt_fixed(100 * sh, 1), "%");
    c.value("wilson_share_fine", fmt_fixed(100 * sh_f, 1), "%");
    c.checks().claim(study::Kind::simulated, "ch2.fe.strain_constant_in_contact",
                     "steady outside strain ranges over 0.2-0.8 of the wrap by < 1/4 of its rise to mid-wrap, both "
                     "meshes (Sec. 2.3.2, against Wilson's linear rise)",
                     sh < 0.25 && sh_f < 0.25,
                     fmt(100 * sh, 3) + " % and " + fmt(100 * sh_f, 3) + " % of the rise; a linear rise gives 60 %");
    // Figs. 2.8, 2.15, 2.16 and Fig. 2.13's inside curve from the strip's
    // last snapshot (ch2_fields.cpp).
    field_figures(c, fr, gr);
    c.plot("strain_distribution", "fig_2_13", {{"datafile", c.out("tables/steady_strain_distribution.csv")},
                                               {"insidefile", c.out("tables/inside_strain.csv")},
                                               {"insidefinefile", c.out("tables/inside_strain_fine.csv")},
                                               {"wrapfile", fmt(Lw, 5)}});
  }
}

// 3. The slide to the steady state against the wrap length.
void steady_state(study::Chapter& c, const Runs& R) {
  const sim::DrawBendSpec &s = R.s;
  const sim::DrawBendResult &fr = R.all[0];
  const std::string& sc = R.sc;
  // The steady state (Sec. 2.3.2: the strains reach a uniform distribution):
  // the whole wrap is steady once the strip leaving it, at the exit tangent,
  // has a steady strain (within 2 % of its last value).  Also at mid-wrap,
  // and for the outlet force (within 2 % of its final level).
  const double Lw = sim::wrap_length(s);
  const double d_force = steady_distance(fr, 0.02), d_strain = fr.steady_strain_slide(0.02, 1.0);
  const double d_mid = fr.steady_strain_slide(0.02, 0.5);
  c.value("d_steady_mid", fmt_fixed(d_mid, 1), "mm");
  c.value("ratio_steady_mid", fmt_fixed(d_mid / Lw, 2));
  c.value("wrap_length", fmt_fixed(Lw, 1), "mm");
  c.value("d_steady_force", fmt_fixed(d_force, 1), "mm");
  c.value("d_steady_strain", fmt_fixed(d_strain, 1), "mm");
  c.value("ratio_steady_strain", fmt_fixed(d_strain / Lw, 2));
  c.value("ratio_steady_force", fmt_fixed(d_force / Lw, 2));
  c.checks().agree(study::Kind::simulated, "ch2.fe.steady_ratio", "slide to steady strain / wrap length (Sec. 2.3.2)",
                   study::scalar(sc, "ch2_steady_ratio").value, d_strain / Lw, 0.3, "-",
                   "0.3: sections one element length apart (0.09 of the wrap at 1 mm) and the 2 % band, "
                   "where the thesis read its plots");
  c.checks().claim(study::Kind::health, "ch2.fe.steady_before_window", "outlet force steady before the last third that is averaged",
                   d_force < (2.0 / 3.0) * sim::draw_length(s),
                   fmt(d_force, 3) + " mm of " + fmt(sim::draw_length(s), 3));
}

// 4. Forces: F_B against Swift, mu by Eq. (2.3).
Forces forces(study::Chapter& c, const Runs& R) {
  const sim::DrawBendSpec &s = R.s;
  const sim::DrawBendResult &fr = R.all[0], &ff = R.all[1];
  const std::string& sc = R.sc;
  const double t = R.t, w_half = R.w_half;
  const double FB = ff.tension_rise();
  const double mu = mu_rope(fr.F_back, fr.F_out, FB, M_PI / 2);
  const double mu_reg = mu_rope(fr.F_back, fr.F_out_regression, ff.F_out_regression - ff.F_back, M_PI / 2);
  const CsvTable t51 = read_csv(c.data("thesis/table_5_1.csv"));
  const double swift = swift_bending_force(t51.number(t51.rows.front(), "YS02_MPa"), t, 2 * w_half,
                                           s.pin_diameter / 2, M_PI / 2, ForceBasis::half_model);
  c.value("FB_ours", fmt_fixed(FB, 1), "N");
  c.value("FB_swift", fmt_fixed(swift, 1), "N");
  c.value("FB_ratio", fmt_fixed(FB / swift, 2));
  c.value("mu_ours", fmt_fixed(mu, 4));
  c.value("mu_ours_reg", fmt_fixed(mu_reg, 4));
  c.value("FY_coulomb", fmt_fixed(fr.F_out, 1), "N");
  const auto fb_lo = study::scalar(sc, "ch2_sim_bending_force_min"), fb_hi = study::scalar(sc, "ch2_sim_bending_force_max");
  c.checks().agree(study::Kind::simulated, "ch2.fe.FB", "bending force F_B, frictionless (Sec. 2.3.3)", 0.5 * (fb_lo.value + fb_hi.value), FB,
                   0.5 * (fb_hi.value - fb_lo.value), "N", "the thesis's own range of simulated values");
  c.checks().agree(study::Kind::simulated, "ch2.fe.mu_retrieved", "mu retrieved by Eq. (2.3), input 0.1 (Sec. 2.3.3)",
                   study::scalar(sc, "ch2_mu_retrieved").value, mu, 0.005, "-",
                   "5 % of the input: the retrieval error is the bending reactions' normal force, which depends on "
                   "bending stiffness at entry and exit");
  auto fh = c.table({"time_s", "F_back_N", "F_out_frictionless_N", "F_out_mu0.1_N"},
                    "draw-step tension forces, 12.7 mm pin (half model, N)");
  {
    const auto a = ff.draw_series(sim::Signal::outlet_force, -1), b = fr.draw_series(sim::Signal::outlet_force, -1);
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
      fh.row({fmt(a[i].first, 6), fmt(ff.F_back, 6), fmt(a[i].second, 6), fmt(b[i].second, 6)});
  }
  c.save(fh, "forces");
  c.plot("force_history", "fig_2_19", {{"datafile", c.out("tables/forces.csv")},
                                       {"title_text", "Tension forces in the draw, 12.7 mm pin (Figs. 2.19-2.20)"}});
  return {FB, mu};
}

// 5. Mass scaling and mesh convergence.
void mass_scaling_and_convergence(study::Chapter& c, const Runs& R, const Forces& F, const sim::ContactArc& arc,
                                  double pmax_r) {
  const sim::DrawBendSpec &s = R.s, &s_fine = R.s_fine;
  const sim::DrawBendResult &gf = R.all[3], &gr = R.all[4];
  const sim::DrawBendResult& fm = R.all[2];
  const double FB = F.FB, mu = F.mu;
  const double FB_ms = fm.tension_rise();
  const double d_ms = 100 * (FB - FB_ms) / FB_ms;
  c.value("FB_low_ms", fmt_fixed(FB_ms, 1), "N");
  c.value("ms_diff", fmt_fixed(d_ms, 2), "%");
  c.checks().claim(study::Kind::simulated, "ch2.fe.mass_scaling_invariant", "F_B changes < 2 % between the two mass scalings (Fig. 2.5)",
                   std::abs(d_ms) < 2.0, fmt(d_ms, 3) + " %");
  auto conv = c.table({"element_length_mm", "F_B_N", "mu_eq_2_3", "p_max_MPa", "contact_arc_deg"},
                      "mesh convergence, 12.7 mm pin (half model)");
  double FB_fine = gf.tension_rise(), mu_fine = mu_rope(gr.F_back, gr.F_out, FB_fine, M_PI / 2);
  double pmax_fine = 0;
  for (const auto& q : gr.map) pmax_fine = std::max(pmax_fine, q.pressure);
  const auto arc_fine = sim::contact_arc(sim::rows_of(gr.map).front(), threshold);
  conv.row({fmt(s.element_length), fmt_fixed(FB, 2), fmt_fixed(mu, 4), fmt_fixed(pmax_r, 2), fmt_fixed(arc.angle(), 1)});
  conv.row({fmt(s_fine.element_length), fmt_fixed(FB_fine, 2), fmt_fixed(mu_fine, 4), fmt_fixed(pmax_fine, 2),
            fmt_fixed(arc_fine.angle(), 1)});
  c.save(conv, "mesh_convergence");
  c.value("conv_FB", fmt_fixed(100 * (FB - FB_fine) / FB_fine, 2), "%");
  c.value("conv_mu", fmt_fixed(100 * (mu - mu_fine) / mu_fine, 2), "%");
  c.value("conv_pmax", fmt_fixed(100 * (pmax_r - pmax_fine) / pmax_fine, 1), "%");
}

}  // namespace

void fe_study(study::Chapter& c, const FeOptions& o) {
  const Runs R = runs(c, o);                                // 1
  const sim::ContactArc arc = pressure_map_and_arc(c, R);  // 2
  pressure_peaks(c, R);
  const double pmax_r = max_pressure_difference(c, R);
  tracked_strains(c, R);                                    // 3
  mid_wrap_strain(c, R);
  steady_strain_distribution(c, R);
  steady_state(c, R);
  const Forces F = forces(c, R);                            // 4
  mass_scaling_and_convergence(c, R, F, arc, pmax_r);       // 5
}

}  // namespace ch2
