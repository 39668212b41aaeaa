// The forms of an effect, compared by held-out data; see forms.hpp.
#include "loop/forms.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include <boost/math/distributions/fisher_f.hpp>

#include "core/csv.hpp"
#include "loop/cells.hpp"
#include "loop/form_plans.hpp"
#include "loop/model_parts.hpp"

namespace drawbend::loop {

namespace {

bool generic_kind(EffectKind k) {
  return k == EffectKind::drift || k == EffectKind::generic_linear || k == EffectKind::generic_saturating ||
         k == EffectKind::categorical || k == EffectKind::generic_log || k == EffectKind::generic_exp ||
         k == EffectKind::generic_linear_by || k == EffectKind::categorical_by || k == EffectKind::bending_linear ||
         k == EffectKind::generic_smooth || k == EffectKind::force_offset || k == EffectKind::generic_step;
}

}  // namespace

namespace detail {

bool applicable(const Design& d, const ModelSpec& s, EffectKind k, const std::string& var) {
  for (const auto& e : s.effects)
    if (e.kind == k && (e.variable == var || !generic_kind(k))) return false;
  if (k == EffectKind::bending_tension && s.bending_linear) return false;
  if (k == EffectKind::pin_surface && d.pins.size() < 2) return false;
  if (k == EffectKind::depletion && !d.data->has_sliding) return false;
  if ((k == EffectKind::direction_harmonic || k == EffectKind::direction_fourier ||
       k == EffectKind::direction_level) && d.direction_is_level)
    return false;
  if (k == EffectKind::direction_level && d.n_dir_params < 1) return false;
  if (k == EffectKind::direction_fourier && d.n_dir_params < 2) return false;
  if (k == EffectKind::generic_linear || k == EffectKind::generic_saturating || k == EffectKind::drift ||
      k == EffectKind::generic_log || k == EffectKind::generic_exp || k == EffectKind::generic_linear_by ||
      k == EffectKind::bending_linear || k == EffectKind::generic_smooth || k == EffectKind::generic_step) {
    try {
      const std::vector<double> x = d.values(var);
      double lo = INFINITY, hi = -INFINITY;
      for (double v : x) lo = std::min(lo, v), hi = std::max(hi, v);
      if (!(hi > lo)) return false;
      if (k == EffectKind::generic_log && !(lo > 0)) return false;
      if (k == EffectKind::generic_smooth && std::set<double>(x.begin(), x.end()).size() <= 8) return false;
    } catch (const InputError&) {
      return false;
    }
  }
  if ((k == EffectKind::categorical || k == EffectKind::categorical_by) && d.data->extra_index(var) < 0) return false;
  return true;
}

// Is group g of model input `by` a union of the model's cells (every cell's
// fixed-pin rows all in it or none)?  Then each cell's mu carries the group's
// mean, and a one-cell form needs no factor of its own.
bool union_of_cells(const Design& d, const std::string& by, int g) {
  int n = 0;
  const std::vector<int> grp = d.groups(by, &n);
  std::vector<int> state(d.cells.size(), -1);  // per cell: -1 no row yet, 0 outside, 1 inside
  for (size_t i = 0; i < d.rows.size(); ++i) {
    if (d.rows[i].rotating || d.rows[i].cell < 0) continue;
    const int in = grp[i] == g ? 1 : 0;
    int& s = state[static_cast<size_t>(d.rows[i].cell)];
    if (s < 0) s = in;
    else if (s != in) return false;
  }
  return true;
}


// A categorical column: its levels, per group of a model input, on the force channel.
void FormPlans::categorical(const std::vector<std::string>& bys) {
  if (!replicated(c.levels.size())) return;  // every form below is per level
  add(EffectKind::categorical);
  if (c.levels.size() <= 4)
    for (const auto& by : bys) add(EffectKind::categorical_by, by);
  add(EffectKind::force_offset);  // levels on the force channel
  if (applicable(d, spec, EffectKind::force_offset, c.name))  // as many per cent of each pin's bending force
    plans.push_back({{{EffectKind::force_offset, "", 0, -1, true}}});
  if (c.levels.size() <= 4) add(EffectKind::force_offset, "pin");
  products(c.levels.size() <= 8);
}

// A numeric column: the generic shapes, its levels (3 to 8 values), a slope
// per group of a model input, the smooths, then the force and bending forms.
void FormPlans::numeric(const std::vector<std::string>& bys) {
  for (EffectKind k : {EffectKind::generic_linear, EffectKind::generic_saturating, EffectKind::generic_log,
                       EffectKind::generic_exp, EffectKind::generic_step})
    add(k);
  // A pair (screen_pairs.cpp): the product with the two columns' own linear
  // effects (a product of two positive quantities has main effects too).
  if (c.kind == "pair" && c.pair.size() == 2 && applicable(d, spec, EffectKind::generic_linear, c.name))
    plans.push_back({{{EffectKind::generic_linear, "", 0, -1, false, c.pair[0]},
                      {EffectKind::generic_linear, "", 0, -1, false, c.pair[1]},
                      {EffectKind::generic_linear, ""}}});
  std::set<double> distinct;
  for (double v : c.x)
    if (std::isfinite(v)) distinct.insert(v);
  if (some_levels(distinct)) add(EffectKind::categorical);
  // A column of the data with 3 or 4 distinct values is also taken as levels
  // per group of a model input, as a categorical one is (a level pattern
  // confined to one pin, speed, direction or lubricant is not linear in x).
  if (few_levels(distinct))
    for (const auto& by : bys) add(EffectKind::categorical_by, by);
  for (const auto& by : bys) add(EffectKind::generic_linear_by, by);
  // A smooth of any shape (bump, U, periodic, sigmoid, step), 3, 5 or 8
  // dof overall (8: a narrow bump, a step or two periods) and 3 or 5 per
  // group of a model input: held-out error and the one-standard-error rule
  // choose among it and the simpler forms.
  if (applicable(d, spec, EffectKind::generic_smooth, c.name)) {
    for (int nb : {3, 5, 8}) plans.push_back({{{EffectKind::generic_smooth, "", nb}}});
    for (const auto& by : bys)
      for (int nb : {3, 5}) plans.push_back({{{EffectKind::generic_smooth, by, nb}}});
  }
  products(some_levels(distinct));
  force_and_bending(distinct);
  bumps(distinct);  // a local bump of the column, on mu and on the force channel (form_bumps.cpp)
}

// The force channel (rotating rows too): linear per pin, a smooth, a smooth per pin.
void FormPlans::force_and_bending(const std::set<double>& distinct) {
  // Each needs a number on every row: empty cells (missing values) take
  // the column's mean (Design::values), as in the generic forms above.
  bool every_row_numeric = true;
  try {
    d.values(c.name);
  } catch (const InputError&) {
    every_row_numeric = false;
  }
  if (every_row_numeric && applicable(d, spec, EffectKind::force_offset, c.name)) {
    plans.push_back({{{EffectKind::force_offset, "pin", 1}}});
    if (some_levels(distinct) && d.data->extra_index(c.name) >= 0) {
      plans.push_back({{{EffectKind::force_offset, "", 0}}});            // levels
      plans.push_back({{{EffectKind::force_offset, "", 0, -1, true}}});  // levels, scaled with the bending force
    }
    if (few_levels(distinct)) plans.push_back({{{EffectKind::force_offset, "pin", 0}}});  // levels per pin
    if (distinct.size() > 8)
      for (const std::string by : {"", "pin"}) plans.push_back({{{EffectKind::force_offset, by, 3}}});
    if (distinct.size() > 8) plans.push_back({{{EffectKind::force_offset, "", 3, -1, true}}});
  }
  if (applicable(d, spec, EffectKind::bending_linear, c.name)) {
    plans.push_back({{{EffectKind::bending_linear, ""}}});
    if (applicable(d, spec, EffectKind::generic_linear, c.name))
      plans.push_back({{{EffectKind::bending_linear, ""}, {EffectKind::generic_linear, ""}}});
  }
}

// An effect confined to one cell (the group of a model input the screen's
// strongest one-group probe points at, or the worst-fitted group of the
// strongest probe's input, or of the probe with the largest held-out gain):
// a slope, a smooth of 3, 5 or 8 dof (up to max_nb; 8 with more than 8
// values: a narrow bump, a step or two periods in the cell) or
// the levels in that cell only, none elsewhere; with `force`, on the force
// channel as well (force_in_cell).  Held-out error and the
// one-standard-error rule choose between it and the global forms.
void FormPlans::in_cell(const std::string& cell_by, int cell_group, int max_nb, bool force) {
  std::set<double> distinct;
  for (double v : c.x)
    if (std::isfinite(v)) distinct.insert(v);
  const bool levels = c.categorical ? replicated(c.levels.size()) : some_levels(distinct);
  // The cell's own factor when no mu of the base model carries the cell's mean.
  const bool offset = !union_of_cells(d, cell_by, cell_group);
  if (levels && d.data->extra_index(c.name) >= 0 && applicable(d, spec, EffectKind::categorical_by, c.name))
    plans.push_back({{{EffectKind::categorical_by, cell_by, 0, cell_group, false, "", offset}}});
  // A slope or smooth in the cell is zero at the column's mean, whatever the
  // file's order: no factor of its own (h50-celloffset tried both and was
  // 98 x slower on one development set: heldout_record.md).
  if (!c.categorical && applicable(d, spec, EffectKind::generic_linear_by, c.name))
    plans.push_back({{{EffectKind::generic_linear_by, cell_by, 0, cell_group}}});
  if (!c.categorical && applicable(d, spec, EffectKind::generic_smooth, c.name))
    for (int nb : {3, 5, 8})
      if (nb <= max_nb && (nb < 8 || distinct.size() > 8))
        plans.push_back({{{EffectKind::generic_smooth, cell_by, nb, cell_group}}});
  if (force) force_in_cell(cell_by, cell_group, levels, distinct, max_nb);
  if (max_nb >= 5) bumps(distinct, cell_by, cell_group, force);  // not in the split cells (3 dof)
}

// The force channel confined to one cell: a column that changes the bending
// or outlet force in one pin, speed, direction or lubricant only (a coating
// or a thickness that matters at one bend, a lubricant that changes how the
// strip wraps) has no friction signature there, and the global force forms
// spread it over every cell.  The column's levels, a slope and (more than 8
// values) a smooth of 3 and 5 dof (at most max_nb) of a numeric column, in the cell only, each as
// newtons and as a share of each pin's bending force (the same with one pin:
// then only newtons).  Held-out error and the one-standard-error rule choose
// among them and the friction forms.
void FormPlans::force_in_cell(const std::string& cell_by, int cell_group, bool levels,
                              const std::set<double>& distinct, int max_nb) {
  if (!measured_column() || !applicable(d, spec, EffectKind::force_offset, c.name)) return;
  bool numeric = !c.categorical;
  try {
    if (numeric) d.values(c.name);
  } catch (const InputError&) {
    numeric = false;  // a number on every row (missing: the column's mean) or no slope
  }
  for (bool scaled : {false, true}) {
    if (scaled && cell_by == "pin") break;
    if (levels) plans.push_back({{{EffectKind::force_offset, cell_by, 0, cell_group, scaled}}});
    if (numeric) plans.push_back({{{EffectKind::force_offset, cell_by, 1, cell_group, scaled}}});
    if (numeric && distinct.size() > 8)
      for (int nb : {3, 5})  // the force channel's smooth: up to 5 dof
        if (nb <= max_nb) plans.push_back({{{EffectKind::force_offset, cell_by, nb, cell_group, scaled}}});
  }
}

// An effect on one side of a threshold of a continuous model input (speed or
// direction with more than 6 distinct values, which groups() cuts at its
// tertiles), when the screen's strongest probe is per that input: the one-cell
// forms (in_cell) in the group below or at and above a threshold midway
// between two of the input's distinct values at its quartiles.  Held-out
// error and the one-standard-error rule choose among them and the other forms.
void FormPlans::split_cells(const std::string& input) {
  if (input != "speed_mm_s" && input != "direction_deg") return;
  std::vector<double> v;  // the input's distinct values on the fixed-pin rows, ascending
  for (size_t i = 0; i < d.rows.size(); ++i)
    if (!d.rows[i].rotating)
      v.push_back(input == "speed_mm_s" ? d.data->rows[i].speed_mm_s : d.data->rows[i].direction_deg);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  if (v.size() <= 6) return;  // groups() has every value as its own group: in_cell covers it
  for (int q = 1; q <= 3; ++q) {
    const size_t at = v.size() * q / 4;
    char by[64];
    std::snprintf(by, sizeof by, "%s>=%.6g", input.c_str(), 0.5 * (v[at - 1] + v[at]));
    for (int side = 0; side < 2; ++side) in_cell(by, side, 3, false);  // 3 dof, friction only: six cells already
  }
}

// An effect on one side of a threshold of a continuous model input, the
// threshold and side scanned where the candidate's column explains the most
// of the current held-out residual (scan_split, cells.hpp): its one-cell
// forms (in_cell, 3 dof, friction only).  The quartile splits (split_cells)
// cut the input where the data's speeds lie, not where the effect changes.
void FormPlans::scanned_split(const std::string& input, const CvResult& cur) {
  const auto s = scan_split(d, cur, c.x, c.categorical, input);
  if (!s) return;
  char by[64];
  std::snprintf(by, sizeof by, "%s>=%.6g", input.c_str(), s->threshold);
  in_cell(by, s->side, 3, false);
}

}  // namespace detail

namespace {

// Groups of a model input with at least two groups among the fixed-pin rows
// (the inputs the screen's per-input probes use: screen_context in loop.cpp).
std::vector<std::string> by_inputs(const Design& d) {
  std::vector<std::string> out;
  for (const std::string by : {"pin", "speed_mm_s", "direction_deg", "lubricant"}) {
    int n = 0;
    const std::vector<int> g = d.groups(by, &n);
    std::set<int> seen;
    for (size_t i = 0; i < g.size(); ++i)
      if (!d.rows[i].rotating) seen.insert(g[i]);
    if (seen.size() >= 2) out.push_back(by);
  }
  return out;
}

// The fits' arithmetic of model s as a key (TrialCache): two models with the
// same key give the same cross-validation and joint fit bit for bit.  A library
// effect whose rule reads no column of its own (effect_rules.hpp: pressure_mu,
// stribeck, depletion, the direction effects, pin_surface, bending_tension) is
// the same model whichever candidate named it, and drift is generic_linear
// (both the rule Linear on the column's z-score, model.cpp).
std::string fits_key(const ModelSpec& s) {
  std::string k = s.bending_linear ? "1" : "0";
  for (const auto& e : s.effects) {
    const bool own_column = generic_kind(e.kind);
    const EffectKind kind = e.kind == EffectKind::drift ? EffectKind::generic_linear : e.kind;
    char num[96];
    std::snprintf(num, sizeof num, "|%d,%a,%d,%d,%d,%d,%d,%d,", static_cast<int>(kind), e.lambda_mm, e.n_levels,
                  e.n_groups, e.cell, e.n_basis, e.bend_scaled ? 1 : 0, e.cell_offset ? 1 : 0);
    k += num + std::to_string(e.by.size()) + ":" + e.by + "," + (own_column ? e.variable : "") +
         (e.times.empty() ? "" : "," + std::to_string(e.times.size()) + "x" + e.times + (e.level_basis ? "L" : ""));
    if (e.bump_width > 0) {  // a bump: its centre and width (two bumps never share a key)
      std::snprintf(num, sizeof num, ",B%a,%a", e.bump_centre, e.bump_width);
      k += num;
    }
    if (e.step) {  // a step: its threshold
      std::snprintf(num, sizeof num, ",S%a", e.step_at);
      k += num;
    }
  }
  return k;
}

// Trial t of plan p: the model with its effects, and its name, meaning and channel.
FormTrial named_trial(const Design& d, const ModelSpec& spec, const Candidate& c, const detail::Plan& p) {
  FormTrial t;
  t.spec = spec;
  bool bend = false, fric = false;
  for (const auto& [k, by, nb, cell, scaled, var, offset, times, levels, centre, width, step] : p.parts) {
    // A pair's main effect (a column of its own) only when the model has none yet.
    if (!var.empty() && !detail::applicable(d, t.spec, k, var)) continue;
    t.spec = with_effect(d, t.spec, k, var.empty() ? c.name : var, by, times);
    if (nb > 0) t.spec.effects.back().n_basis = nb;
    t.spec.effects.back().cell = cell;
    t.spec.effects.back().bend_scaled = scaled;
    t.spec.effects.back().cell_offset = offset && cell >= 0;
    t.spec.effects.back().level_basis = levels;
    t.spec.effects.back().bump_centre = centre;
    t.spec.effects.back().bump_width = width;
    t.spec.effects.back().step = step;
    t.spec.effects.back().step_at = step ? centre : 0.0;
    const std::string shape = width > 0 ? " bump at " + fmt(centre, 6) + ", width " + fmt(width, 6)
                              : step    ? " step at " + fmt(centre, 6)
                              : levels  ? " levels"
                              : nb > 0  ? " " + std::to_string(nb) + " dof"
                                        : "";
    t.name += (t.name.empty() ? "" : " + ") + effect_name(k) + (var.empty() ? "" : " of " + var) + shape +
              (by.empty() ? "" : " (" + by + (cell >= 0 ? " group " + std::to_string(cell + 1) + " only" : "") +
                                  (cell >= 0 && offset ? ", with its own factor" : "") + ")") +
              (scaled ? " (scaled with the pin's bending force)" : "") +
              (times.empty() ? "" : " (times the centred " + times + ")");
    const std::string meaning = width > 0       ? detail::bump_meaning(k)
                                : step          ? detail::step_meaning(k)
                                : times.empty() ? effect_meaning(k)
                                                : detail::product_meaning(k, levels, times);
    if (t.meaning.find(meaning) == std::string::npos)  // a pair's mains: the same meaning once
      t.meaning += (t.meaning.empty() ? "" : "; ") + meaning;
    (acts_on_bending(k) ? bend : fric) = true;
    t.searched = t.searched || !times.empty() || width > 0 || step;
    if (width > 0) t.extra_searched += 2;  // the bump's centre and width
    if (step) t.extra_searched += 1;       // the step's threshold
  }
  t.channel = bend && fric ? "both" : bend ? "bending" : "friction";
  return t;
}

// The trial's cross-validation, or that of the same arithmetic tried before (cache).
void cv_trial(const Design& d, const Folds& folds, FormTrial& t, TrialCache* cache) {
  if (!cache) return void(t.cv = cross_validate(d, t.spec, folds));
  const std::string key = fits_key(t.spec);
  const auto done = cache->cv.find(key);
  if (done != cache->cv.end()) return void(t.cv = done->second);
  t.cv = cross_validate(d, t.spec, folds);
  cache->cv.emplace(key, t.cv);
}

// The trial's joint fit (or the cached one), its F test and q.
void test_trial(const Design& d, FormTrial& t, const JointFit& cur_joint, TrialCache* cache) {
  if (!cache) {
    t.joint = fit_joint(d, t.spec);
  } else {
    const std::string key = fits_key(t.spec);
    const auto done = cache->joint.find(key);
    if (done != cache->joint.end()) t.joint = done->second;
    else t.joint = fit_joint(d, t.spec), cache->joint.emplace(key, t.joint);
  }
  t.q = t.joint.p - cur_joint.p + t.extra_searched;
  t.p_value = f_test(cur_joint, t.joint, t.extra_searched);
  t.tested = true;
}

}  // namespace

double f_test(const JointFit& a, const JointFit& b, int extra_q) {
  const int q = b.p - a.p + extra_q, dof = b.n - b.p - extra_q;
  if (q <= 0 || dof <= 0 || !(b.rss > 0)) return b.rss < a.rss ? 0.0 : 1.0;
  const double F = ((a.rss - b.rss) / q) / (b.rss / dof);
  if (!(F > 0)) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::fisher_f_distribution<double>(q, dof), F));
}

