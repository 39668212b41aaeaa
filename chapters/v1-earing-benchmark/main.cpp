// Validation chapter v1: the ESAFORM 2021 cup-drawing benchmark (AA6016-T4
// earing; Habraken et al. 2022, doi 10.1007/s12289-022-01672-w).  A prediction
// from the published inputs only: nothing here is fitted to the measured cup.
// Recipe (body(), one named step a line; the options are a Config):
//   1.  read_variants: the material variants (data/benchmarks/esaform2021.csv)
//       and the deck (data/cases/esaform2021_cup.toml: tools, blank, mu, E,
//       Swift); --variants keeps a diagnostic subset.
//   1b. calibrate_yld2004 (v1_calibration.cpp): Yld2004-18p fitted to the published sheet tests;
//       the calibration table beside Hill'48 and POSTECH's Yld2004-18p.
//       The numbers the prose quotes from it are values (v1_yield_values.cpp).
//   2.  state_bounds: the checks' bounds before any run: the mesh's own
//       departure from polar symmetry bounds the von Mises earing; the
//       r-values give the ear positions (r0, r90 > r45: ears at 0 and 90 deg).
//   3.  draw_cups: the cups side by side (quarter blank, >= 3 elements through
//       the thickness), each a file-level job in runs/v1_cup_<variant>.
//   4.  tabulate_cup: cup height and flange outline against angle (ears,
//       troughs), punch force against stroke, thickness along RD, 45 deg and
//       TD, hourglass energy by region; the .vtu.
//   5.  check_cup: volume, energies, hourglass, fold and tear, flange out.
//   5b. compare_variants (every variant drawn): von Mises earing below a
//       tenth of Hill'48's; ears where the r-values put them.
//   6.  figures: earing, punch force, thickness.
//
// Sample runs:
//   chapter_v1_earing_benchmark --out build/chapters/v1-earing-benchmark
//       (the quick tier, `ctest -R chapter.v1-earing-benchmark`: a 20 mm stroke)
//   chapter_v1_earing_benchmark --tier full --stroke 50 --cycles 150000 --ring 30
//       (the full tier: the cups drawn out)
//   chapter_v1_earing_benchmark --variants yld2004 --gap 1.25 --holder-force -1
//       (diagnostic, results.md: one variant, rigid holder, wider gap; tables only)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>

#include "material/hill48.hpp"
#include "sim/case_pool.hpp"
#include "sim/executor.hpp"
#include "study/run_health.hpp"
#include "study/chapter.hpp"
#include "v1_cup.hpp"
#include "v1_calibration.hpp"

using namespace drawbend;

