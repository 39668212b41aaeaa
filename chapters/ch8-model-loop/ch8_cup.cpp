// Chapter 8 step 6: the cup (thesis Sec. 6.6) by the same loop.
//
// (a) Why is the punch force at 15 mm high?  Baseline: the Chapter 6 model
//     (src/sim/cup_case.hpp: isotropic J2 on the Table 5.1 RD curve, Table 6.1
//     mu(p, v), 20 kN blank holder, ASSUMED 5 mm punch and die radii).
//     Candidates, tried one after another on top of what was accepted:
//       - die corner radius 3 / 7.5 / 10 mm and punch corner radius 3 / 8 mm
//         (the tool drawing, Fig. 6.12, is missing: a plausible range);
//       - the published Voce flow curve (Hou 2020) instead of the table;
//       - combined hardening as the bending-force loop chose it on the
//         12.7 mm pin (not fitted on the cup): its Armstrong-Frederick back
//         stress (X_sat, gamma), carved out of the cup's current flow curve
//         as in the draw-bend model (modelloop::carved_isotropic_part), or its
//         split beta when --candidates ran split;
//       - Hill'48 with the published r-values (not fitted).
//     A candidate's member is chosen on case 1 (6.4 mm/s) and judged on
//     case 9 (77.1 mm/s, held out); it is accepted if the held-out error
//     falls by more than min_gain.  Case 9 differs from case 1 only in speed,
//     so this hold-out guards against fitting noise, not against a wrong
//     geometry: the page says so.  Frictionless runs bound friction's share.
// (b) The 2 x 2 attribution at 21 mm (Sec. 6.6.3): friction anisotropic
//     (Table 6.1 RD/TD) or isotropic (the RD/TD mean at every node) crossed
//     with von Mises or Hill'48 (published r-values, same flow curve), on the
//     final model's tools.  Per run: the largest plastic strain within 15 deg
//     of RD and of TD (the two bands are mirror images of the disk mesh), its
//     angle, the RD/TD cup sizes.  The isotropic/von Mises run measures the
//     mesh's own asymmetry (ideally none): the noise floor of the attribution.
// Forces for the full blank [kN]; lengths mm; speeds mm/s.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <variant>

#include <toml++/toml.h>

#include "ch8_steps.hpp"
#include "core/hash.hpp"
#include "core/toml_read.hpp"
#include "io/portable_paths.hpp"
#include "sim/cup_case.hpp"
#include "sim/deck_job.hpp"
#include "material/hardening_curve.hpp"
#include "modelloop/material_edits.hpp"

