// Chapter 5 step 8: our own frictionless (rotating-pin) pressure maps for the
// test conditions of Sec. 5.7.1, which replace the maps behind Table 5.16.
//
// Sec. 5.7.1: three pins (12.7, 25.4, 42 mm), back tensions of Table 5.13
// (full strip; half of each on the half model), the RD stress-strain curve for
// every simulation (the thesis used the RD curve for the TD strips too, and so
// do our baseline maps; the TD curve is a sensitivity variant).  Draw speed
// 50 mm/s as in the Chapter 4 simulations, with the mass scaling of Chapter 4
// (x (100/v)^2, the inertia of the 100 mm/s reference).
//
// The sensitivity variants change one thing each, on the 12.7 and 25.4 mm pins
// (the pins of Table 5.16): a finer mesh, a stiffer contact penalty, the TD
// hardening curve.  Forces: half model in the runs, full strip where they meet
// the measured forces.  Lengths mm, pressures MPa, forces N, time s.
#include <chrono>
#include <iostream>

#include "analysis/pressure_ratio.hpp"
#include "ch5_steps.hpp"
#include "sim/case_pool.hpp"
#include "sim/fe_options.hpp"
#include "study/run_health.hpp"
#include "sim/map_tools.hpp"

namespace ch5 {

using namespace drawbend;
using namespace drawbend::analysis;

const sim::DrawBendResult& FeMaps::run(const std::string& variant, double pin) const {
  const auto it = runs.find(variant);
  if (it != runs.end())
    for (const auto& [d, r] : it->second)
      if (study::same(d, pin)) return r;
  throw std::out_of_range("no FE map for variant " + variant + ", pin " + fmt(pin));
}

bool FeMaps::has(const std::string& variant, double pin) const {
  const auto it = runs.find(variant);
  if (it == runs.end()) return false;
  for (const auto& [d, r] : it->second)
    if (study::same(d, pin)) return true;
  return false;
}

PressureMap FeMaps::full_strip_map(const std::string& variant, double pin) const {
  return run(variant, pin).pressure_map(variant + " map, pin " + fmt(pin) + " mm").scaled_areas(2.0);
}

double FeMaps::full_strip_bending(const std::string& variant, double pin) const {
  return 2.0 * run(variant, pin).tension_rise();
}

double ffric_of(const Inputs& in, const std::string& dir, double v, double pin, bool undiluted) {
  return study::find_case(undiluted ? in.ffric_undiluted : in.ffric_diluted, dir, v, pin).value.value;
}

double c_of(CDef d, const Inputs& in, const FeMaps& m, const std::string& variant, const std::string& dir, double v,
            double pin, bool undiluted) {
  if (d == CDef::printed) return study::find_case(undiluted ? in.c_undiluted : in.c_diluted, dir, v, pin).value.value;
  const double Fb = in.back_tension(pin);
  const double Fbend = study::find_fit(in.bending, "RD", 0.0, pin).fit()(Fb);  // Table 5.3 at F_back
  const double Ff = ffric_of(in, dir, v, pin, undiluted);
  if (d == CDef::eq22) return pressure_ratio_from_fits(Fb, Ff, Fbend);
  // Fixed-pin test as measured; rotating-pin test as simulated (our map's run).
  return (2 * Fb + Fbend + Ff) / (2 * Fb + m.full_strip_bending(variant, pin));
}

NewMethodResult identify(const Inputs& in, const FeMaps& m, const std::string& variant, CDef cdef,
                         const std::string& dir, double v, const std::vector<double>& pins, int order,
                         bool undiluted) {
  std::vector<PinTest> tests;
  for (double pin : pins) {
    PinTest t;
    t.map = m.full_strip_map(variant, pin);
    t.c = c_of(cdef, in, m, variant, dir, v, pin, undiluted);
    t.friction_force_N = ffric_of(in, dir, v, pin, undiluted);
    tests.push_back(std::move(t));
  }
  return solve_new_method(tests, order);
}

namespace {

/// Sec. 5.7.1's conditions and the deck of one map run (variant, pin).
struct SpecFor {
  Chapter& c;
  const Inputs& in;
  const FeOptions& o;
  double v, w_half, t_strip, ms;  ///< mm/s, mm, mm, -