namespace {

/// The chapter's options (main() binds each to its command-line name).
struct Config {
  int core = 6, ring = 22, through = 3;  ///< quarter_disk element counts
  double cycles = 60000;                 ///< cycles over the stroke
  double stroke = 20.0;                  ///< punch travel [mm] (quick tier: to the force peak)
  double ramp = 10;                      ///< punch travel of the speed ramp [mm]
  double polar = -1;                     ///< quarter_disk polar_radius [mm] (< 0: the deck's; 0: none)
  // Diagnostic runs (docs: results.md "Why the low-r cups tore"): a subset of the variants and process alternatives.
  std::string variants;  ///< comma-separated variant ids (empty: all, the chapter's run)
  std::string yld_set;  ///< diagnostic run: the yld2004 variant's set from this TOML instead of the fit
  double gap = 0, holder_force = 0, mu = -1, clearance = 0;
  bool voce = false;
};

/// The variants to draw (every one, or a diagnostic run's subset) and the published Hill'48 inputs.
struct Variants {
  std::vector<v1::Variant> list;
  std::map<std::string, std::size_t> idx;  ///< variant id -> index into list
  v1::Variant hr, hsv;                     ///< the published r-values and stress ratios (hill48_r, hill48_s)
  bool subset = false;                     ///< a diagnostic run (--variants): the comparisons are not claimed
};

/// What is stated before any run (step 2).
struct Bounds {
  double r_mid = 0;    ///< the flange's mid radius [mm]
  double e_mesh = 0;   ///< the mesh's angular error there (relative)
  double rp = 0;       ///< rows are circles from here out [mm] (0: none)
  double r_min = 0;    ///< the lowest published r-value
  bool ears_at_axes = false;  ///< what the r-values say: r0, r90 > r45
};

/// The chapter's tables, filled run by run (step 4).
struct CupTables {
  drawbend::CsvWriter ht, ot, ft, tt, gt, st;
  void save(study::Chapter& c) const {
    c.save(ht, "cup_height");
    c.save(ot, "flange_outline");
    c.save(ft, "punch_force");
    c.save(tt, "thickness");
    c.save(gt, "hourglass_regions");
    c.save(st, "summary");
  }
};

std::string fmt_list(const std::vector<std::pair<double, double>>& v) {
  std::string s;
  for (const auto& [a, h] : v) s += (s.empty() ? "" : "; ") + fmt_fixed(a, 1) + "° at " + fmt_fixed(h, 2) + " mm";
  return s.empty() ? "none" : s;
}

/// Extremes of a profile: angle and value of its highest and lowest point, and its mean.
std::array<double, 5> profile_extremes(const std::vector<std::pair<double, double>>& p) {
  auto lo = p.front(), hi = p.front();
  double mean = 0;
  for (const auto& q : p) {
    mean += q.second / static_cast<double>(p.size());
    if (q.second > hi.second) hi = q;
    if (q.second < lo.second) lo = q;
  }
  return std::array<double, 5>{hi.first, hi.second, lo.first, lo.second, mean};
}

/// The profile's value at the angle nearest `a` [deg].
double profile_at(const std::vector<std::pair<double, double>>& p, double a) {
  std::pair<double, double> best = p.front();
  for (const auto& q : p)
    if (std::abs(q.first - a) < std::abs(best.first - a)) best = q;
  return best.second;
}

/// Step 1: the material variants of the benchmark table (a diagnostic run keeps the listed ones).
Variants read_variants(const CsvTable& vt, const Config& cfg) {
  Variants vs;
  for (const auto& row : vt.rows) {
    v1::Variant v;
    v.id = vt.text(row, "variant");
    v.type = vt.text(row, "type");
    v.label = vt.text(row, "label");
    const auto num = [&](const char* k) { return vt.text(row, k).empty() ? 0.0 : vt.number(row, k); };
    v.r0 = num("r0"), v.r45 = num("r45"), v.r90 = num("r90");
    v.s45 = num("s45"), v.s90 = num("s90"), v.sb = num("sb");
    vs.list.push_back(v);
  }
  for (std::size_t k = 0; k < vs.list.size(); ++k) vs.idx[vs.list[k].id] = k;
  for (const char* need : {"von_mises", "hill48_r", "hill48_s"})
    if (!vs.idx.count(need)) throw InputError(vt.path + ": missing variant " + need);
  vs.hr = vs.list[vs.idx.at("hill48_r")], vs.hsv = vs.list[vs.idx.at("hill48_s")];
  // A diagnostic run draws only the listed variants; the checks that compare variants then are not claimed
  // (the chapter's own run, with every variant, claims them all).
  vs.subset = !cfg.variants.empty();
  if (vs.subset) {
    std::vector<v1::Variant> keep;
    std::string rest = cfg.variants + ",";
    for (std::size_t p; (p = rest.find(',')) != std::string::npos; rest.erase(0, p + 1)) {
      const std::string id = rest.substr(0, p);
      if (!vs.idx.count(id)) throw InputError("--variants: no variant '" + id + "' in " + vt.path);
      keep.push_back(vs.list[vs.idx.at(id)]);
    }
    vs.list = keep;
    vs.idx.clear();
    for (std::size_t k = 0; k < vs.list.size(); ++k) vs.idx[vs.list[k].id] = k;
  }
  return vs;
}

/// The mesh and loading of every run, from the options.
v1::RunSpec run_spec(const Config& cfg) {
  v1::RunSpec spec;
  spec.core = cfg.core, spec.ring = cfg.ring, spec.through = cfg.through;
  spec.cycles = static_cast<long>(cfg.cycles), spec.stroke = cfg.stroke;
  spec.polar_radius = cfg.polar;
  spec.ramp = cfg.ramp;
  spec.gap = cfg.gap, spec.holder_force = cfg.holder_force, spec.mu = cfg.mu, spec.voce = cfg.voce;
  spec.clearance = cfg.clearance;
  if (cfg.clearance != 0 && !(cfg.clearance >= 1.0 && cfg.clearance <= 10.0))  // NaN too
    throw InputError("--clearance: the punch-die clearance must lie between the blank's 1.0 mm thickness and 10 mm "
                     "(0: the published 1.2 mm)");
  // The remaining options, checked here so that a bad value names its option instead of surfacing as an
  // infinite step duration in the written deck, or as a run that finishes with a meaningless cup.
  if (!(cfg.stroke > 0.0 && cfg.stroke <= 100.0))  // NaN too
    throw InputError("--stroke: the punch travel must lie in (0, 100] mm (the full draw is 50 mm)");
  if (!(cfg.cycles >= 1000.0 && cfg.cycles <= 1e9))
    throw InputError("--cycles: at least 1000 and at most 1e9 explicit cycles over the stroke");
  if (!(cfg.ramp >= 0.0 && cfg.ramp <= cfg.stroke))
    throw InputError("--ramp: the punch's speed ramp must lie between 0 and the stroke [mm]");
  if (cfg.gap != 0 && !(cfg.gap >= 1.0 && cfg.gap <= 10.0))
    throw InputError("--gap: the holder-die gap must lie between the blank's 1.0 mm thickness and 10 mm "
                     "(0: the published 1.04 mm)");
  if (!(cfg.mu < 0 || cfg.mu <= 1.0))  // < 0: the published value; NaN fails
    throw InputError("--mu: the Coulomb coefficient must lie in [0, 1] (< 0: the published 0.07)");
  if (!std::isfinite(cfg.holder_force))
    throw InputError("--holder-force: expected a finite force [N] (0: the deck's; < 0: the holder fixed at the gap)");
  return spec;
}

/// A full draw or a partial stroke?  By its area, the blank (r = 53.75 mm) makes a wall of about
/// (53.75^2 - 30.6^2) / (2 x 30.6) = 32 mm over the 30.6 mm mid-wall radius; its rim clears the die's shoulder
/// (z = 11.04 mm) after about 32 + 11 = 43 mm of punch travel.  From 45 mm on the cup is drawn out.
bool drawn_out(const v1::RunSpec& spec) { return spec.stroke >= 45.0; }

/// Step 2: the bounds, stated before the run, and what each Hill'48 calibration implies.
Bounds state_bounds(study::Chapter& c, const std::string& deck, const v1::RunSpec& spec, const Variants& vs) {
  Bounds b;
  // The O-grid is mirror-symmetric about 45 deg but not polar: at the flange's mid radius (between the die
  // opening, 31.2 mm, and the blank's edge) its ring elements span unequal angles.  A hoop strain represented
  // with that relative error moves the rim by about the same fraction of the cup height: the von Mises cup's
  // (h_max - h_min) / h_mean must stay below it.
  b.r_mid = 0.5 * (31.2 + 53.75);
  b.e_mesh = v1::mesh_angular_error(deck, spec, b.r_mid);
  c.value("mesh_error_pct", fmt_fixed(100 * b.e_mesh, 2), "%");
  c.value("mesh_error_r", fmt_fixed(b.r_mid, 1), "mm");
  b.rp = v1::polar_start(deck, spec);  // rows are circles from here out [mm] (0: none)
  c.value("polar_radius", fmt_fixed(b.rp, 1), "mm");
  const v1::Variant& hr = vs.hr;
  b.r_min = std::min({hr.r0, hr.r45, hr.r90});  // the lowest published r-value
  b.ears_at_axes = hr.r0 > hr.r45 && hr.r90 > hr.r45;  // what the r-values say
  c.value("r_rule", b.ears_at_axes ? "r0 and r90 above r45: ears at 0° and 90°, a trough at 45°"
                                   : "r45 not below both r0 and r90");
  // What each Hill'48 calibration implies at 0, 45, 90 deg (closed forms, src/material/hill48.hpp): the r-value
  // fit cannot also match the stress ratios, and the stress fit not the r-values.
  auto ct = c.table({"variant", "r0", "r45", "r90", "s45", "s90", "sb"},
                    "Hill'48 calibrations: r-values and yield-stress ratios to RD that each implies (published: r = "
                    "0.525/0.248/0.429, s45/s90/sb = 0.867/0.926/0.975)");
  for (const auto& v : vs.list) {
    if (v.type != "hill48") continue;
    const auto h = v.r0 > 0 ? material::Hill48::from_r_values(v.r0, v.r45, v.r90)
                            : material::Hill48::from_stress_ratios(v.s45, v.s90, v.sb);
    const double q = std::acos(-1.0) / 4;
    ct.row({v.id, fmt_fixed(h.r_value(0), 3), fmt_fixed(h.r_value(q), 3), fmt_fixed(h.r_value(2 * q), 3),
            fmt_fixed(h.uniaxial_ratio(q), 3), fmt_fixed(h.uniaxial_ratio(2 * q), 3), fmt_fixed(h.biaxial_ratio(), 3)});
    c.value(v.id + "_implied", "r = " + fmt_fixed(h.r_value(0), 2) + "/" + fmt_fixed(h.r_value(q), 2) + "/" +
                                   fmt_fixed(h.r_value(2 * q), 2) + ", σ45/σ0 = " + fmt_fixed(h.uniaxial_ratio(q), 3) +
                                   ", σ90/σ0 = " + fmt_fixed(h.uniaxial_ratio(2 * q), 3) +
                                   ", σb/σ0 = " + fmt_fixed(h.biaxial_ratio(), 3));
    c.value(v.id + "_sb", fmt_fixed(h.biaxial_ratio(), 3));
  }
  c.save(ct, "hill48_calibrations");
  return b;
}

/// Step 3: the cups, side by side, each a file-level job with its run folder, runs/v1_cup_<variant>.
std::vector<v1::CupResult> draw_cups(study::Chapter& c, const std::string& deck, const Variants& vs,
                                     const v1::RunSpec& spec) {
  const auto& vars = vs.list;
  std::vector<v1::CupResult> runs(vars.size());
  const auto wall0 = std::chrono::steady_clock::now();
  sim::run_cases(vars.size(), [&](std::size_t k) {
    runs[k] = v1::draw(deck, vars[k], spec, c.out("tables/cup_" + vars[k].id + ".vtu"), c.out("runs/v1_cup_" + vars[k].id));
  }, {}, sim::executor_jobs(sim::executor(), sim::default_case_jobs()));
  {  // the Yld2004-18p return map's health over the runs (every point update of the Yld2004-18p cups), as
     // each run counted it in its summary.csv: the same whichever executor ran the cup
    long plastic = 0, split = 0, fallback = 0;
    int cups = 0;
    for (std::size_t k = 0; k < vars.size(); ++k) {
      if (vars[k].type != "yld2004") continue;
      const auto& n = runs[k].material_counts;
      const auto at = [&](const char* q) {
        if (!n.count(q)) throw InputError(c.out("runs/v1_cup_" + vars[k].id + "/summary.csv") + ": no material_" + q);
        return n.at(q);
      };
      plastic += at("plastic_updates"), split += at("split_updates"), fallback += at("fallback_updates");
      ++cups;
    }
    c.value("yld_returns", cups == 0 ? std::string("no Yld2004-18p cup in this run")
                                     : std::to_string(plastic) + " plastic updates, " + std::to_string(split) +
                                           " with sub-increments, " + std::to_string(fallback) +
                                           " not converged (radial fallback)");
    std::fprintf(stderr, "  Yld2004-18p returns: %ld plastic, %ld split, %ld fallback\n", plastic, split, fallback);
  }
  c.value("runs_wall", fmt_fixed(std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count(), 1), "s");
  return runs;
}

/// Step 4's tables, their captions.
CupTables make_tables(const study::Chapter& c) {
  return CupTables{
      c.table({"variant", "angle_from_RD_deg", "cup_height_mm"},
              "Cup height (outer bottom to the rim's mid-thickness) against angle from RD, end of the stroke"),
      c.table({"variant", "angle_from_RD_deg", "rim_radius_mm"},
              "Flange outline: mean radius of each rim node column against angle from RD, end of the stroke"),
      c.table({"variant", "punch_travel_mm", "punch_force_kN"}, "Punch force (full blank) against punch travel"),
      c.table({"variant", "line_deg", "initial_radius_mm", "radius_mm", "z_mm", "thickness_mm"},
              "Thickness along RD (0), 45 deg and TD (90) at the end, by initial radius; current radius and z"),
      c.table({"variant", "punch_travel_mm", "region", "hourglass_work_mJ", "stored_inplane_mJ", "stored_twist_mJ",
               "stored_xez_mJ"},
              "Where the hourglass energy is (quarter blank), each tenth of the stroke: work done so far in the "
              "region's elements, and the energy stored in the hourglass springs by mode (xi*eta in plane, "
              "xi*eta twist, xi*eta*zeta)"),
      c.table({"variant", "h_mean_mm", "h_max_mm", "h_max_at_deg", "h_min_mm", "h_min_at_deg", "earing_pct", "ears",
               "troughs", "max_force_kN", "volume_change_pct", "kinetic_over_internal", "max_kinetic_over_internal",
               "hourglass_over_internal", "energy_balance_error", "added_mass_ratio", "cycles", "elements"},
              "ESAFORM 2021 cup: summary per material variant (h: cup height; ears/troughs of the checked profile, cup "
              "height or flange outline: angle deg @ mm)")};
}

/// Step 4, one run: its rows of the tables and its values.
void tabulate_cup(study::Chapter& c, CupTables& t, const v1::Variant& v, const v1::CupResult& r, bool drawn) {
  if (r.height.size() < 3) throw std::runtime_error("v1: fewer than 3 rim columns");
  double mean = 0, hmax = -1e30, amax = 0, hmin = 1e30, amin = 0, fmax = 0;
  for (const auto& [a, h] : r.height) {
    t.ht.row({v.id, fmt_fixed(a, 3), fmt_fixed(h, 4)});
    mean += h / static_cast<double>(r.height.size());
    if (h > hmax) hmax = h, amax = a;
    if (h < hmin) hmin = h, amin = a;
  }
  for (const auto& [a, q] : r.outline) t.ot.row({v.id, fmt_fixed(a, 3), fmt_fixed(q, 4)});
  for (const auto& [d, f] : r.curve) {
    t.ft.row({v.id, fmt_fixed(d, 4), fmt_fixed(f / 1000, 4)});
    fmax = std::max(fmax, f);
  }
  for (const auto& g : r.hourglass_regions)
    t.gt.row({v.id, fmt_fixed(g[0], 2), v1::kRegions[static_cast<int>(g[1])], fmt(g[2], 4), fmt(g[3], 4),
              fmt(g[4], 4), fmt(g[5], 4)});
  for (const auto& q : r.thickness)
    t.tt.row({v.id, fmt(q[0]), fmt_fixed(q[1], 3), fmt_fixed(q[2], 3), fmt_fixed(q[3], 3), fmt_fixed(q[4], 4)});
  const auto ex = v1::extrema(drawn ? r.height : r.outline);  // ears and troughs of the checked profile
  std::string ears, troughs;
  for (const auto& [a, h] : ex.ears) ears += (ears.empty() ? "" : " ") + fmt_fixed(a, 1) + "@" + fmt_fixed(h, 3);
  for (const auto& [a, h] : ex.troughs) troughs += (troughs.empty() ? "" : " ") + fmt_fixed(a, 1) + "@" + fmt_fixed(h, 3);
  t.st.row({v.id, fmt_fixed(mean, 3), fmt_fixed(hmax, 3), fmt_fixed(amax, 1), fmt_fixed(hmin, 3), fmt_fixed(amin, 1),
            fmt_fixed(100 * (hmax - hmin) / mean, 2), ears, troughs, fmt_fixed(fmax / 1000, 3),
            fmt_fixed(100 * (r.volume_ratio - 1), 3), fmt(r.kinetic_ratio, 3), fmt(r.max_kinetic_ratio, 3),
            fmt(r.hourglass_ratio, 3), fmt(r.balance_error, 3), fmt(r.added_mass_ratio, 3), std::to_string(r.cycles),
            std::to_string(r.elements)});
  c.value(v.id + "_mean", fmt_fixed(mean, 2), "mm");
  c.value(v.id + "_max", fmt_fixed(hmax, 2), "mm");
  c.value(v.id + "_amax", fmt_fixed(amax, 1), "°");
  c.value(v.id + "_min", fmt_fixed(hmin, 2), "mm");
  c.value(v.id + "_amin", fmt_fixed(amin, 1), "°");
  c.value(v.id + "_ears", fmt_list(ex.ears));
  c.value(v.id + "_troughs", fmt_list(ex.troughs));
  c.value(v.id + "_fmax", fmt_fixed(fmax / 1000, 2), "kN");
  // the profile the earing checks read (cup height, or flange outline after a partial stroke)
  const auto e = profile_extremes(drawn ? r.height : r.outline);
  c.value(v.id + "_pmax", fmt_fixed(e[1], 2), "mm");
  c.value(v.id + "_pamax", fmt_fixed(e[0], 1), "°");
  c.value(v.id + "_pmin", fmt_fixed(e[3], 2), "mm");
  c.value(v.id + "_pamin", fmt_fixed(e[2], 1), "°");
  c.value(v.id + "_earing", fmt_fixed(e[1] - e[3], 2), "mm");
}

/// Step 5, one run: volume, health, fold and tear, flange out.
void check_cup(study::Chapter& c, const v1::Variant& v, const v1::CupResult& r, const v1::RunSpec& spec,
               const Bounds& b, bool drawn) {
  c.checks().claim(study::Kind::verification, "v1.volume." + v.id, "sheet volume at the end within 0.6 % of the blank's (" + v.label + ")",
                   std::abs(r.volume_ratio - 1) <= 0.006,
                   "plastic flow is isochoric; the elastic dilatation is p / K with |p| below the flow stress "
                   "(~400 MPa) and K = E / (3 (1 - 2 nu)) = 68.6 GPa: at most 0.58 %");
  c.checks().claim(study::Kind::health, "v1.quasi_static." + v.id,
                   "kinetic/internal energy < 5 % over the draw after its first tenth of punch travel (" + v.label + ")",
                   r.max_kinetic_ratio < 0.05,
                   "the fixed health limit of every run (data/thesis/README.md), here over the whole draw rather "
                   "than at its end only: mass scaling and punch speed must leave inertia negligible");
  study::check_run_health(c.checks(), "v1." + v.id, v.label, {r.balance_error, r.kinetic_ratio, r.hourglass_ratio});
  // A fold (wrinkle) or a tear shows in the thickness lines.
  double tmin = 1e30, tmax = 0;
  for (const auto& q : r.thickness) tmin = std::min(tmin, q[4]), tmax = std::max(tmax, q[4]);
  c.value(v.id + "_tmin", fmt_fixed(tmin, 3), "mm");
  c.value(v.id + "_tmax", fmt_fixed(tmax, 3), "mm");
  const double t_hi = std::pow(53.75 / 30.6, 1.0 / (1.0 + b.r_min));
  // Where the sheet is thinnest: on the punch nose (current radius >= 24.5 mm, mid-surface within the nose's
  // 5 mm below the punch face, whose mid-surface is at stroke + 0.5 mm)?
  std::array<double, 5> thin = r.thickness.front();
  for (const auto& q : r.thickness)
    if (q[4] < thin[4]) thin = q;
  const bool thin_at_nose = thin[2] >= 24.5 && thin[3] >= spec.stroke - 5.5 && thin[3] <= spec.stroke + 0.5;
  c.value(v.id + "_thin_at", "along " + fmt(thin[0]) + "°, initial radius " + fmt_fixed(thin[1], 1) +
                                 " mm, now at r = " + fmt_fixed(thin[2], 1) + " mm, z = " + fmt_fixed(thin[3], 1) + " mm");
  if (v.id == "hill48_r") {
    // Stated before the run: this calibration's balanced-biaxial yield stress is 0.828 sigma_0 (published
    // 0.975; table above), so the cup bottom and the punch nose, stretched near plane strain and biaxially,
    // yield at a lower stress than the flange needs to draw in: the sheet necks at the punch nose and, in a
    // full draw, may tear there.  That is a property of Hill'48 fitted to r < 1, not a numerical fault, so the
    // 0.5 mm floor is not claimed for this variant: where it thins is.
    c.checks().claim(study::Kind::verification, "v1.no_fold.hill48_r",
                     "Hill'48 from r-values: thickness along RD, 45 deg and TD at most " + fmt_fixed(t_hi, 2) +
                         " mm at the end (no fold)",
                     tmax <= t_hi,
                     "pure hoop compression of the rim from r = 53.75 to 30.6 mm thickens it at most by (53.75 / "
                     "30.6)^(1 / (1 + r_min)) with r_min = " + fmt(b.r_min) + " the lowest r-value");
    c.checks().claim(study::Kind::verification, "v1.hill48_r.thins_at_nose",
                     "Hill'48 from r-values: the thinnest point of the three lines is on the punch nose",
                     thin_at_nose,
                     "this calibration gives sigma_b / sigma_0 = 0.828 (published 0.975): the bottom and the nose "
                     "yield before the flange draws in, so the sheet necks at the nose (a tear there is the "
                     "calibration's prediction, reported, not a fault)");
  } else {
    c.checks().claim(study::Kind::verification, "v1.no_fold_no_tear." + v.id,
                     "thickness along RD, 45 deg and TD between 0.5 and " + fmt_fixed(t_hi, 2) + " mm at the end (" +
                         v.label + ")",
                     tmin >= 0.5 && tmax <= t_hi,
                     "pure hoop compression of the rim from r = 53.75 to 30.6 mm thickens it at most by (53.75 / "
                     "30.6)^(1 / (1 + r_min)) with r_min = " + fmt(b.r_min) + " the lowest r-value; thinner than half "
                     "the blank is a tear (a neck at the punch nose)");
  }
  if (drawn)
    c.checks().claim(study::Kind::verification, "v1.flange_out." + v.id,
                     "every rim node inside r = " + fmt(v1::kFlangeOutRadius) +
                         " mm at the end: the flange has left the holder (" + v.label + ")",
                     r.rim_r_max < v1::kFlangeOutRadius, "the benchmark's cup is drawn to the end of the stroke");
}

/// Step 5b, every variant drawn: von Mises earing against the mesh bound; ears where the r-values put them.
/// After a full draw the profile is the cup height; after a partial stroke (the quick tier) it is the flange
/// outline, the rim's radius, whose excess over its mean becomes wall height once the flange is drawn in
/// (chosen before the run).
void compare_variants(study::Chapter& c, const Variants& vs, const std::vector<v1::CupResult>& runs, const Bounds& b,
                      bool drawn) {
  const auto profile = [&](const std::string& id) {
    return drawn ? runs[vs.idx.at(id)].height : runs[vs.idx.at(id)].outline;
  };
  const auto pv = profile("von_mises"), ph = profile("hill48_r");
  const auto ev = profile_extremes(pv), eh = profile_extremes(ph);
  // scale: the cup's mean height, or the flange's mean draw-in (blank radius minus mean outline radius)
  const double vm_rel = (ev[1] - ev[3]) / (drawn ? ev[4] : 53.75 - ev[4]);
  c.value("vm_earing_pct", fmt_fixed(100 * vm_rel, 2), "%");
  double mirror = 0;  // the mesh is mirror-symmetric about 45 deg: so must the von Mises profile be
  for (std::size_t k = 0; k < pv.size(); ++k) mirror = std::max(mirror, std::abs(pv[k].second - pv[pv.size() - 1 - k].second));
  c.value("vm_mirror", fmt_fixed(mirror, 3), "mm");
  const std::string what = drawn ? "cup height" : "flange outline (rim radius)";
  c.value("profile", drawn ? "the cup height" : "the flange outline (rim radius) at the end of the partial stroke");
  c.value("heights_are", drawn ? "the predicted heights of the drawn cup"
                               : "heights of the part-drawn cup (wall and rim still in the flange) after a partial "
                                 "stroke, not the predicted cup: only the full tier draws the cup out");
  const auto es = profile_extremes(profile("hill48_s"));
  c.value("vm_spread", fmt_fixed(ev[1] - ev[3], 3), "mm");
  c.value("hs_spread_tenth", fmt_fixed(0.1 * (es[1] - es[3]), 3), "mm");
  c.checks().claim(study::Kind::verification, "v1.von_mises.earing_small",
                   "von Mises, " + what + ": max - min below a tenth of the Hill'48 stress-ratio cup's",
                   ev[1] - ev[3] <= 0.1 * (es[1] - es[3]),
                   "an isotropic sheet has no earing.  The mesh is polar wherever the sheet is drawn (rows are "
                   "circles and ring lines radial at equal angles from " + fmt_fixed(b.rp, 1) + " mm out, inside the "
                   "flat punch face; its angular error at the flange's mid radius is " + fmt_fixed(100 * b.e_mesh, 2) +
                   " %, computed before the run), so a von Mises earing is numerical noise; it must stay below a "
                   "tenth of the anisotropic earing it would blur (the stress-ratio calibration, the one that "
                   "draws out)");
  const v1::Variant& hr = vs.hr;
  const double h0 = profile_at(ph, 0), h45 = profile_at(ph, 45), h90 = profile_at(ph, 90);
  c.checks().claim(study::Kind::verification, "v1.hill48_r.ears_at_axes",
                   "Hill'48 from r-values, " + std::string(drawn ? "cup height" : "flange outline") +
                       ": highest within 15° of RD or TD, lowest within 15° of 45°, and p(0), p(90) > p(45)",
                   b.ears_at_axes == ((eh[0] <= 15.0 || eh[0] >= 75.0) && std::abs(eh[2] - 45.0) <= 15.0 && h0 > h45 &&
                                      h90 > h45),
                   "the flange thickens least, so draws in most slowly and rises highest, where r is largest: "
                   "r0 = " + fmt(hr.r0) + ", r90 = " + fmt(hr.r90) + " > r45 = " + fmt(hr.r45) +
                       " gives ears at 0° and 90°; 15° is two rim elements of the quick mesh");
  if (vs.idx.count("yld2004")) {  // the same rule, stated before the run, for the Yld2004-18p cup
    const auto py = profile("yld2004");
    const auto ey = profile_extremes(py);
    const double y0 = profile_at(py, 0), y45 = profile_at(py, 45), y90 = profile_at(py, 90);
    c.checks().claim(study::Kind::verification, "v1.yld2004.ears_at_axes",
                     "Yld2004-18p, " + std::string(drawn ? "cup height" : "flange outline") +
                         ": highest within 15° of RD or TD, lowest within 15° of 45°, and p(0), p(90) > p(45)",
                     b.ears_at_axes == ((ey[0] <= 15.0 || ey[0] >= 75.0) && std::abs(ey[2] - 45.0) <= 15.0 &&
                                        y0 > y45 && y90 > y45),
                     "the tested r-values are highest at RD and TD (r0 = " + fmt(hr.r0) + ", r90 = " + fmt(hr.r90) +
                         " > r45 = " + fmt(hr.r45) + "), and the fit reproduces r(theta) (calibration table): ears at "
                         "0° and 90°; 15° is two rim elements of the quick mesh");
  }
}

/// Step 6: the run's size for the page, and the figures.
void figures(study::Chapter& c, const Variants& vs, const std::vector<v1::CupResult>& runs, const v1::RunSpec& spec,
             bool drawn) {
  const auto& r0 = runs.front();
  c.value("elements", std::to_string(r0.elements));
  c.value("layers", std::to_string(r0.layers));
  c.value("rim_columns", std::to_string(r0.height.size()));
  c.value("stroke", fmt(spec.stroke), "mm");
  c.value("cycles", std::to_string(spec.cycles));
  // The figure's variants: after a full draw, only the cups whose flange left the holder (a torn cup's
  // rim height is no cup height, and its scale would flatten the others); the title names the rest.
  std::string shown, left_out;
  std::vector<std::string> order{"von_mises", "hill48_r", "hill48_s"};  // the script's vars, in its order
  if (vs.idx.count("yld2004")) order.push_back("yld2004");
  for (std::size_t i = 0; i < order.size(); ++i) {
    const auto& r = runs[vs.idx.at(order[i])];
    if (drawn && r.rim_r_max >= v1::kFlangeOutRadius)
      left_out += (left_out.empty() ? "" : ", ") + vs.list[vs.idx.at(order[i])].label;
    else
      shown += (shown.empty() ? "" : " ") + std::to_string(i + 1);
  }
  c.plot("v1_earing", "fig_v1_earing",
         {{"datafile", c.out(drawn ? "tables/cup_height.csv" : "tables/flange_outline.csv")},
          {"shown", shown},
          {"note", left_out.empty() ? "" : "not shown: " + left_out + " (its flange never left the holder)"},
          {"ylab", drawn ? "cup height (mm)" : "flange outline: rim radius (mm)"},
          {"stage", drawn ? "end of stroke" : "partial stroke of " + fmt(spec.stroke) + " mm"}});
  c.plot("v1_force", "fig_v1_force", {{"datafile", c.out("tables/punch_force.csv")}});
  c.plot("v1_thickness", "fig_v1_thickness", {{"datafile", c.out("tables/thickness.csv")}});
}

/// The chapter: the recipe of the header, one named step a line.
void body(study::Chapter& c, const Config& cfg) {
  const CsvTable vt = read_csv(c.data("benchmarks/esaform2021.csv"));  // 1. inputs
  const std::string deck = c.data("cases/esaform2021_cup.toml");
  Variants vs = read_variants(vt, cfg);
  v1::calibrate_yld2004(c, vs.list, vs.hr, vs.hsv, cfg.yld_set);  // 1b
  const v1::RunSpec spec = run_spec(cfg);
  const bool drawn = drawn_out(spec);
  const Bounds b = state_bounds(c, deck, spec, vs);                      // 2
  const std::vector<v1::CupResult> runs = draw_cups(c, deck, vs, spec);  // 3
  CupTables t = make_tables(c);
  for (std::size_t k = 0; k < vs.list.size(); ++k) {
    tabulate_cup(c, t, vs.list[k], runs[k], drawn);    // 4
    check_cup(c, vs.list[k], runs[k], spec, b, drawn);  // 5
  }
  if (vs.subset) return t.save(c);  // a diagnostic run: its tables only (the page's comparisons need every variant)
  compare_variants(c, vs, runs, b, drawn);  // 5b
  t.save(c);
  figures(c, vs, runs, spec, drawn);  // 6
}

}  // namespace