namespace ch8 {

using namespace drawbend;

namespace {

/// A cup model: tool radii and a material built from named typed parts.
struct CupModel {
  std::string label = "Chapter 6 model";
  double punch_r = NAN, die_r = NAN;         ///< NaN: the deck's assumed 5 mm
  std::optional<io::CurveVoce> voce;         ///< the Voce flow curve; none: the deck's tabulated curve
  double beta = -1;                          ///< split kinematic fraction, < 0: isotropic hardening
  double x_sat = 0, gamma = 0;               ///< Armstrong-Frederick back stress [MPa, -]; x_sat 0: none
  std::string curve;                         ///< the tabulated flow curve the back stress is carved from (CSV)
  std::optional<io::YieldSurface> hill;      ///< Hill'48's surface; none: von Mises
  std::string friction;                      ///< sim::CupSpec::friction
  bool combined() const { return beta >= 0 || x_sat > 0; }
  /// The material as the builder's --material text: io::to_toml_inline of the
  /// typed spec (no flow curve: the deck's, which the builder fills in);
  /// empty: the deck's material.
  std::string material() const {
    if (!voce && !combined() && !hill) return "";
    io::MaterialSpec m;
    m.type = hill ? io::MaterialType::hill48 : combined() ? io::MaterialType::j2_combined : io::MaterialType::j2;
    if (hill) m.surface = *hill;
    if (x_sat > 0) {  // the flow curve (Voce when chosen, else `curve`) less the back stress's saturation
      const material::HardeningCurve c =
          voce ? material::HardeningCurve::voce(voce->sigma0, voce->Q, voce->b) : material::HardeningCurve::load(curve);
      m.curve = io::CurveTable{c.plastic_strains(), modelloop::carved_isotropic_part(c, x_sat, gamma)};
      m.kinematic = io::KinematicChaboche{{gamma * x_sat}, {gamma}};
    } else {
      if (voce) m.curve = *voce;
      if (beta >= 0) m.kinematic = io::KinematicSplit{beta};
    }
    return io::to_toml_inline(m);
  }
};

struct CupSetup {
  std::string deck;
  double v1 = 0, v9 = 0, e1 = 0, e9 = 0, d_eval = 15, d_fail = 21, max_stroke = 17;
  long cycles_per_max = 30000;  ///< cycles for the Chapter 6 stroke (17 mm)
  int refine = 1;
};

sim::CupSpec spec_of(const CupSetup& s, const CupModel& m, double speed, double stroke) {
  sim::CupSpec c;
  c.deck = s.deck, c.speed = speed, c.stroke = stroke, c.refine = s.refine;
  c.cycles = static_cast<long>(s.cycles_per_max * stroke / s.max_stroke);
  c.punch_radius = m.punch_r, c.die_radius = m.die_r;
  c.material = m.material();
  c.friction = m.friction;
  return c;
}

/// The [material] of a material file, typed.
io::MaterialSpec material_file(const std::string& file) {
  const toml::table t = parse_toml_file(file);
  const auto* m = t["material"].as_table();
  if (!m) throw InputError(file + ": no [material] table");
  return io::read_material(*m, file);
}

/// The die radius as a calibrated input: the radius whose case-1 force meets
/// the measured `e1` [kN], by linear interpolation between the two radii tried
/// that bracket it; its uncertainty is half the bracketing interval (the
/// force between the tried radii is not known better than linear).  When no
/// tried radius brings the force down to e1, the value is a bound: at least
/// the largest radius tried.
void die_radius_calibration(Chapter& c, std::vector<double> r, std::vector<double> f, double e1) {
  std::vector<std::size_t> o(r.size());
  for (std::size_t k = 0; k < o.size(); ++k) o[k] = k;
  std::sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return r[a] < r[b]; });
  std::string value = "not calibrated: no radius brackets the measured force", unc = "";
  for (std::size_t j = 0; j + 1 < o.size(); ++j) {
    const double r0 = r[o[j]], r1 = r[o[j + 1]], f0 = f[o[j]], f1 = f[o[j + 1]];
    if ((f0 - e1) * (f1 - e1) <= 0 && f0 != f1) {
      value = fmt_fixed(r0 + (e1 - f0) * (r1 - r0) / (f1 - f0), 1) + " mm";
      unc = fmt_fixed(0.5 * (r1 - r0), 1) + " mm";
    }
  }
  if (unc.empty() && !o.empty()) {
    const std::size_t last = o.back();
    if (f[last] > e1) value = "at least " + fmt(r[last]) + " mm (the largest radius tried still gives " + fmt_fixed(f[last], 1) +
                              " kN against " + fmt(e1) + " kN: the end of the range, not a fit)";
  }
  std::string tried;
  for (std::size_t k : o) tried += (tried.empty() ? "" : ", ") + fmt(r[k]) + " mm: " + fmt_fixed(f[k], 1) + " kN";
  c.value("die_r_fitted", value);
  c.value("die_r_uncertainty", unc.empty() ? "not estimated (a bound)" : unc);
  c.value("die_r_tried", tried);
}

