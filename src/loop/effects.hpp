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
  categorical,         ///< mu * (1 + g_level), one factor per level but the first (batch, coil, lot)
  generic_linear,      ///< mu * (1 + beta z), z = z-score of a column no library effect knows
  generic_saturating,  ///< mu * (1 + beta tanh(z)): saturating monotone alternative
  direction_level,     ///< mu * (1 + g_dir) per direction level other than 0 and 90 deg
  direction_fourier,   ///< mu * (1 + c1 sin^2(2 phi) + c2 (cos 2phi - cos 6phi)/2): smooth, zero at RD and TD
  generic_log,         ///< mu * (1 + beta u), u = z-score of log(x) (positive columns)
  generic_exp,         ///< mu * (1 + beta (1 - exp(-(x - x_min)/lambda))): saturating exponential, lambda on a grid
  generic_linear_by,   ///< mu * (1 + beta_g z): one slope per group g of a model input (pin, speed, direction)
  categorical_by,      ///< mu * (1 + g_{group,level}): a group factor per group of a model input
  bending_linear,      ///< bending channel: F_B + c_pin z per pin (fitted with the bending lines), z the z-score
  generic_smooth,      ///< mu * (1 + sum_j beta_j B_j(x)): natural cubic spline of n_basis dof (per group with `by`),
                       ///< or a Gaussian bump of x (Effect::bump_width > 0, n_basis 1), or a step of x (Effect::step)
  force_offset,        ///< outlet force + sum_j c_j B_j(x) on every row, rotating included (levels: one c per level
                       ///< but the first; numeric: spline basis of n_basis dof); per pin with by = "pin"
  generic_step,        ///< mu * (1 + beta [x > c]): a step at the threshold c (Effect::lambda_mm) chosen on a grid
};

struct Effect {
  EffectKind kind = EffectKind::pressure_mu;
  std::string variable;  ///< the column a drift effect uses
  double lambda_mm = 0;  ///< depletion length, generic_exp length, generic_step threshold (chosen on a grid)
  int n_levels = 0;      ///< categorical: number of levels of the column
  /// generic_linear_by / categorical_by: the model input whose groups get their
  /// own parameters ("pin", "speed_mm_s", "direction_deg" or "lubricant").
  std::string by;
  int n_groups = 0;      ///< number of groups of `by`
  /// generic_linear_by / categorical_by / generic_smooth with `by`: >= 0 confines
  /// the effect to that one group of `by` (one cell: a pin, speed, direction or
  /// lubricant), with one group's parameters; -1: every group its own.
  int cell = -1;
  /// One-cell forms (cell >= 0): the cell's own factor as well, mu (1 + c0 +
  /// ...) on its rows, when the cell is not a union of the model's cells (a
  /// pin, or a group of an input that is not a cell level): there no mu of the
  /// base model carries the cell's mean, and without it the levels form would
  /// assume the effect zero at the column's first level in the file (its fit
  /// would depend on the file's row order).  Read by the levels rule
  /// (categorical_by) only: a slope or smooth in one cell is zero at the
  /// column's mean whatever the order (forms.cpp in_cell).
  bool cell_offset = false;
  int n_basis = 0;       ///< generic_smooth: spline basis functions (dof of the shape, constant excluded)
  /// force_offset: the term times the row's pin's bending force relative to
  /// the pins' mean (Fit::bend_scale): a change of the bending force itself
  /// (thickness, yield stress) is as many per cent on every pin, not as many newtons.
  bool bend_scaled = false;
  /// generic_linear / generic_step / generic_smooth: the shape times the
  /// centred value of this model-input quantity (Design::values: e.g.
  /// kNominalPressure or kLnSpeed), so the column changes mu's slope in it
  /// (empty: no multiplier).
  std::string times;
  /// generic_smooth with `times`: the basis is the column's levels (an
  /// indicator per level but the first, centred; n_basis = levels - 1), not a
  /// spline: a categorical or few-level column that changes mu's slope in the
  /// model input, one slope change per level.
  bool level_basis = false;
  /// generic_smooth / force_offset with n_basis 1: > 0 makes the basis a
  /// Gaussian bump of the column, exp(-((x - bump_centre) / bump_width)^2 / 2)
  /// (bump.hpp; centred and scaled to unit sd, as the spline basis), its
  /// centre and width (column units) scanned by scan_bump; 0: the spline.
  double bump_centre = 0, bump_width = 0;
  /// generic_smooth / force_offset with n_basis 1: true makes the basis a step
  /// of the column, [x > step_at] (bump.hpp; centred and scaled to unit sd, as
  /// the bump), its threshold (column units) scanned by scan_step; an effect
  /// that switches on above a value in one cell, or on the force channel.
  bool step = false;
  double step_at = 0;
};

std::string effect_name(EffectKind k);
std::string effect_meaning(EffectKind k);
/// Library effects that can explain a candidate variable (empty: none does).
std::vector<EffectKind> effects_for(const std::string& candidate);
/// Generic effects for a variable no library effect explains (or whose library
/// effects failed): categorical -> group factor; numeric -> linear and saturating.
std::vector<EffectKind> generic_effects(bool categorical);
/// Effects that act on the bending force (channel "bending"), not on mu.
bool acts_on_bending(EffectKind k);
/// Identity variables (test_id): handled by design as a random effect, never
/// permuted and never added as a fixed effect.
bool is_identity(const std::string& candidate);

}  // namespace drawbend::loop
