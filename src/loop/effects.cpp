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
  if (c == "direction_deg") return {K::direction_harmonic};
  if (c == "test_order" || c == "time_s") return {K::drift};
  return {};
}

}  // namespace drawbend::loop