int main(int argc, char** argv) {
  study::Chapter ch("v1-earing-benchmark", "Validation v1: ESAFORM 2021 cup-drawing benchmark (AA6016-T4 earing)");
  Config cfg;  // the chapter's options
  auto& o = ch.options();
  o.add(cfg.core, "core", "quarter disk: elements along each core side (the rim has twice as many)");
  o.add(cfg.ring, "ring", "quarter disk: elements from the core to the rim");
  o.add(cfg.through, "through", "elements through the thickness (at least 3)");
  o.add(cfg.cycles, "cycles", "explicit cycles over the stroke (sets the mass scaling)");
  o.add(cfg.stroke, "stroke", "punch travel [mm]");
  o.add(cfg.ramp, "ramp", "punch travel over which the punch accelerates uniformly from rest [mm]");
  o.add(cfg.polar, "polar-radius", "quarter disk: rows are circles from this radius out [mm] (< 0: the deck's, 0: none)");
  o.add(cfg.variants, "variants", "diagnostic run: only these variant ids, comma-separated (empty: all)");
  o.add(cfg.gap, "gap", "diagnostic run: holder-die gap [mm] (0: the published 1.04 mm)");
  o.add(cfg.holder_force, "holder-force", "diagnostic run: holder force on the quarter blank [N] (0: the deck's; < 0: the holder held fixed at the gap)");
  o.add(cfg.mu, "mu", "diagnostic run: Coulomb mu on every contact (< 0: the published 0.07)");
  o.add(cfg.clearance, "clearance", "diagnostic run: punch-die clearance [mm] (0: the published 1.2 mm; the die opening, shoulder and face move out)");
  o.add(cfg.yld_set, "yld2004-set", "diagnostic run: the Yld2004-18p variant's parameter set from this TOML (yld2004 = {a, c1, c2}) instead of the fit (empty: the fit)");
  o.add(cfg.voce, "voce", "diagnostic run: the published Voce curve instead of Swift");
  o.range("core", 1, 64).range("ring", 1, 500).range("through", 3, 32);  // through >= 3: issue 19
  o.range("holder-force", -1e6, 1e6, "N");  // < 0: the holder fixed at the gap
  return study::run_chapter(ch, argc, argv, [&cfg](study::Chapter& c) { body(c, cfg); });
}
