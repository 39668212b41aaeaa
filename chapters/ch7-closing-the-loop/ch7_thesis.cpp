// Chapter 7 steps 1-6: the thesis data in the sample format, the maps, the
// thesis's own loop (demonstration 1), the automatic loop, and the loops
// beyond the thesis (demonstration 2).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "analysis/rope.hpp"
#include "ch7_steps.hpp"
#include "loop/report.hpp"
#include "loop/thesis_rows.hpp"
#include "study/thesis_data.hpp"

namespace ch7 {

using namespace drawbend;
using namespace drawbend::loop;

namespace {
double rms(const std::vector<double>& e) {
  double s = 0;
  for (double x : e) s += x * x;
  return e.empty() ? 0 : std::sqrt(s / e.size());
}
double maxabs(const std::vector<double>& e) {
  double m = 0;
  for (double x : e) m = std::max(m, std::abs(x));
  return m;
}
ModelSpec with(EffectKind k, bool linear = true) {
  ModelSpec s;
  s.bending_linear = linear;
  s.effects.push_back({k, "", 0, 0, "", 0});
  return s;
}
}  // namespace

// Step 1.
Thesis load_thesis_data(Chapter& c, const Config& cfg) {
  const std::string path = c.data("measured/thesis_drawbend.csv");
  Thesis t{read_measured(path), MapLibrary{}};
  const Dataset regen = thesis_dataset(c.data("thesis"), 7);
  const std::string regen_path = c.out("tables/thesis_drawbend_regenerated.csv");
  write_measured(regen_path, regen);
  c.checks().claim(study::Kind::software, "ch7.data.reproducible", "data/measured/thesis_drawbend.csv equals its generator's output",
                   read_file(path) == read_file(regen_path),
                   "the shipped file must be exactly what drawbend synth --from-thesis writes");
  c.checks().claim(study::Kind::software, "ch7.data.clean", "every row of thesis_drawbend.csv is usable (no data problems)",
                   t.data.problems.empty() && static_cast<int>(t.data.rows.size()) == t.data.rows_read,
                   "the file is generated from the thesis tables, so any problem is a generator or reader bug");
  std::set<std::string> tests, fixed_tests;
  int rot = 0;
  for (const auto& s : t.data.rows) {
    tests.insert(s.test_id);
    if (!s.rotating) fixed_tests.insert(s.test_id);
    rot += s.rotating;
  }
  c.value("thesis_rows", std::to_string(t.data.rows.size()));
  c.value("thesis_tests", std::to_string(tests.size()));
  c.value("thesis_fixed_tests", std::to_string(fixed_tests.size()));
  c.value("thesis_rotating_rows", std::to_string(rot));
  std::set<double> pins;
  for (const auto& s : t.data.rows) pins.insert(s.pin_d_mm);
  t.maps = cfg.maps_dir.empty() ? MapLibrary::stand_in({pins.begin(), pins.end()}) : MapLibrary::load_dir(cfg.maps_dir);
  c.value("maps", t.maps.label());
  return t;
}

// Step 2.
void map_table(Chapter& c, const MapLibrary& m) {
  auto w = c.table({"pin_mm", "map", "fref_N", "S1_N", "weighted_pressure_MPa", "belt_pressure_MPa", "peak_MPa"},
                   "pressure maps used by the loop (" + m.label() + "): full-strip normal force S1 = sum p A and "
                   "force-weighted mean pressure sum p^2 A / sum p A at the reference back tension");
  for (const auto& p : m.maps()) {
    const double belt = p.fref_N / (p.pin_d_mm / 2 * kStripWidthMm);
    w.row({fmt(p.pin_d_mm), m.is_stand_in() ? "analytic stand-in, not FE" : p.provenance, fmt(p.fref_N),
           fmt(p.S1, 5), fmt(p.weighted_pressure(p.fref_N), 4), fmt(belt, 4),
           fmt(*std::max_element(p.map.p_MPa.begin(), p.map.p_MPa.end()), 4)});
  }
  c.save(w, "maps");
}

// Step 3.  Demonstration 1: fit at one back tension per test (the middle row of
// each fixed-pin fit, all rotating rows for the bending lines), hold out the
// other back tensions of every fit.
void thesis_loop_pressure(Chapter& c, const Thesis& t) {
  const Design d = make_design(t.data, t.maps);
  std::map<std::string, std::vector<int>> by_test;
  for (size_t i = 0; i < d.rows.size(); ++i) by_test[t.data.rows[i].test_id].push_back(static_cast<int>(i));
  std::vector<int> train, held;
  for (auto& [id, ix] : by_test) {
    if (d.rows[ix[0]].rotating) {
      train.insert(train.end(), ix.begin(), ix.end());
      continue;
    }
    std::stable_sort(ix.begin(), ix.end(), [&](int a, int b) { return d.rows[a].fback < d.rows[b].fback; });
    const size_t mid = ix.size() / 2;
    for (size_t k = 0; k < ix.size(); ++k) (k == mid ? train : held).push_back(ix[k]);
  }
  const Fit f0 = fit_model(d, ModelSpec{}, train);
  const Fit f1 = fit_model(d, with(EffectKind::pressure_mu), train);
  std::vector<double> e0, e1;
  auto res = c.table({"line", "test_id", "pin", "resid_before_N", "resid_after_N", "pin_diameter_mm", "back_tension_N"},
                     "demonstration 1: held-out residual (measured - predicted outlet force, N) of constant mu "
                     "(before) and mu(p) through the maps (after); trained at the middle back tension of each fit");
  struct Acc {
    double s0 = 0, s1 = 0, ffric = 0;
    int n = 0;
  };
  std::map<std::pair<std::string, double>, Acc> cellpin;
  for (int i : held) {
    const Sample& s = t.data.rows[i];
    const double r0 = d.rows[i].y - predict(d, f0, i), r1 = d.rows[i].y - predict(d, f1, i);
    e0.push_back(r0);
    e1.push_back(r1);
    res.row({std::to_string(s.line), s.test_id, "fixed", fmt(r0, 6), fmt(r1, 6), fmt(s.pin_d_mm), fmt(s.back_tension_N, 6)});
    auto& a = cellpin[{d.cells[d.rows[i].cell], s.pin_d_mm}];
    a.s0 += r0, a.s1 += r1, a.n++;
  }
  c.save(res, "demo1_residuals");
  // Mean residual per cell and pin, and whether it is ordered with pin diameter.
  auto w = c.table({"cell", "pin_mm", "mean_resid_const_mu_N", "mean_resid_mu_p_N"},
                   "demonstration 1: mean held-out residual per cell and pin (N)");
  std::map<std::string, std::vector<double>> by_cell0, by_cell1;
  for (const auto& [k, a] : cellpin) {
    w.row({k.first, fmt(k.second), fmt(a.s0 / a.n, 4), fmt(a.s1 / a.n, 4)});
    by_cell0[k.first].push_back(a.s0 / a.n);
    by_cell1[k.first].push_back(a.s1 / a.n);
  }
  c.save(w, "demo1_pin_means");
  auto ordered = [](const std::vector<double>& v) {
    bool inc = true, dec = true;
    for (size_t k = 1; k < v.size(); ++k) inc = inc && v[k] > v[k - 1], dec = dec && v[k] < v[k - 1];
    return v.size() >= 3 && (inc || dec);
  };
  int ord0 = 0, ord1 = 0, small_first = 0, cells = 0;
  double spread0 = 0, spread1 = 0;
  for (const auto& [cell, v] : by_cell0) {
    if (v.size() < 3) continue;
    ++cells;
    ord0 += ordered(v);
    ord1 += ordered(by_cell1[cell]);
    small_first += v[0] > v[1];
    spread0 += (*std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end())) / 1;
    const auto& u = by_cell1[cell];
    spread1 += *std::max_element(u.begin(), u.end()) - *std::min_element(u.begin(), u.end());
  }
  c.value("d1_cells", std::to_string(cells));
  c.value("d1_ordered_const", std::to_string(ord0));
  c.value("d1_ordered_mup", std::to_string(ord1));
  c.value("d1_small_above", std::to_string(small_first));
  c.value("d1_spread_const", fmt(spread0 / std::max(1, cells), 3), "N");
  c.value("d1_spread_mup", fmt(spread1 / std::max(1, cells), 3), "N");
  c.checks().claim(study::Kind::measured, "ch7.demo1.pin_spread", "mu(p) narrows the spread of the per-pin mean held-out residuals",
                   spread1 < spread0, "pressure non-uniformity is the thesis's explanation of the pin dependence (Sec. 5.7)");
  c.value("d1_train", std::to_string(train.size()));
  c.value("d1_held", std::to_string(held.size()));
  c.value("d1_rms_const", fmt(rms(e0), 4), "N");
  c.value("d1_rms_mup", fmt(rms(e1), 4), "N");
  c.value("d1_max_const", fmt(maxabs(e0), 4), "N");
  c.value("d1_max_mup", fmt(maxabs(e1), 4), "N");
  c.checks().claim(study::Kind::measured, "ch7.demo1.heldout_rms", "mu(p) through the maps lowers the held-out RMS of the thesis data",
                   rms(e1) < rms(e0), "the thesis's argument for the new method (Sec. 5.7) on held-out back tensions");
  auto pw = c.table({"parameter", "value", "se"}, "demonstration 1: mu(p) = mu0 + a1 p per cell, fitted at the "
                    "middle back tension of each fit (maps: " + t.maps.label() + ")");
  for (const auto& p : f1.params) pw.row({p.name, fmt(p.value, 5), fmt(p.se, 3)});
  c.save(pw, "demo1_mu_p");
  c.plot("loop_residual", "demo1_resid_pin", {{"datafile", c.out("tables/demo1_residuals.csv")}, {"xcol", "6"},
                                              {"xname", "pin diameter (mm)"}});
  c.plot("loop_residual", "demo1_resid_fback", {{"datafile", c.out("tables/demo1_residuals.csv")}, {"xcol", "7"},
                                                {"xname", "back tension (N)"}});
}