/// Runs cup specs, each a file-level job (sim/deck_job.hpp) through the case
/// pool: its deck in runs/cup_<io::portable_fingerprint> (as the draw-bend runs'
/// fb_<...>), the run folder kept, the result read back from it
/// (sim::read_cup_run); counts the runs and their wall time.
struct CupRunner {
  Chapter& c;
  bool reuse = false;
  int n_runs = 0;
  double wall = 0;
  std::vector<sim::CupResult> operator()(const std::vector<sim::CupSpec>& specs) {
    std::vector<std::string> names, texts;
    for (const auto& sp : specs) {
      texts.push_back(sim::cup_deck_text(sp));
      names.push_back("cup_" + hex64(io::portable_fingerprint(texts.back())));
    }
    const auto dirs = sim::run_jobs(names, texts, c.out("runs"), reuse, "Chapter 8's cup loop");
    std::vector<sim::CupResult> r;
    for (std::size_t k = 0; k < specs.size(); ++k) r.push_back(sim::read_cup_run(specs[k], dirs[k]));
    for (const auto& x : r) ++n_runs, wall += x.wall_seconds;
    return r;
  }
};

/// The cases of Table 6.5 the loop uses and the thesis's scalars.
CupSetup cup_setup(const Chapter& c) {
  CupSetup s;
  s.deck = c.data("cases/cup_draw.toml");
  const CsvTable t65 = read_csv(c.data("thesis/table_6_5.csv"));
  const std::string sc = c.data("thesis/scalars.csv");
  s.v1 = t65.number(t65.rows.front(), "punch_speed_mm_s");
  s.v9 = t65.number(t65.rows.back(), "punch_speed_mm_s");
  s.e1 = study::scalar(sc, "ch6_punch_force_exp_case1").value;
  s.e9 = study::scalar(sc, "ch6_punch_force_exp_case9").value;
  s.d_eval = study::scalar(sc, "ch6_punch_force_eval_displacement").value;
  s.d_fail = study::scalar(sc, "ch6_failure_stroke").value;
  s.max_stroke = study::scalar(sc, "ch6_max_stroke").value;
  s.refine = 1, s.cycles_per_max = 30000;
  return s;
}

/// The bending loop's combined hardening, chosen on the 12.7 mm pin: split's
/// beta or the back stress (X_sat = C / gamma, one term).
struct BendingHardening {
  double beta = -1, x_sat = 0, gamma = 0;
};

/// Read from the accepted members' materials (inline tables), typed
/// (modelloop::material_of): the last accepted split or back stress.
BendingHardening bending_hardening(const modelloop::ModelLoopResult& bending) {
  BendingHardening h;
  for (const auto& st : bending.steps)
    if (!st.spec.material.empty() && st.spec.material.front() == '{') {
      const io::MaterialSpec m = modelloop::material_of(st.spec);
      if (!m.kinematic) continue;
      if (const auto* b = std::get_if<io::KinematicSplit>(&*m.kinematic)) h.beta = b->beta, h.x_sat = 0;
      const auto* ch = std::get_if<io::KinematicChaboche>(&*m.kinematic);
      if (ch && !ch->C.empty() && !ch->gamma.empty() && ch->gamma[0] > 0)
        h.x_sat = ch->C[0] / ch->gamma[0], h.gamma = ch->gamma[0], h.beta = -1;
    }
  return h;
}

/// The cup deck's own flow curve (a CSV path relative to the deck).
std::string deck_flow_curve(const std::string& deck_path) {
  const io::CaseSpec deck = io::read_case(deck_path);
  const io::CurveFile* f = deck.material && deck.material->curve ? std::get_if<io::CurveFile>(&*deck.material->curve) : nullptr;
  if (!f) throw InputError(deck_path + ": [material] hardening: expected the path of a flow-curve CSV");
  return (std::filesystem::path(deck_path).parent_path() / f->path).lexically_normal().string();
}

/// A candidate of the cup loop: named members, each an edit of the current model.
struct Cand {
  std::string name;
  std::vector<std::pair<std::string, std::function<void(CupModel&)>>> members;
};