int searched_params(const std::vector<Effect>& added) {
  int q = 0;
  for (const Effect& e : added) q += (e.bump_width > 0 ? 2 : 0) + (e.step ? 1 : 0);
  return q;
}

ModelSpec with_effect(const Design& d, const ModelSpec& s, EffectKind k, const std::string& variable,
                      const std::string& by, const std::string& times) {
  ModelSpec t = s;
  Effect e;
  e.kind = k;
  e.variable = variable;
  e.by = by;
  e.times = times;
  if (k == EffectKind::bending_tension) t.bending_linear = true;
  if (k == EffectKind::categorical || k == EffectKind::categorical_by ||
      (k == EffectKind::force_offset && d.data->extra_index(variable) >= 0)) {
    std::vector<std::string> names;
    d.levels(variable, &names);
    e.n_levels = static_cast<int>(names.size());
  }
  if (!by.empty()) d.groups(by, &e.n_groups);
  auto rss = [&](double lam) {
    ModelSpec u = s;
    Effect v = e;
    v.lambda_mm = lam;
    u.effects.push_back(v);
    return fit_model(d, u, {}, false).rss;
  };
  if (k == EffectKind::depletion) {  // lambda: grid, then golden section in log(lambda), by the full-data fit
    const std::vector<double> grid = {10.0, 25.0, 50.0, 100.0, 200.0, 400.0, 800.0};
    size_t bi = 0;
    double best = INFINITY;
    for (size_t i = 0; i < grid.size(); ++i) {
      const double r = rss(grid[i]);
      if (r < best) best = r, bi = i;
    }
    double a = std::log(grid[bi > 0 ? bi - 1 : 0]), b = std::log(grid[std::min(bi + 1, grid.size() - 1)]);
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = rss(std::exp(x1)), f2 = rss(std::exp(x2));
    for (int it = 0; it < 20; ++it) {
      if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = rss(std::exp(x1));
      else a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = rss(std::exp(x2));
    }
    e.lambda_mm = std::exp(0.5 * (a + b));
    if (rss(e.lambda_mm) > best) e.lambda_mm = grid[bi];
  }
  if (k == EffectKind::generic_exp) {  // lambda on a grid of fractions of the column's range
    const std::vector<double> x = d.values(variable);
    double lo = INFINITY, hi = -INFINITY;
    for (double v : x) lo = std::min(lo, v), hi = std::max(hi, v);
    double best = INFINITY;
    for (double frac : {0.03, 0.07, 0.15, 0.3, 0.6}) {
      const double r = rss(frac * (hi - lo));
      if (r < best) best = r, e.lambda_mm = frac * (hi - lo);
    }
  }
  if (k == EffectKind::generic_step) {
    // Threshold: midway between the column's value at a quantile and the next
    // value; the deciles first, then the 80-quantiles between the best
    // decile's neighbours (a step between two deciles is placed to 1/80).
    std::vector<double> x = d.values(variable);
    std::sort(x.begin(), x.end());
    double best = INFINITY;
    std::set<double> tried;
    auto at_quantile = [&](int q, int of) {
      const size_t at = x.size() * q / of;
      const auto above = std::upper_bound(x.begin(), x.end(), x[at]);
      if (above == x.end() || !tried.insert(0.5 * (x[at] + *above)).second) return false;
      const double c = 0.5 * (x[at] + *above), r = rss(c);
      if (r < best) best = r, e.lambda_mm = c;
      return r <= best;
    };
    int qb = 0;
    for (int q = 1; q <= 9; ++q)
      if (at_quantile(q, 10)) qb = q;
    if (qb > 0)
      for (int q = 8 * (qb - 1) + 1; q < 8 * (qb + 1) && q < 80; ++q) at_quantile(q, 80);
  }
  t.effects.push_back(e);
  return t;
}