// Step 4.  The automatic loop on the thesis data.
void automatic_loop(Chapter& c, const Thesis& t, const Config& cfg) {
  const Design d = make_design(t.data, t.maps);
  LoopOptions o;
  o.permutations = cfg.permutations;
  const LoopResult r = run_loop(d, o);
  c.save(steps_table(r), "auto_steps");
  c.save(candidates_table(r), "auto_candidates");
  c.save(effects_table(r), "auto_effects");
  c.save(residuals_table(d, r), "auto_residuals");
  write_file_atomic(c.out("tables/auto_loop_summary.json"), summary_json(r));
  c.value("auto_cv", r.cv_mode);
  c.value("auto_n_pred", std::to_string(r.cv.front().n));
  c.value("auto_n_rows", std::to_string(d.rows.size()));
  c.value("auto_steps", std::to_string(r.steps.size()));
  c.value("auto_first", r.steps.empty() ? "none" : r.steps[0].variable + " → " + r.steps[0].effect);
  c.value("auto_rms_base", fmt(r.cv.front().rms, 4), "N");
  c.value("auto_rms_final", fmt(r.cv.back().rms, 4), "N");
  c.value("auto_stop", r.stopped_because);
  for (size_t k = 0; k < r.candidates.size(); ++k)
    if (r.candidates[k].name == "avg_pressure_MPa" || r.candidates[k].name == "inv_R_per_mm")
      c.plot("loop_residual", "auto_resid_" + r.candidates[k].name,
             {{"datafile", c.out("tables/auto_residuals.csv")}, {"xcol", std::to_string(6 + k)},
              {"xname", r.candidates[k].name}});
}