/// The candidates, in the order tried (the die radius first: die_radius_calibration reads it).
std::vector<Cand> cup_candidates(const io::CurveVoce& voce, const io::YieldSurface& hill, const BendingHardening& bh,
                                 const std::string& rd_curve) {
  std::vector<Cand> cands;
  Cand d{"die corner radius (ASSUMED 5 mm)", {}};
  for (double r : {3.0, 7.5, 10.0}) d.members.push_back({"die radius " + fmt(r) + " mm", [r](CupModel& m) { m.die_r = r; }});
  cands.push_back(d);
  Cand p{"punch corner radius (ASSUMED 5 mm)", {}};
  for (double r : {3.0, 8.0}) p.members.push_back({"punch radius " + fmt(r) + " mm", [r](CupModel& m) { m.punch_r = r; }});
  cands.push_back(p);
  cands.push_back({"Voce flow curve (Hou 2020)", {{"Voce", [voce](CupModel& m) { m.voce = voce; }}}});
  const double beta = bh.beta, x_sat = bh.x_sat, gamma = bh.gamma;
  if (beta >= 0)
    cands.push_back({"split combined hardening (beta from the bending loop)",
                     {{"split beta " + fmt(beta), [beta](CupModel& m) { m.beta = beta; }}}});
  if (x_sat > 0)
    cands.push_back({"back stress (X_sat, gamma from the bending loop)",
                     {{"back stress X_sat " + fmt(x_sat) + " MPa, gamma " + fmt(gamma),
                       [x_sat, gamma, rd_curve](CupModel& m) { m.x_sat = x_sat, m.gamma = gamma, m.curve = rd_curve; }}}});
  cands.push_back({"Hill'48 (Hou 2020 r-values)", {{"Hill'48", [hill](CupModel& m) { m.hill = hill; }}}});
  return cands;
}

double rel_err(double f, double e) { return f / e - 1; }

/// The state of the punch-force loop (a): the current model and its forces at
/// the evaluation stroke [kN] on cases 1 and 9.
struct CupLoopState {
  CupModel cur;
  double f1 = 0, f9 = 0;            ///< the current model's forces
  double base_f1 = 0, base_f9 = 0;  ///< the Chapter 6 model's
  double c1 = 0, c9 = 0;            ///< the final model on the checked mesh
  double nofric_f1 = 0;             ///< the final model without friction, case 1
  std::vector<double> die_r, die_f; ///< the die radii tried on case 1 [mm] and their forces [kN]
};

/// The punch force at the evaluation stroke [kN].
double f_eval(const CupSetup& s, const sim::CupResult& r) { return sim::force_at(r, s.d_eval) / 1000; }

