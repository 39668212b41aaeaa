#pragma once
// Internal to the loop's force model: the effect table.  One rule per
// EffectKind of effects.hpp says how many friction parameters the effect has,
// the term it adds to mu of a fixed-pin row, and the names of its parameters.
// visit_rule is the one switch over EffectKind; its callers (layout,
// predict_row, friction_names) pass a generic lambda, so each rule's functions
// are called directly and inline in the fits' inner loop.  Adding an effect
// kind means adding one rule here and one line in visit_rule.  A rule may
// say which of its parameters a row reads (`static int reads(const
// EffectArgs&, int* out)`: offsets from its first parameter, returns how
// many; at most its count); without it every one of its parameters is
// assumed read (rule_reads).  The fits evaluate their Jacobians only there
// and check the claim (least_squares.hpp), so a wrong `reads` costs a dense
// fit, never a wrong one.
#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/csv.hpp"
#include "loop/model_parts.hpp"

namespace drawbend::loop::detail {

using Names = std::vector<std::string>;

/// Base of the rules with one parameter.
struct OneParam {
  static int count(const Design&, const Effect&) { return 1; }
};

/// mu(p) = mu0 + a1 p per cell (the new method); p from the map (Eq. 2.2 scaling in predict_row).
struct PressureMu {
  static int count(const Design& d, const Effect&) { return static_cast<int>(d.cells.size()); }
  static void apply(const EffectArgs& a, Terms& t) { t.a1 = a.th[a.r.cell]; }
  static int reads(const EffectArgs& a, int* o) { return o[0] = a.r.cell, 1; }
  static void name(const Design& d, const Effect&, const Names&, int s, Names& n) {
    for (size_t c = 0; c < d.cells.size(); ++c) n[s + c] = "a1 [" + d.cells[c] + "] (1/MPa)";
  }
};

/// mu (1 + beta lg L), lg L centred (Eq. 3.1's lubricant number, see make_design).
struct Stribeck : OneParam {
  static void apply(const EffectArgs& a, Terms& t) { t.factor += a.th[0] * a.r.lgL; }
  static void name(const Design&, const Effect&, const Names&, int s, Names& n) { n[s] = "beta per decade of L"; }
};

/// mu (1 - beta (1 - exp(-s/lambda))), s the sliding distance.
struct Depletion : OneParam {
  static void apply(const EffectArgs& a, Terms& t) {
    t.factor -= a.th[0] * (1 - std::exp(-a.r.sliding / a.e.lambda_mm));
  }
  static void name(const Design&, const Effect& e, const Names&, int s, Names& n) {
    n[s] = "beta depletion (lambda = " + fmt(e.lambda_mm) + " mm)";
  }
};

/// mu (1 + beta sin^2(2 phi)).
struct DirectionHarmonic : OneParam {
  static void apply(const EffectArgs& a, Terms& t) { t.factor += a.th[0] * a.r.sin2; }
  static void name(const Design&, const Effect&, const Names&, int s, Names& n) { n[s] = "beta sin^2(2 phi)"; }
};

/// drift, generic_linear, generic_log, generic_exp and generic_step: mu (1 + beta u), u the effect's feature
/// per row (fit_model: z-score, z-score of log, 1 - exp(-(x - x_min)/lambda), or [x > c]).
struct Linear : OneParam {
  static void apply(const EffectArgs& a, Terms& t) { t.factor += a.th[0] * a.f.drift_z[a.k][a.i]; }
  static void name(const Design&, const Effect& e, const Names&, int s, Names& n) {
    n[s] = e.kind == EffectKind::generic_log ? "beta per SD of log " + e.variable
           : e.kind == EffectKind::generic_exp ? "beta (1 - exp(-(x - x_min)/" + fmt(e.lambda_mm, 3) + ")) of " + e.variable
           : e.kind == EffectKind::generic_step ? "beta [x > " + fmt(e.lambda_mm, 4) + "] of " + e.variable
                                                : "beta per SD of " + e.variable;
  }
};

/// Groups of `by` with their own parameters: all, or the one cell (e.cell >= 0).
inline int own_groups(const Effect& e) { return e.cell >= 0 ? 1 : e.n_groups; }
/// Parameter block of row i's group (0 for the cell), -1 when the effect does not act there.
inline int group_slot(const EffectArgs& a) {
  const int g = a.f.group[a.k][a.i];
  return a.e.cell < 0 ? g : g == a.e.cell ? 0 : -1;
}
/// The one-cell levels form's own factor (Effect::cell_offset): 1 parameter, after the levels.
inline int cell_extra(const Effect& e) { return e.cell >= 0 && e.cell_offset ? 1 : 0; }
inline std::string group_text(const Effect& e, int g) {
  return e.by + " group " + std::to_string((e.cell >= 0 ? e.cell : g) + 1) + (e.cell >= 0 ? " only" : "");
}

/// mu (1 + beta_g z): one slope per group g of the effect's `by` input (or in one group only).
struct LinearBy {
  static int count(const Design&, const Effect& e) { return own_groups(e); }
  static void apply(const EffectArgs& a, Terms& t) {
    const int g = group_slot(a);
    if (g >= 0) t.factor += a.th[g] * a.f.drift_z[a.k][a.i];
  }
  static int reads(const EffectArgs& a, int* o) {
    const int g = group_slot(a);
    return g >= 0 ? (o[0] = g, 1) : 0;
  }
  static void name(const Design&, const Effect& e, const Names&, int s, Names& n) {
    for (int g = 0; g < own_groups(e); ++g) n[s + g] = "beta per SD of " + e.variable + " [" + group_text(e, g) + "]";
  }
};

/// mu (1 + g_{group,level}), one factor per level but the first in every group of `by`.
struct CategoricalBy {
  static int count(const Design&, const Effect& e) { return own_groups(e) * std::max(0, e.n_levels - 1) + cell_extra(e); }
  static void apply(const EffectArgs& a, Terms& t) {
    const int l = a.f.level[a.k][a.i], g = group_slot(a);
    if (l > 0 && g >= 0) t.factor += a.th[g * (a.e.n_levels - 1) + l - 1];
    if (g >= 0 && cell_extra(a.e)) t.factor += a.th[std::max(0, a.e.n_levels - 1)];
  }
  static int reads(const EffectArgs& a, int* o) {
    const int l = a.f.level[a.k][a.i], g = group_slot(a);
    int k = 0;
    if (l > 0 && g >= 0) o[k++] = g * (a.e.n_levels - 1) + l - 1;
    if (g >= 0 && cell_extra(a.e)) o[k++] = std::max(0, a.e.n_levels - 1);
    return k;
  }
  static void name(const Design&, const Effect& e, const Names& level_names, int s, Names& n) {
    for (int g = 0; g < own_groups(e); ++g)
      for (int l = 1; l < e.n_levels; ++l)
        n[s + g * (e.n_levels - 1) + l - 1] = "g [" + e.variable + " = " + level_names[l] + ", " + group_text(e, g) + "]";
    if (cell_extra(e))
      n[s + std::max(0, e.n_levels - 1)] = "g0 [" + e.variable + " = " + level_names[0] + ", " + group_text(e, 0) +
                                            "]: the cell's own factor";
  }
};

/// A bump's parameter name: "bump of x (centre c, width w)" (Effect::bump_width > 0), a step's "step of x
/// at c" (Effect::step), else "spline j of x".
inline std::string basis_text(const Effect& e, int j) {
  return e.bump_width > 0 ? "bump of " + e.variable + " (centre " + fmt(e.bump_centre, 6) + ", width " +
                                fmt(e.bump_width, 6) + ")"
         : e.step ? "step of " + e.variable + " at " + fmt(e.step_at, 6)
                  : "spline " + std::to_string(j + 1) + " of " + e.variable;
}

/// mu (1 + sum_j beta_j B_j(x)): natural cubic spline basis, or a bump
/// (fit_model: f.basis), per group of `by` when set.
struct Smooth {
  static int count(const Design&, const Effect& e) { return e.n_basis * (e.by.empty() ? 1 : own_groups(e)); }
  static void apply(const EffectArgs& a, Terms& t) {
    const auto& B = a.f.basis[a.k];
    const int g = a.e.by.empty() ? 0 : group_slot(a);
    if (g < 0) return;
    const double* th = a.th + static_cast<size_t>(g) * a.e.n_basis;
    for (int j = 0; j < a.e.n_basis; ++j) t.factor += th[j] * B[static_cast<size_t>(j)][a.i];
  }
  static int reads(const EffectArgs& a, int* o) {
    const int g = a.e.by.empty() ? 0 : group_slot(a);  // the rule's own slot (one-cell forms: 0, or none)
    if (g < 0) return 0;
    for (int j = 0; j < a.e.n_basis; ++j) o[j] = g * a.e.n_basis + j;
    return a.e.n_basis;
  }
  static void name(const Design&, const Effect& e, const Names& level_names, int s, Names& n) {
    const int G = e.by.empty() ? 1 : own_groups(e);
    for (int g = 0; g < G; ++g)
      for (int j = 0; j < e.n_basis; ++j)
        n[s + g * e.n_basis + j] =
            (e.level_basis && static_cast<size_t>(j + 1) < level_names.size()
                 ? "beta [" + e.variable + " = " + level_names[static_cast<size_t>(j + 1)] + "]"
                 : "beta " + basis_text(e, j)) +
            (e.times.empty() ? "" : " times the centred " + e.times) +
            (e.by.empty() ? "" : " [" + group_text(e, g) + "]");
  }
};

/// outlet force + c_{g,j} B_j (numeric: spline basis, f.basis) or + c_{g,level} (levels but the first),
/// g the group of `by` (else one group), or the one group e.cell only (none elsewhere: a force
/// channel confined to one pin, speed, direction or lubricant, as the one-cell friction forms are).
struct ForceOffset {
  static int per_group(const Effect& e) { return e.n_basis > 0 ? e.n_basis : std::max(0, e.n_levels - 1); }
  static int groups(const Effect& e) { return e.by.empty() ? 1 : own_groups(e); }
  static int slot(const EffectArgs& a) { return a.e.by.empty() ? 0 : group_slot(a); }
  static int count(const Design&, const Effect& e) { return per_group(e) * groups(e); }
  static void apply(const EffectArgs& a, Terms& t) {
    const int g = slot(a);
    if (g < 0) return;
    const double* th = a.th + static_cast<size_t>(g) * per_group(a.e);
    const double s = a.e.bend_scaled ? a.f.bend_scale[a.r.pin] : 1.0;
    if (a.e.n_basis > 0) {
      const auto& B = a.f.basis[a.k];
      for (int j = 0; j < a.e.n_basis; ++j) t.add_N += s * th[j] * B[static_cast<size_t>(j)][a.i];
    } else {
      const int l = a.f.level[a.k][a.i];
      if (l > 0) t.add_N += s * th[l - 1];
    }
  }
  static int reads(const EffectArgs& a, int* o) {
    const int g = slot(a), P = per_group(a.e);
    if (g < 0) return 0;
    if (a.e.n_basis > 0) {
      for (int j = 0; j < a.e.n_basis; ++j) o[j] = g * P + j;
      return a.e.n_basis;
    }
    const int l = a.f.level[a.k][a.i];
    return l > 0 ? (o[0] = g * P + l - 1, 1) : 0;
  }
  static void name(const Design&, const Effect& e, const Names& level_names, int s, Names& n) {
    const int G = groups(e), P = per_group(e);
    for (int g = 0; g < G; ++g)
      for (int j = 0; j < P; ++j)
        n[s + g * P + j] = "force c " + (e.n_basis > 0 ? basis_text(e, j) + " (N per SD)"
                                                       : "[" + e.variable + " = " + level_names[j + 1] + "] (N)") +
                           (e.by.empty() ? "" : " [" + group_text(e, g) + "]") +
                           (e.bend_scaled ? " x the pin's relative bending force" : "");
  }
};

/// mu (1 + beta tanh(z)).
struct Saturating : OneParam {
  static void apply(const EffectArgs& a, Terms& t) { t.factor += a.th[0] * std::tanh(a.f.drift_z[a.k][a.i]); }
  static void name(const Design&, const Effect& e, const Names&, int s, Names& n) {
    n[s] = "beta tanh(z) of " + e.variable;
  }
};

/// mu (1 + g_level), one factor per level but the first.
struct Categorical {
  static int count(const Design&, const Effect& e) { return std::max(0, e.n_levels - 1); }
  static void apply(const EffectArgs& a, Terms& t) {
    const int l = a.f.level[a.k][a.i];
    if (l > 0) t.factor += a.th[l - 1];
  }
  static int reads(const EffectArgs& a, int* o) {
    const int l = a.f.level[a.k][a.i];
    return l > 0 ? (o[0] = l - 1, 1) : 0;
  }
  static void name(const Design&, const Effect& e, const Names& level_names, int s, Names& n) {
    for (int l = 1; l < e.n_levels; ++l) n[s + l - 1] = "g [" + e.variable + " = " + level_names[l] + "]";
  }
};

/// mu (1 + g_dir) per direction level other than 0 and 90 deg.
struct DirectionLevel {
  static int count(const Design& d, const Effect&) { return d.n_dir_params; }
  static void apply(const EffectArgs& a, Terms& t) {
    if (a.r.dir >= 0 && a.d.dir_param[a.r.dir] >= 0) t.factor += a.th[a.d.dir_param[a.r.dir]];
  }
  static int reads(const EffectArgs& a, int* o) {
    return a.r.dir >= 0 && a.d.dir_param[a.r.dir] >= 0 ? (o[0] = a.d.dir_param[a.r.dir], 1) : 0;
  }
  static void name(const Design& d, const Effect&, const Names&, int s, Names& n) {
    for (size_t k = 0; k < d.fixed_directions.size(); ++k)
      if (d.dir_param[k] >= 0) n[s + d.dir_param[k]] = "g [direction " + fmt(d.fixed_directions[k]) + " deg]";
  }
};

/// mu (1 + c1 sin^2(2 phi) + c2 (cos 2phi - cos 6phi)/2).
struct DirectionFourier {
  static int count(const Design&, const Effect&) { return 2; }
  static void apply(const EffectArgs& a, Terms& t) { t.factor += a.th[0] * a.r.sin2 + a.th[1] * a.r.four2; }
  static void name(const Design&, const Effect&, const Names&, int s, Names& n) {
    n[s] = "c1 sin^2(2 phi)";
    n[s + 1] = "c2 (cos 2phi - cos 6phi)/2";
  }
};

/// mu (1 + s_pin), one factor per pin but the first.
struct PinSurface {
  static int count(const Design& d, const Effect&) { return static_cast<int>(d.pins.size()) - 1; }
  static void apply(const EffectArgs& a, Terms& t) {
    if (a.r.pin > 0) t.pinf += a.th[a.r.pin - 1];
  }
  static int reads(const EffectArgs& a, int* o) { return a.r.pin > 0 ? (o[0] = a.r.pin - 1, 1) : 0; }
  static void name(const Design& d, const Effect&, const Names&, int s, Names& n) {
    for (size_t p = 1; p < d.pins.size(); ++p) n[s + p - 1] = "s_pin " + fmt(d.pins[p]) + " mm";
  }
};

/// bending_tension and bending_linear act on the bending line (fit_bending), not on mu: no friction parameter.
struct BendingTension {
  static int count(const Design&, const Effect&) { return 0; }
  static void apply(const EffectArgs&, Terms&) {}
  static void name(const Design&, const Effect&, const Names&, int, Names&) {}
};

/// The offsets (from the effect's first parameter) of the parameters rule R may
/// read for the row of a: R::reads when it has one, else all R::count of them.
template <class R, class = void>
struct HasReads : std::false_type {};
template <class R>
struct HasReads<R, std::void_t<decltype(R::reads(std::declval<const EffectArgs&>(), std::declval<int*>()))>>
    : std::true_type {};
template <class R>
void rule_reads(const EffectArgs& a, std::vector<int>& out) {
  const int n = R::count(a.d, a.e);
  if constexpr (HasReads<R>::value) {
    // The claim in a scratch buffer of the rule's count (out grew to the count
    // and back for every row: an allocation per row for a 42-level factor).
    thread_local std::vector<int> claim;
    claim.resize(static_cast<size_t>(std::max(n, 1)));
    const int m = R::reads(a, claim.data());
    bool inside = m >= 0 && m <= n;  // a claim outside the rule's own block is not believed
    for (int j = 0; inside && j < m; ++j) inside = claim[j] >= 0 && claim[j] < n;
    if (inside) {
      out.insert(out.end(), claim.begin(), claim.begin() + m);
      return;
    }
  }
  for (int j = 0; j < n; ++j) out.push_back(j);
}

/// Calls f(Rule{}) with the rule of kind k: the one switch over EffectKind
/// (-Wswitch checks that every kind has a rule).
template <class F>
decltype(auto) visit_rule(EffectKind k, F&& f) {
  switch (k) {
    case EffectKind::pressure_mu: return f(PressureMu{});
    case EffectKind::stribeck: return f(Stribeck{});
    case EffectKind::depletion: return f(Depletion{});
    case EffectKind::direction_harmonic: return f(DirectionHarmonic{});
    case EffectKind::pin_surface: return f(PinSurface{});
    case EffectKind::drift:
    case EffectKind::generic_linear: return f(Linear{});
    case EffectKind::bending_tension: break;
    case EffectKind::categorical: return f(Categorical{});
    case EffectKind::generic_saturating: return f(Saturating{});
    case EffectKind::direction_level: return f(DirectionLevel{});
    case EffectKind::direction_fourier: return f(DirectionFourier{});
    case EffectKind::generic_log:
    case EffectKind::generic_exp:
    case EffectKind::generic_step: return f(Linear{});
    case EffectKind::generic_linear_by: return f(LinearBy{});
    case EffectKind::categorical_by: return f(CategoricalBy{});
    case EffectKind::bending_linear: break;  // on the bending lines (model.cpp), no friction parameter
    case EffectKind::generic_smooth: return f(Smooth{});
    case EffectKind::force_offset: return f(ForceOffset{});
  }
  return f(BendingTension{});
}

}  // namespace drawbend::loop::detail