// Step 5.  Demonstration 2a: the 42 mm pin (Sec. 5.6).  mu(p) is fitted on the
// 12.7 and 25.4 mm pins only (as the thesis did for Table 5.16), then the 42 mm
// fixed-pin rows are predicted; diluted and undiluted lubricant compared.
void pin_42_anomaly(Chapter& c, const Thesis& t) {
  const Design d = make_design(t.data, t.maps);
  std::vector<int> train;
  for (size_t i = 0; i < d.rows.size(); ++i)
    if (d.rows[i].rotating || t.data.rows[i].pin_d_mm < 30) train.push_back(static_cast<int>(i));
  const Fit f = fit_model(d, with(EffectKind::pressure_mu), train);
  auto w = c.table({"cell", "rows", "mean_resid_N", "mean_friction_N", "relative"},
                   "demonstration 2a: 42 mm pin predicted by mu(p) from the 12.7 and 25.4 mm pins; mean residual "
                   "(measured - predicted outlet force, N) relative to the measured friction force");
  std::map<std::string, std::array<double, 3>> acc;
  for (size_t i = 0; i < d.rows.size(); ++i) {
    const Sample& s = t.data.rows[i];
    if (d.rows[i].rotating || s.pin_d_mm < 30) continue;
    const double fb = f.b0[d.rows[i].pin] + f.b1[d.rows[i].pin] * s.back_tension_N;
    auto& a = acc[d.cells[d.rows[i].cell]];
    a[0] += s.outlet_force_N - predict(d, f, static_cast<int>(i));
    a[1] += s.outlet_force_N - s.back_tension_N - fb;
    a[2] += 1;
  }
  double rel_dil = 0, rel_und = 0;
  int n_dil = 0, n_und = 0;
  for (const auto& [cell, a] : acc) {
    const double rel = a[0] / a[1];
    w.row({cell, fmt(a[2]), fmt(a[0] / a[2], 4), fmt(a[1] / a[2], 4), fmt(rel, 3)});
    if (cell.find("undiluted") != std::string::npos) rel_und += rel, ++n_und;
    else rel_dil += rel, ++n_dil;
  }
  c.save(w, "demo2_pin42");
  rel_dil /= std::max(1, n_dil);
  rel_und /= std::max(1, n_und);
  c.checks().claim(study::Kind::measured, "ch7.demo2.pin42_undiluted",
                   "the 42 mm pin's excess friction over the mu(p) prediction is smaller with undiluted lubricant",
                   rel_und < rel_dil, "Sec. 5.8: the rich lubricant reduces the 42 mm pin's anomaly (Fig. 5.30)");
  c.value("d2_rel_diluted", fmt(100 * rel_dil, 3), "%");
  c.value("d2_rel_undiluted", fmt(100 * rel_und, 3), "%");
  c.value("d2_cells_diluted", std::to_string(n_dil));
  c.value("d2_cells_undiluted", std::to_string(n_und));
  // The fitted mu(p) from the two smaller pins against the printed Table 5.16.
  const CsvTable t516 = read_csv(c.data("thesis/table_5_16.csv"));
  auto cmp = c.table({"cell", "mu0_ours", "a1_ours_per_MPa", "a1_se", "a0_table_5_16", "a1_table_5_16_per_MPa"},
                     "mu(p) = mu0 + a1 p from the 12.7 and 25.4 mm pins (all back tensions; maps: " + t.maps.label() +
                         ") against the printed Table 5.16 (FE maps of the thesis, Table 5.13 back tensions)");
  for (size_t k = 0; k < d.cells.size(); ++k) {
    const std::string& cell = d.cells[k];
    std::string mu0 = "-", a1 = "-", se = "-", a0t = "-", a1t = "-";
    for (const auto& p : f.params) {
      if (p.name == "mu_RD [" + cell + "]" || p.name == "mu_TD [" + cell + "]") mu0 = fmt(p.value, 4);
      if (p.name == "a1 [" + cell + "] (1/MPa)") a1 = fmt(p.value, 3), se = fmt(p.se, 2);
    }
    for (const auto& r : t516.rows) {
      const std::string dir = t516.text(r, "direction");
      if (cell.find("diluted") != std::string::npos && cell.find("undiluted") == std::string::npos &&
          cell.find("| " + fmt(t516.number(r, "speed_mm_s")) + " mm/s | " + dir) != std::string::npos)
        a0t = t516.text(r, "a0"), a1t = t516.text(r, "a1_per_MPa");
    }
    cmp.row({cell, mu0, a1, se, a0t, a1t});
  }
  c.save(cmp, "demo2_mu_p_vs_table_5_16");
  // The loop's per-pin surface factor on all data, with mu(p).
  ModelSpec s = with(EffectKind::pressure_mu);
  s.effects.push_back({EffectKind::pin_surface, "", 0, 0, "", 0});
  const Fit g = fit_model(d, s);
  auto pw = c.table({"parameter", "value", "se"}, "demonstration 2a: mu(p) plus a per-pin surface factor on all rows");
  for (const auto& p : g.params)
    if (p.name.rfind("s_pin", 0) == 0) {
      pw.row({p.name, fmt(p.value, 4), fmt(p.se, 3)});
      if (p.name.find("42") != std::string::npos) c.value("d2_s42", fmt(p.value, 3) + " ± " + fmt(p.se, 2));
    }
  c.save(pw, "demo2_pin_factor");
}