/// One candidate of (a): its members on case 1, the best on case 9 (held
/// out), accepted when the held-out error falls by more than min_gain; its
/// rows of the steps and figure tables.
void try_candidate(const Cand& cand, bool first, const CupSetup& s, double stroke, double min_gain, CupRunner& run,
                   CupLoopState& st, CsvWriter& steps, CsvWriter& fig, int& fig_rows) {
  std::vector<CupModel> ms;
  std::vector<sim::CupSpec> specs;
  for (const auto& [name, apply] : cand.members) {
    CupModel m = st.cur;
    apply(m);
    m.label = (st.cur.label == "Chapter 6 model" ? "" : st.cur.label + " + ") + name;
    ms.push_back(m);
    specs.push_back(spec_of(s, m, s.v1, stroke));
  }
  const auto r = run(specs);
  std::size_t best = 0;
  std::string members;
  for (std::size_t k = 0; k < r.size(); ++k) {
    members += (members.empty() ? "" : "; ") + cand.members[k].first + ": " + fmt_fixed(f_eval(s, r[k]), 2);
    if (std::abs(rel_err(f_eval(s, r[k]), s.e1)) < std::abs(rel_err(f_eval(s, r[best]), s.e1))) best = k;
  }
  if (first) {  // the die radius: the baseline's 5 mm and the members
    st.die_r.push_back(std::isnan(st.cur.die_r) ? 5.0 : st.cur.die_r);  // NaN: the deck's ASSUMED 5 mm (cup_case.hpp)
    st.die_f.push_back(st.f1);
    for (std::size_t k = 0; k < r.size(); ++k) st.die_r.push_back(ms[k].die_r), st.die_f.push_back(f_eval(s, r[k]));
  }
  const auto r9 = run({spec_of(s, ms[best], s.v9, stroke)});
  const double g1 = f_eval(s, r[best]), g9 = f_eval(s, r9[0]);
  const double gain = std::abs(rel_err(st.f9, s.e9)) - std::abs(rel_err(g9, s.e9));
  const bool accept = gain > min_gain;
  steps.row({cand.name, members, cand.members[best].first, fmt_fixed(g1, 2), pct(rel_err(g1, s.e1)), fmt_fixed(g9, 2),
             pct(rel_err(g9, s.e9)),
             accept ? "accepted (held-out error falls " + fmt_fixed(100 * gain, 1) + " points)"
                    : "rejected (held-out error falls " + fmt_fixed(100 * gain, 1) + " points, needs > " +
                          fmt_fixed(100 * min_gain, 0) + ")"});
  fig.row({std::to_string(fig_rows++), cand.members[best].first + (accept ? " (accepted)" : " (rejected)"), fmt(g1, 5),
           fmt(g9, 5)});
  if (accept) st.cur = ms[best], st.f1 = g1, st.f9 = g9;
}

/// (a) The punch-force loop: the baseline, each candidate in turn, the
/// frictionless bound, and the final model on the checked mesh (the full
/// tier: refined); the steps table, the die radius, the figure.
CupLoopState punch_force_loop(Chapter& c, const Config& cfg, const CupSetup& s, const CupSetup& fine,
                              const std::vector<Cand>& cands, CupRunner& run) {
  const double stroke = s.d_eval + 0.5;  // just past the evaluation point
  CupLoopState st;
  const auto base = run({spec_of(s, st.cur, s.v1, stroke), spec_of(s, st.cur, s.v9, stroke)});
  st.f1 = f_eval(s, base[0]), st.f9 = f_eval(s, base[1]);
  st.base_f1 = st.f1, st.base_f9 = st.f9;
  auto steps = c.table({"candidate", "members_case1_kN", "chosen", "case1_kN", "case1_err_pct", "case9_kN",
                        "case9_err_pct", "decision"},
                       "the cup loop: punch force at " + fmt(s.d_eval) + " mm (full blank, kN); members judged on case 1 "
                       "(" + fmt(s.v1) + " mm/s), the chosen member on case 9 (" + fmt(s.v9) + " mm/s, held out); measured " +
                       fmt(s.e1) + " / " + fmt(s.e9) + " kN (Sec. 6.6.2); " + (s.refine > 1 ? "refined" : "coarse") + " mesh");
  steps.row({"baseline", "", st.cur.label, fmt_fixed(st.f1, 2), pct(rel_err(st.f1, s.e1)), fmt_fixed(st.f9, 2),
             pct(rel_err(st.f9, s.e9)), ""});
  auto fig = c.table({"step", "model", "case1_kN", "case9_kN"}, "punch force at 15 mm per model of the loop, for the figure");
  fig.row({"0", "Chapter 6 model", fmt(st.f1, 5), fmt(st.f9, 5)});
  int fig_rows = 1;
  for (const auto& cand : cands)
    try_candidate(cand, &cand == &cands.front(), s, stroke, cfg.min_gain, run, st, steps, fig, fig_rows);
  // Friction's share: the final model without friction (a bound, not a candidate).
  CupModel nofric = st.cur;
  nofric.friction = "none";
  const auto rn = run({spec_of(s, nofric, s.v1, stroke)});
  st.nofric_f1 = f_eval(s, rn[0]);
  steps.row({"bound: no friction", "", st.cur.label == "Chapter 6 model" ? "frictionless" : st.cur.label + ", frictionless",
             fmt_fixed(st.nofric_f1, 2), pct(rel_err(st.nofric_f1, s.e1)), "", "",
             "not a candidate: friction's share of the force"});
  // The final model on the checked mesh (the full tier: refined).
  st.c1 = st.f1, st.c9 = st.f9;
  if (fine.refine != s.refine) {
    // (The baseline on this mesh is Chapter 6's full tier: not run again here.)
    const auto rf = run({spec_of(fine, st.cur, s.v1, stroke), spec_of(fine, st.cur, s.v9, stroke)});
    st.c1 = f_eval(s, rf[0]), st.c9 = f_eval(s, rf[1]);
    steps.row({"confirm: refined mesh", "", st.cur.label, fmt_fixed(st.c1, 2), pct(rel_err(st.c1, s.e1)),
               fmt_fixed(st.c9, 2), pct(rel_err(st.c9, s.e9)), "the final model on the checked mesh"});
  }
  c.save(steps, "cup_loop_steps");
  die_radius_calibration(c, st.die_r, st.die_f, s.e1);
  c.save(fig, "cup_figure");
  c.plot("cup_loop", "cup_loop", {{"datafile", c.out("tables/cup_figure.csv")}, {"e1", fmt(s.e1)}, {"e9", fmt(s.e9)},
                                  {"v1", fmt(s.v1)}, {"v9", fmt(s.v9)}});
  return st;
}

