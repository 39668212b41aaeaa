#pragma once
// Internal to the loop's force model (model.hpp is the public header): the
// parameter layout, the table of effects, and the row prediction that the
// fits (model.cpp) and the public predictions (predict.cpp) share.
//
//   design.cpp        Design, make_design: per-row quantities from the data and maps
//   effect_rules.cpp  one rule per EffectKind: its parameter count, its term in mu, its names
//   predict.cpp       predict_row: base model + effects, Eqs. 2.2, 5.1 and the ellipse
//   model.cpp         the fits: bending lines, Levenberg-Marquardt, standard errors
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "loop/model.hpp"

namespace drawbend::loop::detail {

/// Where each friction parameter lives in theta.
struct Layout {
  std::vector<int> mu_rd, mu_td;  ///< per cell, -1 absent
  std::vector<int> eff_start;     ///< per effect: index of its first parameter
  int n = 0;
};

/// The multiplicative and pressure terms the effects contribute to mu of a
/// fixed-pin row: mu = (mu0 + a1 p) * factor * pinf.
struct Terms {
  double a1 = 0, factor = 1, pinf = 1;
};

/// What an effect's rule sees when it adds its term for row i (r is the row,
/// possibly a copy at another direction); th points at the effect's first parameter.
struct EffectArgs {
  const Design& d;
  const Fit& f;
  const Row& r;
  int i;
  size_t k;  ///< index of the effect in f.spec.effects
  const Effect& e;
  const double* th;
};

/// One entry of the effect table: everything the model does per EffectKind.
struct EffectRule {
  int (*count)(const Design& d, const Effect& e);  ///< number of friction parameters
  void (*apply)(const EffectArgs& a, Terms& t);    ///< adds the effect's term (nullptr: none)
  /// Writes the names of its parameters at n[s..]; level_names: the effect's level names.
  void (*name)(const Design& d, const Effect& e, const std::vector<std::string>& level_names, int s,
               std::vector<std::string>& n);
};

/// The rule of an effect kind (one switch, checked for completeness by -Wswitch).
const EffectRule& rule(EffectKind k);

Layout layout(const Design& d, const ModelSpec& spec);

std::vector<std::string> friction_names(const Design& d, const ModelSpec& spec, const Layout& L,
                                        const std::vector<std::vector<std::string>>& level_names);

/// Predicted outlet force of row i [N] with friction parameters th; mu_out and
/// p_out receive mu and the map's mean pressure [MPa]; override_row replaces
/// d.rows[i] (same i for the effects' per-row data).
double predict_row(const Design& d, const Fit& f, const Layout& L, const Eigen::VectorXd& th, int i, double* mu_out,
                   const Row* override_row = nullptr, double* p_out = nullptr);

}  // namespace drawbend::loop::detail