// Step 6.  Demonstration 2b: bending force against back tension.  Swift's
// Eq. (2.1) has no back-tension term; Table 5.3 falls with back tension.
void bending_vs_swift(Chapter& c, const Thesis& t, const Config& cfg) {
  const std::string sc = c.data("thesis/scalars.csv");
  const double th = study::scalar(sc, "ch5_strip_thickness").value;
  const double wd = study::scalar(sc, "ch5_strip_width").value;
  const double sy = 99.71;  // Table 5.1 RD 0.2 % proof stress, MPa
  const auto fits = study::load_fits(c.data("thesis/table_5_3.csv"), "Table 5.3");
  auto w = c.table({"pin_mm", "swift_N", "table_5_3_mid_N", "slope", "fall_over_range_N", "fall_pct"},
                   "demonstration 2b: bending force by Swift Eq. (2.1) (sigma_y = 99.71 MPa, t, w of Sec. 5.2, "
                   "r = pin radius, Theta = 90 deg) against the Table 5.3 line at mid range (full strip, N)");
  for (const auto& f : fits) {
    const double sw = analysis::swift_bending_force(sy, th, wd, f.pin_mm / 2, M_PI / 2, analysis::ForceBasis::full_strip);
    const auto lf = f.fit();
    const double mid = 0.5 * (lf.range->lo + lf.range->hi), fall = -lf.slope * (lf.range->hi - lf.range->lo);
    w.row({fmt(f.pin_mm), fmt(sw, 4), fmt(lf(mid), 5), fmt(lf.slope, 3), fmt(fall, 3), fmt(100 * fall / lf(mid), 3)});
  }
  c.save(w, "demo2_bending");
  // The loop started from a Swift-like constant bending force.
  const Design d = make_design(t.data, t.maps);
  LoopOptions o;
  o.bending_linear = false;
  o.permutations = cfg.permutations;
  const LoopResult r = run_loop(d, o);
  c.save(steps_table(r), "demo2_bending_loop_steps");
  bool found = false;
  for (const auto& s : r.steps) found = found || s.effect == "bending_tension";
  c.value("d2b_steps", std::to_string(r.steps.size()));
  c.value("d2b_first", r.steps.empty() ? "none" : r.steps[0].variable + " → " + r.steps[0].effect);
  c.value("d2b_found", found ? "adds" : "does not add");
  c.value("d2b_rms_base", fmt(r.cv.front().rms, 4), "N");
  c.value("d2b_stop", r.stopped_because);
}