/// (a)'s values for the page and its checks on the final model.
void report_punch_force_loop(Chapter& c, const CupSetup& s, const CupSetup& fine, const CupLoopState& st) {
  const std::string tier = fine.refine > 1 ? " (refined mesh)" : " (coarse mesh)";
  c.value("cup_final_model", st.cur.label);
  c.value("cup_check_mesh", fine.refine > 1 ? "refined mesh (the full tier)" : "coarse mesh (the quick tier)");
  c.value("cup_check_f1", fmt_fixed(st.c1, 2), "kN");
  c.value("cup_check_f9", fmt_fixed(st.c9, 2), "kN");
  c.value("cup_check_err1", pct(rel_err(st.c1, s.e1)), "%");
  c.value("cup_check_err9", pct(rel_err(st.c9, s.e9)), "%");
  c.value("cup_base_f1", fmt_fixed(st.base_f1, 2), "kN");
  c.value("cup_base_f9", fmt_fixed(st.base_f9, 2), "kN");
  c.value("cup_base_err1", pct(rel_err(st.base_f1, s.e1)), "%");
  c.value("cup_base_err9", pct(rel_err(st.base_f9, s.e9)), "%");
  c.value("cup_final_f1", fmt_fixed(st.f1, 2), "kN");
  c.value("cup_final_f9", fmt_fixed(st.f9, 2), "kN");
  c.value("cup_final_err1", pct(rel_err(st.f1, s.e1)), "%");
  c.value("cup_final_err9", pct(rel_err(st.f9, s.e9)), "%");
  c.value("cup_nofric_f1", fmt_fixed(st.nofric_f1, 2), "kN");
  c.value("cup_friction_share", fmt_fixed(100 * (1 - st.nofric_f1 / st.f1), 0), "%");
  const std::string why = "10 % of the measured force: the accuracy goal for the cup (issue 23); the thesis's own model "
                          "came within 3 %";
  // Not agreement: the tool radii were chosen on case 1 (fitted), and case 9,
  // which differs from it only in punch speed, accepted each change
  // (selected).  No cup case played no part in the choice, so the die radius
  // is reported as a calibrated input (die_radius_calibration above).
  c.checks().agree(study::Kind::fitted, "ch8.cup.f15.case1", "punch force at 15 mm, case 1, final cup model" + tier, s.e1,
                   st.c1, 0.10 * s.e1, "kN", why + "; the radii are fitted on this case");
  c.checks().agree(study::Kind::selected, "ch8.cup.f15.case9", "punch force at 15 mm, case 9, final cup model" + tier, s.e9,
                   st.c9, 0.10 * s.e9, "kN", why + "; this case accepted each change (it differs from case 1 only in speed)");
}

