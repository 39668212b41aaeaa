#pragma once
// The library of physical effects the loop may add, each with a stated
// meaning and few parameters, and the candidate variables each can explain.
// All friction effects act on the friction coefficient mu of a fixed-pin row:
//   mu = (mu_base + a1_cell c p_w) * (1 + sum of terms) * (1 + s_pin)
#include <string>
#include <vector>

namespace drawbend::loop {

enum class EffectKind {
  pressure_mu,         ///< mu(p) = mu0 + a1 p over the pressure map, per cell (new method)
  stribeck,            ///< mu * (1 + beta log10(L/L_ref)), L = eta v / (p Ra_combined)
  depletion,           ///< mu * (1 - beta (1 - exp(-s/lambda))), s = sliding distance
  direction_harmonic,  ///< mu * (1 + beta sin^2(2 phi)): departure from the ellipse
  pin_surface,         ///< mu * (1 + s_pin), one factor per pin but the first
  drift,               ///< mu * (1 + beta z), z = z-score of test order or time
  bending_tension,     ///< bending force b0 + b1 F_back per pin (instead of constant)
};

struct Effect {
  EffectKind kind = EffectKind::pressure_mu;
  std::string variable;  ///< the column a drift effect uses
  double lambda_mm = 0;  ///< depletion length (chosen on a grid)
};

std::string effect_name(EffectKind k);
std::string effect_meaning(EffectKind k);
/// Library effects that can explain a candidate variable (empty: none does).
std::vector<EffectKind> effects_for(const std::string& candidate);

}  // namespace drawbend::loop