// Step 7.  Demonstration 2c: the RD/TD crossover at high speed (Table 5.16,
// Figs. 5.19/5.20).  Constant mu per direction and speed is fitted pin by pin
// (diluted lubricant); the RD - TD difference is compared with its pin-to-pin
// scatter, the only scatter fit-derived rows still carry.
void rd_td_crossover(Chapter& c, const Thesis& t) {
  const Design d = make_design(t.data, t.maps);
  auto w = c.table({"speed_mm_s", "mu_RD_mean", "mu_TD_mean", "diff_mean", "diff_se_pins", "t_ratio", "pins"},
                   "demonstration 2c: constant mu per direction and speed fitted per pin (diluted lubricant); RD - TD "
                   "difference, its standard error from the pin-to-pin scatter, and their ratio");
  int decided = 0, speeds = 0;
  std::string sign_change;
  double prev = NAN;
  for (double v : {6.35, 25.4, 101.6}) {
    std::vector<double> diffs, rd, td;
    for (size_t p = 0; p < d.pins.size(); ++p) {
      std::vector<int> train;
      for (size_t i = 0; i < d.rows.size(); ++i) {
        const Sample& s = t.data.rows[i];
        if (s.rotating || (s.pin_d_mm == d.pins[p] && s.speed_mm_s == v && s.lubricant == "MP404 diluted"))
          train.push_back(static_cast<int>(i));
      }
      const Fit f = fit_model(d, ModelSpec{}, train);
      double mrd = NAN, mtd = NAN;
      for (const auto& q : f.params) {
        if (q.name.find("diluted | " + fmt(v) + " mm/s | RD") != std::string::npos && q.name.find("undiluted") == std::string::npos)
          mrd = q.value;
        if (q.name.find("diluted | " + fmt(v) + " mm/s | TD") != std::string::npos && q.name.find("undiluted") == std::string::npos)
          mtd = q.value;
      }
      if (std::isfinite(mrd) && std::isfinite(mtd)) diffs.push_back(mrd - mtd), rd.push_back(mrd), td.push_back(mtd);
    }
    if (diffs.size() < 2) continue;
    double m = 0, q = 0, mr = 0, mt = 0;
    for (size_t k = 0; k < diffs.size(); ++k) m += diffs[k], mr += rd[k], mt += td[k];
    m /= diffs.size(), mr /= diffs.size(), mt /= diffs.size();
    for (double x : diffs) q += (x - m) * (x - m);
    const double se = std::sqrt(q / (diffs.size() - 1) / diffs.size());
    const double tr = m / se;
    ++speeds;
    decided += std::abs(tr) > 4.30;  // two-sided 5 % t quantile, 2 degrees of freedom
    if (std::isfinite(prev) && (prev > 0) != (m > 0)) sign_change += (sign_change.empty() ? "" : ", ") + fmt(v) + " mm/s";
    prev = m;
    w.row({fmt(v), fmt(mr, 4), fmt(mt, 4), fmt(m, 3), fmt(se, 3), fmt(tr, 3), std::to_string(diffs.size())});
  }
  c.save(w, "demo2_rd_td");
  c.value("d2c_decided", std::to_string(decided));
  c.value("d2c_speeds", std::to_string(speeds));
  c.value("d2c_sign_change", sign_change.empty() ? "at no speed" : "at " + sign_change);
}

}  // namespace ch7