/// (b)'s four runs at the failure stroke, case 1, on the final model's tools:
/// friction isotropic (RD/TD mean) or anisotropic (Table 6.1) crossed with von
/// Mises or Hill'48, in that order (isotropic/von Mises first).
std::vector<sim::CupResult> attribution_runs(Chapter& c, const CupSetup& s, const CupSetup& fine, const CupModel& cur,
                                             const io::YieldSurface& hill, CupRunner& run) {
  const std::string iso_nodes = c.out("tables/table_6_1_isotropic.csv");
  sim::write_isotropic_nodes(c.data("thesis/table_6_1.csv"), iso_nodes);
  std::vector<CupModel> grid;
  for (int fr = 0; fr < 2; ++fr)
    for (int mat = 0; mat < 2; ++mat) {
      CupModel m;
      m.punch_r = cur.punch_r, m.die_r = cur.die_r;
      m.friction = fr ? "" : iso_nodes;
      if (mat) m.hill = hill;
      m.label = std::string(fr ? "anisotropic friction (Table 6.1)" : "isotropic friction (RD/TD mean)") + ", " +
                (mat ? "Hill'48" : "von Mises");
      grid.push_back(m);
    }
  std::vector<sim::CupSpec> gs;
  for (const auto& m : grid) gs.push_back(spec_of(fine, m, s.v1, s.d_fail));
  return run(gs);
}