  sim::DrawBendSpec operator()(const std::string& variant, double pin) const {
    sim::DrawBendSpec s = o.base;
    s.pin_diameter = pin;
    s.thickness = t_strip;
    s.width = w_half;
    s.back_tension = in.back_tension(pin) / 2.0;  // half model (Sec. 5.7.1)
    s.speed = v;
    s.mass_scaling = ms;
    s.hardening = c.data("materials/aa5754_o_rd.csv");
    if (variant == "penalty") s.penalty = o.stiff_penalty;
    if (variant == "td_curve") s.hardening = c.data("materials/aa5754_o_td.csv");
    if (variant == "fine_along")
      s.element_length = o.fine_element_length > 0 ? o.fine_element_length : o.base.element_length / 2;
    if (variant == "fine_across") s.across = o.fine_across > 0 ? o.fine_across : 2 * o.base.across;
    s.name = "ch5_d" + fmt(pin) + "_" + variant;
    return s;
  }
};

/// The conditions from data/thesis/scalars.csv.
SpecFor map_conditions(Chapter& c, const Inputs& in, const FeOptions& o) {
  const std::string sc = c.data("thesis/scalars.csv");
  const double v = study::scalar(sc, "ch4_outlet_speed").value;  // 50 mm/s
  const double w_half = study::scalar(sc, "ch5_strip_width").value / 2;
  const double t_strip = study::scalar(sc, "ch5_strip_thickness").value;
  const double ms = sim::mass_scaling_for_speed(o.base.mass_scaling, v);
  return {c, in, o, v, w_half, t_strip, ms};
}

/// All runs side by side (sim/case_pool.hpp).
FeMaps run_maps(Chapter& c, const FeOptions& o, const SpecFor& spec_for) {
  FeMaps m;
  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<sim::CaseJob> jobs;  // all runs side by side (sim/case_pool.hpp)
  std::vector<std::pair<std::string, double>> keys;
  for (const char* variant : kVariants) {
    const bool base = std::string(variant) == "base";
    for (double pin : kPins) {
      if (!base && (pin > 25.4 + 1e-9 || !o.map_variants)) continue;  // variants: the pins of Table 5.16
      if (std::string(variant) == "fine_across" && !o.across_variant) continue;
      const sim::DrawBendSpec s = spec_for(variant, pin);
      jobs.push_back({s, c.out("runs/" + s.name)});
      keys.emplace_back(variant, pin);
    }
  }
  std::vector<sim::DrawBendResult> all = sim::run_drawbend_all(jobs, o.reuse);
  for (std::size_t i = 0; i < all.size(); ++i) m.runs[keys[i].first].emplace(keys[i].second, std::move(all[i]));
  m.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return m;
}

/// The run table fe_runs, the run health checks and the base runs' values; the sum of the runs' wall times.
double run_table(Chapter& c, const Inputs& in, const FeMaps& m) {
  // Run table, invariants and the bending force beside the measured one.
  auto tab = c.table({"run", "pin_mm", "variant", "F_back_half_N", "F_out_half_N", "F_B_full_N", "F_bend_T5.3_N",
                      "S1_full_N", "p_bar_MPa", "p_max_MPa", "energy_error", "KE_IE", "HG_IE", "cycles", "wall_s"},
                     "our frictionless draw-bend runs (Sec. 5.7.1 conditions): forces (half model and full strip, N), "
                     "map normal force S1 = sum p A and pressure-weighted mean pressure S2/S1 (full strip)");
  double cpu = 0;
  for (const auto& [variant, pins] : m.runs)
    for (const auto& [pin, r] : pins) {
      const PressureMap pm = m.full_strip_map(variant, pin);
      double pmax = 0;
      for (double p : pm.p_MPa) pmax = std::max(pmax, p);
      const double Fbend = study::find_fit(in.bending, "RD", 0.0, pin).fit()(in.back_tension(pin));
      tab.row({r.spec.name, fmt(pin), variant, fmt_fixed(r.F_back, 1), fmt_fixed(r.F_out, 1),
               fmt_fixed(2 * r.tension_rise(), 1), fmt_fixed(Fbend, 1), fmt_fixed(pm.moment(1), 1),
               fmt_fixed(pm.moment(2) / pm.moment(1), 2), fmt_fixed(pmax, 1), fmt(r.balance_error, 3),
               fmt(r.kinetic_ratio, 3), fmt(r.hourglass_ratio, 3), std::to_string(r.cycles),
               fmt_fixed(r.wall_seconds, 1)});
      cpu += r.wall_seconds;
      const std::string id = "ch5.fe." + r.spec.name;
      // Quasi-static invariants of each run.
      study::check_run_health(c.checks(), id, r.spec.name, {r.balance_error, r.kinetic_ratio, r.hourglass_ratio});
      if (variant == "base") {
        const std::string d = fmt(pin);
        c.value("fe_FB_d" + d, fmt_fixed(2 * r.tension_rise(), 1), "N");
        c.value("fe_Fbend_d" + d, fmt_fixed(Fbend, 1), "N");
        c.value("fe_pbar_d" + d, fmt_fixed(pm.moment(2) / pm.moment(1), 1), "MPa");
        c.value("fe_pmax_d" + d, fmt_fixed(pmax, 1), "MPa");
        c.value("fe_wall_d" + d, fmt_fixed(r.wall_seconds, 0), "s");
      }
    }
  c.save(tab, "fe_runs");
  return cpu;
}

/// Figs. 5.12-5.14.
void bending_figures(Chapter& c, const Inputs& in, const FeMaps& m) {
  // Figs. 5.12-5.14: the bending force of the rotating-pin tests against the
  // back tension (Table 5.3's fit over its printed range, full strip) with
  // our frictionless run at the back tension of Table 5.13 beside it.
  for (const auto& [pin, r] : m.runs.at("base")) {
    const auto& fit = study::find_fit(in.bending, "RD", 0.0, pin);
    const std::string d = fmt(pin);
    auto line = c.table({"F_back_N", "F_bend_T5.3_N"}, "Table 5.3 bending-force fit, RD, pin " + d +
                                                           " mm, over its printed back-tension range (full strip, N)");
    const double lo = fit.range ? fit.range->lo : in.back_tension(pin) - 100, hi = fit.range ? fit.range->hi : lo + 200;
    for (int k = 0; k <= 10; ++k) {
      const double fb = lo + (hi - lo) * k / 10.0;
      line.row({fmt(fb, 6), fmt(fit.fit()(fb), 6)});
    }
    c.save(line, "bending_fit_d" + d);
    auto pt = c.table({"F_back_N", "F_B_ours_N"}, "our frictionless run, pin " + d + " mm (full strip, N)");
    pt.row({fmt(2 * r.F_back, 6), fmt(2 * r.tension_rise(), 6)});
    c.save(pt, "bending_ours_d" + d);
    const std::string fig = pin < 20 ? "fig_5_12" : pin < 30 ? "fig_5_13" : "fig_5_14";
    c.plot("bending_force", fig,
           {{"linefile", c.out("tables/bending_fit_d" + d + ".csv")},
            {"pointfile", c.out("tables/bending_ours_d" + d + ".csv")},
            {"title_text", "Bending force, " + d + " mm pin, RD (Fig. " + fig.substr(4, 1) + "." + fig.substr(6) + ")"}});
  }
}

/// The runs' conditions and what ran.
void map_values(Chapter& c, const FeOptions& o, const FeMaps& m, const SpecFor& spec_for, double cpu) {
  const double v = spec_for.v, ms = spec_for.ms;
  c.value("fe_wall", fmt_fixed(m.wall_s / 60.0, 1), "min");
  c.value("fe_run_wall_sum", fmt_fixed(cpu / 60.0, 1), "min");
  c.value("fe_runs", std::to_string([&] {
            std::size_t n = 0;
            for (const auto& [k, p] : m.runs) n += p.size();
            return n;
          }()));
  c.value("fe_speed", fmt(v), "mm/s");
  c.value("fe_ms", fmt(ms));
  c.value("fe_h", fmt(o.base.element_length), "mm");
  c.value("fe_across", std::to_string(o.base.across));
  c.value("fe_through", std::to_string(o.base.through));
  c.value("fe_fine_h", fmt(spec_for("fine_along", 12.7).element_length), "mm");
  c.value("fe_fine_across", std::to_string(spec_for("fine_across", 12.7).across));
  c.value("fe_across_ran", o.map_variants && o.across_variant
                              ? "was run"
                              : "was not run in this (quick) tier of the chapter; the full tier (`make`, or "
                                "`--fe-map-variants true --fe-across-variant true`) runs it");
  c.value("fe_variants_ran", o.map_variants
                                 ? "ran in this tier of the chapter"
                                 : "did not run in this (quick) tier: they are six more runs. The full tier (`make`, "
                                   "or `--fe-map-variants true`) runs them, and the rows below then have numbers");
  c.value("fe_penalty", fmt(o.base.penalty));
  c.value("fe_stiff_penalty", fmt(o.stiff_penalty));
}

/// Figs. 5.23-5.25.
void map_figures(Chapter& c, const Inputs& in, const FeMaps& m) {
  // Figs. 5.23-5.25: the baseline maps (half model, as the thesis plots them).
  const char* fig[3] = {"fig_5_23_fe", "fig_5_24_fe", "fig_5_25_fe"};
  for (int k = 0; k < 3; ++k) {
    const auto& r = m.run("base", kPins[k]);
    const std::string stem = "map_d" + fmt(kPins[k]);
    sim::save_map_grid(r.map, c.out("tables/" + stem + ".dat"),
                       "our frictionless contact-pressure map [MPa], pin " + fmt(kPins[k]) + " mm, F_back/2 = " +
                           fmt(r.F_back) + " N");
    c.plot("pressure_map", fig[k],
           {{"gridfile", c.out("tables/" + stem + ".dat")},
            {"title_text", "Our pressure map, " + fmt(kPins[k]) + " mm pin, back tension " +
                               fmt(in.back_tension(kPins[k])) + " N"}});
  }
}

}  // namespace

FeMaps run_fe_maps(Chapter& c, const Inputs& in, const FeOptions& o) {
  const SpecFor spec_for = map_conditions(c, in, o);
  FeMaps m = run_maps(c, o, spec_for);
  const double cpu = run_table(c, in, m);
  bending_figures(c, in, m);
  map_values(c, o, m, spec_for, cpu);
  map_figures(c, in, m);
  return m;
}

}  // namespace ch5
