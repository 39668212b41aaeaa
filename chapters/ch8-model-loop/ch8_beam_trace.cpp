// Chapter 8 step 2: trace the bending-force residual with beam theory
// (analysis/bending_work.hpp), independently of the solver.
//
// The FE loop can afford a few members per candidate; beam theory costs
// milliseconds per point.  So this step asks, per pin, what each
// constitutive assumption does to F_B = oint M dkappa of a strip bent and
// unbent under the Table 5.13 back tension:
//   - isotropic hardening in plane strain (what the FE model is): the FE's
//     isotropic F_B against it separates numerics from physics; and the same
//     with the section thinning as the strip stretches (the FE's finite
//     strain; the small-strain beam keeps the thickness, issue 51);
//   - plane stress (a free beam) and Hosford's a = 8 surface (the usual
//     exponent for FCC metals) in plane strain: the transverse constraint;
//   - an Armstrong-Frederick back stress (the FE loop's chaboche candidate,
//     the same carved flow curve) on a grid of X_sat and gamma, the member
//     chosen on the fit pin alone (as the loop does), judged on the others;
//     and, labelled in-sample, the member best on all pins: whether the family
//     can represent the three pins at all.
// Forces full strip [N]; lengths mm; stresses MPa.
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/bending_work.hpp"
#include "ch8_steps.hpp"
#include "material/hardening_curve.hpp"