/// (b) The 2 x 2 attribution at 21 mm: its table, each factor's shift, the
/// answer, and the symmetry check of the isotropic/von Mises run.
void attribution(Chapter& c, const CupSetup& s, const CupSetup& fine, const std::vector<sim::CupResult>& ga) {
  const std::string tier = fine.refine > 1 ? " (refined mesh)" : " (coarse mesh)";
  auto at = c.table({"friction", "material", "band_RD", "band_TD", "RD_minus_TD", "max_strain", "at_angle_from_RD_deg",
                     "cup_size_RD_mm", "cup_size_TD_mm", "RD_minus_TD_size_mm", "hourglass_over_internal"},
                    "2 x 2 attribution at " + fmt(s.d_fail) + " mm, case 1" + tier + ": largest plastic strain within 15 deg "
                    "of RD and of TD, its angle, and the cup sizes along RD and TD (flange outer diameter, mm)");
  std::vector<double> d(4), dsize(4);
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& r = ga[k];
    d[k] = r.band_rd - r.band_td;
    dsize[k] = r.size_rd - r.size_td;
    at.row({k >= 2 ? "anisotropic" : "isotropic", k % 2 ? "Hill'48" : "von Mises", fmt_fixed(r.band_rd, 4),
            fmt_fixed(r.band_td, 4), fmt_fixed(d[k], 4), fmt_fixed(r.max_strain, 4), fmt_fixed(r.max_strain_angle, 1),
            fmt_fixed(r.size_rd, 2), fmt_fixed(r.size_td, 2), fmt_fixed(dsize[k], 2), fmt(r.hourglass_ratio, 3)});
  }
  c.save(at, "cup_attribution");
  // Each factor alone and both together, against the isotropic/von Mises run,
  // on RD band minus TD band (> 0: the peak is along RD, where the cup failed).
  const double fric = d[2] - d[0], mat = d[1] - d[0], both = d[3] - d[0];
  const double noise = std::abs(d[0]);  // isotropic friction and von Mises: 0 by mirror symmetry
  c.value("attr_fric", fmt(fric, 3));
  c.value("attr_mat", fmt(mat, 3));
  c.value("attr_both", fmt(both, 3));
  c.value("attr_noise", fmt(noise, 2));
  c.value("attr_size_fric", fmt_fixed(dsize[2] - dsize[0], 2), "mm");
  c.value("attr_size_mat", fmt_fixed(dsize[1] - dsize[0], 2), "mm");
  c.value("attr_size_both", fmt_fixed(dsize[3] - dsize[0], 2), "mm");
  // Clear when one factor alone puts the peak in RD by more than three times
  // both the other factor's shift and the mesh's own asymmetry.
  auto clear = [&](double a, double b) { return a > 3 * std::abs(b) && a > 3 * noise; };
  std::string answer = clear(fric, mat)  ? "frictional anisotropy: alone it moves the peak towards RD by " + fmt(fric, 2) +
                                               ", more than three times the material's shift (" + fmt(mat, 2) + ")"
                       : clear(mat, fric) ? "material anisotropy: alone it moves the peak towards RD by " + fmt(mat, 2) +
                                               ", more than three times the friction's shift (" + fmt(fric, 2) + ")"
                                          : "neither factor alone clearly (friction " + fmt(fric, 2) + ", material " +
                                                fmt(mat, 2) + ")";
  answer += "; with both, the peak lies along " + std::string(both > 0 ? "RD" : "TD") + " (" + fmt(both, 2) + ")";
  c.value("attr_answer", answer);
  // The mesh is a mirror image about 45 deg: with isotropic friction and material the
  // two bands must agree.  Tolerance: 2 % of the band strain, the relative size of
  // the loading's only asymmetry left (roundoff and the order of the node sums).
  const double band0 = 0.5 * (ga[0].band_rd + ga[0].band_td);
  c.checks().agree(study::Kind::verification, "ch8.cup.attr.symmetry",
                   "RD band minus TD band, isotropic friction and von Mises at " + fmt(s.d_fail) + " mm" + tier, 0.0, d[0],
                   0.02 * band0, "-",
                   "2 % of the band strain: the quarter disk is a mirror image about 45 deg, so only roundoff and the "
                   "order of node sums may separate the bands");
}

}  // namespace

void cup_loop(Chapter& c, const Config& cfg, const modelloop::ModelLoopResult& bending) {
  const CupSetup s = cup_setup(c);
  // The loop runs on Chapter 6's coarse mesh in both tiers (20 runs); the full
  // tier confirms the final model and runs the attribution on Chapter 6's
  // refined mesh (elements x 8, 160000 cycles per 17 mm), whose forces are
  // the ones checked there.
  CupSetup fine = s;
  if (cfg.full_study) fine.refine = 2, fine.cycles_per_max = 160000;
  const io::YieldSurface hill = material_file(c.data("materials/aa5754_o_hill48_hou2020.toml")).surface;
  const io::MaterialSpec voce_file = material_file(c.data("materials/aa5754_o_voce_hou2020.toml"));
  if (!voce_file.curve || !std::holds_alternative<io::CurveVoce>(*voce_file.curve))
    throw InputError(c.data("materials/aa5754_o_voce_hou2020.toml") + ": [material] voce: expected a Voce flow curve");
  const io::CurveVoce voce = std::get<io::CurveVoce>(*voce_file.curve);
  const std::vector<Cand> cands = cup_candidates(voce, hill, bending_hardening(bending), deck_flow_curve(s.deck));
  CupRunner run{c, cfg.reuse_runs};
  const CupLoopState st = punch_force_loop(c, cfg, s, fine, cands, run);  // (a)
  report_punch_force_loop(c, s, fine, st);
  attribution(c, s, fine, attribution_runs(c, s, fine, st.cur, hill, run));  // (b)
  c.value("cup_loop_runs", std::to_string(run.n_runs));
  c.value("cup_loop_wall", fmt_fixed(run.wall, 0), "s");
}

}  // namespace ch8
