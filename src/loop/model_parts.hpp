#pragma once
// Internal to the loop's force model (model.hpp is the public header): the
// parameter layout, the table of effects, and the row prediction that the
// fits (model.cpp) and the public predictions (predict.cpp) share.
//
//   design.cpp        Design, make_design: per-row quantities from the data and maps
//   effect_rules.hpp  one rule per EffectKind: its parameter count, its term in mu, its names
//   effect_rules.cpp  the layout of theta and the parameters' names from those rules
//   predict_row.hpp   predict_row: base model + effects, Eqs. 2.2, 5.1 and the ellipse (inline)
//   predict.cpp       the public predictions
//   model.cpp         the fits: bending lines, Levenberg-Marquardt, standard errors
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "loop/model.hpp"

namespace drawbend::loop::detail {

/// Where each friction parameter lives in theta (effect_rules.cpp).
struct Layout {
  std::vector<int> mu_rd, mu_td;  ///< per cell, -1 absent
  std::vector<int> eff_start;     ///< per effect: index of its first parameter
  int n = 0;
};

/// The multiplicative and pressure terms the effects contribute to mu of a
/// fixed-pin row: mu = (mu0 + a1 p) * factor * pinf.
struct Terms {
  double a1 = 0, factor = 1, pinf = 1;
  double add_N = 0;  ///< force-channel effects: added to the outlet force of the row (rotating rows too)
};

/// What an effect's rule (effect_rules.hpp) sees when it adds its term for row i (r is the row,
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

Layout layout(const Design& d, const ModelSpec& spec);

std::vector<std::string> friction_names(const Design& d, const ModelSpec& spec, const Layout& L,
                                        const std::vector<std::vector<std::string>>& level_names);

/// Predicted outlet force of row i [N] with friction parameters th; mu_out and
/// p_out receive mu and the map's mean pressure [MPa]; override_row replaces
/// d.rows[i] (same i for the effects' per-row data).  Defined in predict_row.hpp.
inline double predict_row(const Design& d, const Fit& f, const Layout& L, const Eigen::VectorXd& th, int i,
                          double* mu_out, const Row* override_row = nullptr, double* p_out = nullptr);

}  // namespace drawbend::loop::detail