namespace ch8 {

using namespace drawbend;

namespace {

analysis::BendMaterial on_curve(const material::HardeningCurve& curve) {
  analysis::BendMaterial m;
  m.flow = [curve](double p) { return curve.stress(p); };
  m.dflow = [curve](double p) { return curve.slope(p); };
  return m;
}

/// The chaboche candidate's material (modelloop::carved_isotropic_part) in beam form.
analysis::BendMaterial carved(const material::HardeningCurve& curve, double x_sat, double gamma) {
  const material::HardeningCurve r(curve.plastic_strains(), modelloop::carved_isotropic_part(curve, x_sat, gamma), "carved");
  analysis::BendMaterial m;
  m.x_sat_MPa = x_sat;
  m.gamma = gamma;
  m.flow = [r, x_sat, gamma](double p) { return r.stress(p) + x_sat * (1 - std::exp(-gamma * p)); };
  m.dflow = [r, x_sat, gamma](double p) { return r.slope(p) + x_sat * gamma * std::exp(-gamma * p); };
  return m;
}

}  // namespace

BeamTrace beam_trace(Chapter&, const Inputs& in, const Config& cfg) {
  const material::HardeningCurve curve = material::HardeningCurve::load(in.base.hardening);
  const double width = 2 * in.base.width;  // full strip
  // 60 layers and 100 steps each way: within 0.04 % of 200 layers x 400 steps on
  // these pins (isotropic, and a back stress of 90 MPa at gamma 60; 2026-11-26).
  auto run_at = [&](const analysis::BendMaterial& m, double pin, double tension, bool thinning = false) {
    analysis::BendCase bc{pin, in.thickness, width, tension, 60, 100};
    bc.thinning = thinning;
    return analysis::bend_unbend(bc, m).bending_force_N;
  };
  auto all_pins = [&](BeamModel& b) {
    b.fb.clear();
    for (std::size_t k = 0; k < in.pins.size(); ++k) b.fb.push_back(run_at(b.mat, in.pins[k], in.fback[k], b.thinning));
  };
  auto err = [&](double f, std::size_t k) { return f / in.measured(in.pins[k], in.fback[k]) - 1; };

  std::vector<BeamModel> models;
  BeamModel iso{"isotropic, plane strain (the FE model's assumption)", on_curve(curve), {}};
  models.push_back(iso);
  BeamModel ps{"isotropic, plane stress (a free beam)", on_curve(curve), {}};
  ps.mat.constraint = 1;
  models.push_back(ps);
  BeamModel hos{"isotropic, Hosford a = 8, plane strain", on_curve(curve), {}};
  hos.mat.constraint = analysis::hosford_plane_strain_factor(8);
  models.push_back(hos);
  BeamModel thin{"isotropic, plane strain, the section thinning as the strip stretches (finite strain, as the FE)",
                 on_curve(curve), {}, true};
  models.push_back(thin);
  for (auto& m : models) all_pins(m);

  // The Armstrong-Frederick grid: chosen on the fit pin, and in-sample.
  const std::vector<double> xs = {30, 60, 90, 120, 150}, gs = {15, 30, 60, 120, 240};
  std::size_t fit_k = in.pins.size();
  for (std::size_t k = 0; k < in.pins.size(); ++k)
    if (study::same(in.pins[k], cfg.fit_pin)) fit_k = k;
  if (fit_k == in.pins.size())
    throw std::invalid_argument("--fit-pin " + fmt(cfg.fit_pin) + ": no such pin in Table 5.13 (12.7, 25.4, 42)");
  BeamModel best_fit, best_all, best_slow;
  double e_fit = std::numeric_limits<double>::infinity(), e_all = e_fit, e_slow = e_fit;
  const auto& fit = study::find_fit(in.bending, "RD", 0.0, cfg.fit_pin);
  if (!fit.range) throw std::invalid_argument("Table 5.3: the " + fmt(cfg.fit_pin) + " mm pin's fit has no back-tension range");
  const auto& range = *fit.range;  // Table 5.3's F_back range
  double slope_lo = e_fit, slope_hi = -e_fit;
  int members = 0;
  std::vector<GridMember> grid;
  // The member each pin alone would choose (the leave-one-pin-out folds fit
  // on a pin other than the fit pin, and choose their grid point there).
  std::vector<double> e_on(in.pins.size(), e_fit);
  std::vector<std::pair<double, double>> af_on(in.pins.size(), {0.0, 0.0});
  for (double g : gs)
    for (double x : xs) {
      BeamModel m{"", {}, {}};
      try {
        m.mat = carved(curve, x, g);
      } catch (const InputError&) {
        continue;  // no elastic range left: not a member
      }
      ++members;
      m.label = "X_sat " + fmt(x) + " MPa, gamma " + fmt(g);
      all_pins(m);
      grid.push_back({x, g, m.fb});
      const double ef = std::abs(err(m.fb[fit_k], fit_k));
      double ea = 0;
      for (std::size_t k = 0; k < in.pins.size(); ++k) ea = std::max(ea, std::abs(err(m.fb[k], k)));
      if (ef < e_fit) e_fit = ef, best_fit = m;
      for (std::size_t k = 0; k < in.pins.size(); ++k)
        if (std::abs(err(m.fb[k], k)) < e_on[k]) e_on[k] = std::abs(err(m.fb[k], k)), af_on[k] = {x, g};
      if (ea < e_all) e_all = ea, best_all = m;
      if (g <= 30 && ef < e_slow) e_slow = ef, best_slow = m;
      const double slope = (run_at(m.mat, cfg.fit_pin, range.hi) - run_at(m.mat, cfg.fit_pin, range.lo)) / (range.hi - range.lo);
      slope_lo = std::min(slope_lo, slope), slope_hi = std::max(slope_hi, slope);
    }
  best_fit.label = "Armstrong-Frederick, chosen on the " + fmt(cfg.fit_pin) + " mm pin: " + best_fit.label;
  best_all.label = "Armstrong-Frederick, best on all pins (in-sample, not a prediction): " + best_all.label;
  models.push_back(best_fit);
  models.push_back(best_all);

  BeamTrace t;
  t.models = models;
  t.chosen_x = best_fit.mat.x_sat_MPa;
  t.chosen_gamma = best_fit.mat.gamma;
  t.af_on_pin = af_on;
  t.members = members;
  t.grid = grid;
  t.best_slow = best_slow;
  t.slope_lo = slope_lo, t.slope_hi = slope_hi;
  t.slope_meas = fit.slope.value;
  t.best_all = best_all;
  t.best_fit = best_fit;
  return t;
}

void save_beam_trace(Chapter& c, const Inputs& in, const BeamTrace& t, const modelloop::ModelLoopResult* loop) {
  const auto& models = t.models;
  const auto& best_fit = t.best_fit;
  const auto& best_all = t.best_all;
  const int members = t.members;
  auto err = [&](double f, std::size_t k) { return f / in.measured(in.pins[k], in.fback[k]) - 1; };
  std::vector<std::string> head = {"model"};
  for (double d : in.pins) {
    head.push_back("d" + fmt(d) + "_N");
    head.push_back("d" + fmt(d) + "_err_pct");
  }
  auto tab = c.table(head, "beam theory (bend and unbend under the Table 5.13 back tension, oint M dkappa; "
                           "analysis/bending_work.hpp): F_B per pin (full strip, N) and its error against Table 5.3; "
                           "the finite-element rows for comparison");
  auto row = [&](const std::string& label, const std::vector<double>& fb) {
    std::vector<std::string> r = {label};
    for (std::size_t k = 0; k < fb.size(); ++k) {
      r.push_back(fmt_fixed(fb[k], 1));
      r.push_back(pct(err(fb[k], k)));
    }
    tab.row(r);
  };
  for (const auto& m : models) row("beam: " + m.label, m.fb);
  if (loop) {
    std::vector<double> fe_iso, fe_final;
    for (std::size_t k = 0; k < in.pins.size(); ++k) {
      fe_iso.push_back(loop->baseline.points[k].predicted_N);
      fe_final.push_back(loop->final_model.points[k].predicted_N);
    }
    row("FE: isotropic", fe_iso);
    row("FE: final model (" + loop->final_model.model + ")", fe_final);
    for (std::size_t k = 0; k < in.pins.size(); ++k) {
      c.value("fe_vs_beam_d" + fmt(in.pins[k]), pct(fe_iso[k] / models[0].fb[k] - 1), "%");
      c.value("fe_vs_beam_thin_d" + fmt(in.pins[k]), pct(fe_iso[k] / models[3].fb[k] - 1), "%");
    }
  }
  c.save(tab, "beam_trace");
  for (std::size_t k = 0; k < in.pins.size(); ++k) {
    const std::string d = fmt(in.pins[k]);
    c.value("beam_iso_d" + d, fmt_fixed(models[0].fb[k], 1), "N");
    c.value("beam_iso_err_d" + d, pct(err(models[0].fb[k], k)), "%");
    c.value("beam_ps_err_d" + d, pct(err(models[1].fb[k], k)), "%");
    c.value("beam_hos_err_d" + d, pct(err(models[2].fb[k], k)), "%");
    c.value("beam_thin_d" + d, fmt_fixed(models[3].fb[k], 1), "N");
    c.value("beam_thin_vs_iso_d" + d, pct(models[3].fb[k] / models[0].fb[k] - 1), "%");
    c.value("beam_thin_err_d" + d, pct(err(models[3].fb[k], k)), "%");
    c.value("beam_af_err_d" + d, pct(err(best_fit.fb[k], k)), "%");
    c.value("beam_af_all_err_d" + d, pct(err(best_all.fb[k], k)), "%");
  }
  c.value("beam_af_members", std::to_string(members));
  c.value("beam_slow", t.best_slow.label);
  for (std::size_t k = 0; k < in.pins.size(); ++k)
    c.value("beam_slow_err_d" + fmt(in.pins[k]), pct(err(t.best_slow.fb[k], k)), "%");
  c.value("beam_slope_lo", fmt(t.slope_lo, 3), "N/N");
  c.value("beam_slope_hi", fmt(t.slope_hi, 3), "N/N");
  c.value("beam_slope_meas", fmt(t.slope_meas, 3), "N/N");
  c.value("beam_af_chosen", best_fit.label.substr(best_fit.label.find(": ") + 2));
  c.value("beam_af_all", best_all.label.substr(best_all.label.find(": ") + 2));
  c.value("hosford8_factor", fmt(analysis::hosford_plane_strain_factor(8), 4));
}

}  // namespace ch8