double mse_diff_se(const CvResult& a, const CvResult& b, const Folds& f) {
  std::map<int, double> dt;
  int n = 0;
  for (size_t i = 0; i < a.resid.size(); ++i)
    if (std::isfinite(a.resid[i]) && std::isfinite(b.resid[i]))
      dt[f.test[i]] += a.resid[i] * a.resid[i] - b.resid[i] * b.resid[i], ++n;
  if (dt.size() < 2 || n == 0) return 0;
  double m = 0;
  for (const auto& [t, v] : dt) m += v / dt.size();
  double q = 0;
  for (const auto& [t, v] : dt) q += (v - m) * (v - m);
  return std::sqrt(q * dt.size() / (dt.size() - 1.0)) / n;
}

std::vector<FormTrial> try_forms(const Design& d, const Folds& folds, const ModelSpec& spec, const Candidate& c,
                                 const CvResult& cur, const JointFit& cur_joint, double thr, double min_gain_N,
                                 const std::function<void(const std::string&)>& progress, const std::string& cell_by,
                                 int cell_group, TrialCache* cache, const std::string& probe_input, int max_q,
                                 bool products, const std::string& cv_input) {
  detail::FormPlans fp{d, spec, c, {}, products, &cur};
  std::vector<detail::Plan>& plans = fp.plans;
  for (EffectKind k : effects_for(c.name))
    if (detail::applicable(d, spec, k, c.name)) plans.push_back({{{k, ""}}});
  // Generic forms for a column of the data, and for a numeric model input the
  // base model does not use (speed when it is continuous, not a cell level).
  if (c.kind == "column" || c.kind == "pair" || (c.name == "speed_mm_s" && !d.speed_is_level)) {
    auto bys = by_inputs(d);
    bys.erase(std::remove(bys.begin(), bys.end(), c.name), bys.end());
    if (c.categorical) fp.categorical(bys);
    else fp.numeric(bys);
    if (cell_group >= 0 && !cell_by.empty() && cell_by != c.name) fp.in_cell(cell_by, cell_group);
    if (!probe_input.empty() && probe_input != c.name) {
      // The screen's strongest probe is per a model input but named no one
      // group (the one-cell sub-probes are off): the group with the largest
      // mean squared held-out residual of the current model.
      if (cell_group < 0) fp.in_cell(probe_input, worst_group(d, cur, probe_input));
      fp.split_cells(probe_input);
      fp.scanned_split(probe_input, cur);
    } else if (probe_input.empty() && cell_group < 0 && !cv_input.empty() && cv_input != c.name) {
      // The strongest probe is an overall one, but the probe with the largest
      // held-out gain is per a model input: the one-cell forms in that
      // input's worst-fitted group too, and its scanned split (not the
      // quartile splits).
      fp.in_cell(cv_input, worst_group(d, cur, cv_input));
      fp.scanned_split(cv_input, cur);
    }
  }
  std::vector<FormTrial> out;
  const int p0 = max_q >= 0 ? detail::layout(d, spec).n : 0;
  for (const detail::Plan& p : plans) {
    FormTrial t = named_trial(d, spec, c, p);
    if (max_q >= 0 && detail::layout(d, t.spec).n - p0 > max_q) continue;
    if (progress) progress("  " + c.name + ": trying " + t.name);
    cv_trial(d, folds, t, cache);
    const double gain = std::sqrt(std::max(0.0, cur.rms * cur.rms - t.cv.rms * t.cv.rms));
    // The F test only for a form whose held-out error passes its gates (the
    // other forms cannot pass; complete_trials makes theirs when listed).
    if (gain >= min_gain_N && t.cv.rms < cur.rms) {
      test_trial(d, t, cur_joint, cache);
      t.passed = t.p_value <= thr;
    }
    out.push_back(std::move(t));
  }
  return out;
}

