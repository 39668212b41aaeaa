// The effect library: names, physical meanings, and which candidate variable
// each effect can trace.
#include "loop/effects.hpp"

namespace drawbend::loop {

std::string effect_name(EffectKind k) {
  switch (k) {
    case EffectKind::pressure_mu: return "pressure_mu";
    case EffectKind::stribeck: return "stribeck";
    case EffectKind::depletion: return "depletion";
    case EffectKind::direction_harmonic: return "direction_harmonic";
    case EffectKind::pin_surface: return "pin_surface";
    case EffectKind::drift: return "drift";
    case EffectKind::bending_tension: return "bending_tension";
    case EffectKind::categorical: return "group_factor";
    case EffectKind::generic_linear: return "generic_linear";
    case EffectKind::generic_saturating: return "generic_saturating";
    case EffectKind::direction_level: return "direction_levels";
    case EffectKind::direction_fourier: return "direction_fourier";
    case EffectKind::generic_log: return "generic_log";
    case EffectKind::generic_exp: return "generic_saturating_exp";
    case EffectKind::generic_step: return "generic_step";
    case EffectKind::generic_linear_by: return "generic_linear_by_group";
    case EffectKind::categorical_by: return "group_factor_by_group";
    case EffectKind::bending_linear: return "bending_linear";
    case EffectKind::generic_smooth: return "generic_smooth";
    case EffectKind::force_offset: return "force_offset";
  }
  return "?";
}

std::string effect_meaning(EffectKind k) {
  switch (k) {
    case EffectKind::pressure_mu:
      return "pressure-dependent friction mu(p) = mu0 + a1 p, integrated over the frictionless pressure map "
             "scaled by c (new method, Eqs. 4.2, 5.3); one a1 per cell";
    case EffectKind::stribeck:
      return "mixed lubrication: mu scales with log10 of the lubricant number L = eta v / (p Ra), Ra the "
             "combined roughness sqrt(Ra_sheet^2 + Ra_pin^2) (Eq. 3.1); one slope";
    case EffectKind::depletion:
      return "lubricant depletion along the sliding distance s: mu (1 - beta (1 - exp(-s/lambda))); beta and "
             "lambda";
    case EffectKind::direction_harmonic:
      return "anisotropy beyond the RD/TD ellipse: mu (1 + beta sin^2(2 phi)), peak at 45 deg; one amplitude";
    case EffectKind::pin_surface:
      return "per-pin surface factor: mu (1 + s_pin) for each pin but the smallest (different finish or wear)";
    case EffectKind::drift:
      return "linear drift with test order or time (tool wear, temperature): mu (1 + beta z); one slope";
    case EffectKind::bending_tension:
      return "back-tension term in the bending force F_B = b0 + b1 F_back per pin (Swift Eq. 2.1 has none)";
    case EffectKind::categorical:
      return "group factor: mu (1 + g_level) for every level but the first (e.g. coil, batch, lubricant lot); "
             "one factor per level";
    case EffectKind::generic_linear:
      return "generic effect of a variable no library effect knows: mu (1 + beta z), z its z-score; sign and size "
             "only, no physics claimed";
    case EffectKind::generic_saturating:
      return "generic saturating effect: mu (1 + beta tanh z), z the variable's z-score; no physics claimed";
    case EffectKind::direction_level:
      return "direction as a factor: mu (1 + g_dir) at each direction other than RD (0) and TD (90 deg), "
             "against the RD/TD ellipse";
    case EffectKind::direction_fourier:
      return "smooth non-elliptical anisotropy: mu (1 + c1 sin^2 2phi + c2 (cos 2phi - cos 6phi)/2), "
             "both terms zero at RD and TD";
    case EffectKind::generic_log:
      return "generic logarithmic effect: mu (1 + beta u), u the z-score of log(x); no physics claimed";
    case EffectKind::generic_exp:
      return "generic saturating exponential: mu (1 + beta (1 - exp(-(x - x_min)/lambda))), lambda chosen on a "
             "grid; no physics claimed";
    case EffectKind::generic_step:
      return "generic step: mu (1 + beta [x > c]), the threshold c chosen on a grid of the column's quantiles "
             "(deciles, then 80-quantiles near the best); no physics claimed";
    case EffectKind::generic_linear_by:
      return "generic effect acting differently per group of a model input: mu (1 + beta_g z), one slope per "
             "group (pin, speed, direction or lubricant); no physics claimed";
    case EffectKind::categorical_by:
      return "group factor per group of a model input: mu (1 + g_{group,level}); no physics claimed";
    case EffectKind::bending_linear:
      return "bending channel: the bending force F_B + c_pin z per pin (z the variable's z-score), fitted with "
             "the bending lines on the rotating-pin rows; a sheet thickness or yield stress acts here";
    case EffectKind::generic_smooth:
      return "generic smooth effect of any shape: mu (1 + sum_j beta_j B_j(x)), B_j a natural cubic spline basis "
             "with knots at quantiles of x (a bump, U, step, periodic or sigmoid shape), optionally per group of a "
             "model input; its dof chosen by held-out error; no physics claimed";
    case EffectKind::force_offset:
      return "force channel: an extra force on the outlet force of every row, fixed and rotating pin (F_out + "
             "sum_j c_j B_j(x), levels or a spline of x, optionally per group of a model input or in one group only), "
             "fitted jointly with friction and the "
             "bending lines: a drag, a bending-force change (thickness, yield stress) or an offset of the load cell";
  }
  return "";
}

std::vector<EffectKind> effects_for(const std::string& c) {
  using K = EffectKind;
  if (c == "pin" || c == "pin_diameter_mm" || c == "inv_R_per_mm")
    return {K::pressure_mu, K::pin_surface};
  if (c == "avg_pressure_MPa") return {K::pressure_mu, K::stribeck};
  if (c == "back_tension_N") return {K::bending_tension, K::pressure_mu};
  if (c == "speed_mm_s") return {K::stribeck};
  if (c == "pin_Ra_um") return {K::pin_surface, K::stribeck};
  if (c == "sliding_distance_mm") return {K::depletion};
  if (c == "direction_deg") return {K::direction_harmonic, K::direction_fourier, K::direction_level};
  if (c == "test_order" || c == "time_s") return {K::drift};
  return {};
}

std::vector<EffectKind> generic_effects(bool categorical) {
  if (categorical) return {EffectKind::categorical};
  return {EffectKind::generic_linear, EffectKind::generic_saturating};
}

bool acts_on_bending(EffectKind k) {
  return k == EffectKind::bending_linear || k == EffectKind::bending_tension || k == EffectKind::force_offset;
}

bool is_identity(const std::string& c) { return c == "test_id"; }

}  // namespace drawbend::loop
