#pragma once
// The loop's force model: base model plus library effects, fitted to the rows
// of a measured data set.  Units: N, mm, MPa, mm/s.
//
// Base model
//   rotating pin:  F_out = F_back + F_B,   F_B = b0_pin + b1_pin F_back (linear
//                  least squares per pin diameter on the rotating-pin rows;
//                  b1 = 0 with the "constant" bending option, Swift-like)
//   fixed pin:     F_out = F_back + F_B + F_back (exp(mu Theta) - 1)  (Eq. 5.1)
//                  mu = ellipse(mu_RD, mu_TD; direction) per cell, a cell being
//                  lubricant x speed level x direction level (speed is a level
//                  only with at most 3 distinct speeds, direction only with at
//                  most 2; otherwise they are continuous and candidates).
// Effects (effects.hpp) modify mu (or the bending force).  The friction
// parameters are fitted by Levenberg-Marquardt on the fixed-pin rows with the
// bending lines held; standard errors from s^2 (J^T J)^-1.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "loop/effects.hpp"
#include "loop/maps.hpp"
#include "loop/measured.hpp"

namespace drawbend::loop {

/// Friction coefficient in direction phi [rad] from RD on the ellipse with
/// semi-axes mu_RD = a and mu_TD = b (Eq. 6.3): a b / sqrt(b^2 cos^2 + a^2 sin^2).
double ellipse(double a, double b, double phi);

constexpr double kWrapRad = 1.5707963267948966;  ///< 90 deg wrap (Sec. 5.6)
constexpr double kStripWidthMm = 25.4;           ///< Sec. 5.2

/// Per-row quantities the model needs, precomputed from the data and maps.
struct Row {
  int pin = 0;           ///< index into Design::pins
  int cell = 0;          ///< index into Design::cells (fixed rows)
  bool rotating = false;
  double fback = 0, y = 0;  ///< back tension and measured outlet force [N]
  double phi = 0;           ///< direction [rad]
  double pw_map = 0;        ///< map's force-weighted mean pressure at F_back, c = 1 [MPa]
  double lgL = 0;           ///< log10 lubricant number, centred over fixed rows
  double sliding = 0;       ///< sliding distance [mm] (0 when absent)
  double sin2 = 0;          ///< sin^2(2 phi)
};

struct Design {
  const Dataset* data = nullptr;
  const MapLibrary* maps = nullptr;
  std::vector<double> pins;          ///< distinct pin diameters, ascending
  std::vector<std::string> cells;    ///< cell names
  std::vector<char> cell_rd, cell_td;  ///< which direction parameters a cell has
  bool speed_is_level = true;
  bool direction_is_level = true;  ///< at most 2 directions: direction is part of the cell
  std::vector<Row> rows;             ///< parallel to data->rows
  std::vector<std::string> notes;    ///< how the design was built
  /// z-scored numeric column (for drift effects); NaN-free or throws.
  std::vector<double> zscore(const std::string& column) const;
};

/// Build the design.  Ra_sheet_um is the sheet roughness for the combined
/// roughness of the Stribeck effect (pin Ra from column pin_Ra_um, else 0.1 um,
/// Table 5.2).
Design make_design(const Dataset& d, const MapLibrary& maps, double Ra_sheet_um = 0.4);

struct ModelSpec {
  bool bending_linear = true;
  std::vector<Effect> effects;
  bool has(EffectKind k) const;
  std::string describe() const;
};

struct Param {
  std::string name;
  double value = 0, se = 0;
  std::string unit;
};

struct Fit {
  ModelSpec spec;
  Eigen::VectorXd theta;            ///< friction parameters
  std::vector<Param> params;        ///< bending + friction, with standard errors
  std::vector<double> b0, b1;       ///< bending line per pin (NaN: no rotating rows)
  std::vector<std::vector<double>> drift_z;  ///< z-scores of each drift effect's variable
  double rss = 0;                   ///< fixed-pin rows
  int n_fixed = 0, n_friction_params = 0;
  bool converged = false;
  std::vector<char> seen;            ///< friction parameter had training rows
};

/// Fit on the rows whose index is in `train` (all rows when empty).
Fit fit_model(const Design& d, const ModelSpec& spec, const std::vector<int>& train = {});
/// Bending and friction fitted together on all rows (rotating and fixed), so
/// that the residual sum of squares of nested models can be compared by an F
/// test that accounts for the uncertainty of the bending lines.
struct JointFit {
  double rss = 0;
  int n = 0, p = 0;
};
JointFit fit_joint(const Design& d, const ModelSpec& spec);

/// Predicted outlet force of row i [N] (NaN when its pin has no bending line).
double predict(const Design& d, const Fit& f, int i);
/// Predicted friction coefficient (mean over the map) of fixed row i.
double predict_mu(const Design& d, const Fit& f, int i);

}  // namespace drawbend::loop