void complete_trials(const Design& d, std::vector<FormTrial>& trials, const JointFit& cur_joint, TrialCache* cache) {
  for (FormTrial& t : trials)
    if (!t.tested) test_trial(d, t, cur_joint, cache);
}

int choose_form(const std::vector<FormTrial>& t, const Folds& f) {
  int best = -1;
  for (size_t i = 0; i < t.size(); ++i)
    if (t[i].passed && (best < 0 || t[i].cv.rms < t[best].cv.rms)) best = static_cast<int>(i);
  if (best < 0) return -1;
  int keep = best;
  const double mse_best = t[best].cv.rms * t[best].cv.rms;
  for (size_t i = 0; i < t.size(); ++i) {
    if (!t[i].passed || static_cast<int>(i) == best) continue;
    // The one-SE rule does not hand the step from a better form to a product
    // form: a product's parameters understate what was searched for it (the
    // quantity it multiplies, pressure or log speed, and a step's threshold),
    // so its count is not comparable with the other forms'.
    // A bump's too (its centre and width searched on a grid, form_bumps.cpp).
    if (t[i].searched && !t[best].searched) continue;
    const double mse = t[i].cv.rms * t[i].cv.rms;
    if (mse - mse_best > mse_diff_se(t[i].cv, t[best].cv, f)) continue;
    if (t[i].q < t[keep].q || (t[i].q == t[keep].q && t[i].cv.rms < t[keep].cv.rms)) keep = static_cast<int>(i);
  }
  return keep;
}

}  // namespace drawbend::loop
