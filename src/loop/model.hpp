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
/// semi-axes mu_RD = a and mu_TD = b (Sec. 6.4, Fig. 6.5; analysis::ellipse_mu):
/// a b / sqrt(b^2 cos^2 + a^2 sin^2).
double ellipse(double a, double b, double phi);
/// The same from cos(phi) and sin(phi) (bit for bit ellipse(a, b, phi)).
double ellipse_cs(double a, double b, double c, double s);

constexpr double kWrapRad = 1.5707963267948966;  ///< 90 deg wrap (Sec. 5.6)
constexpr double kStripWidthMm = 25.4;           ///< Sec. 5.2
/// Design::values names of two model-input quantities that are not columns:
/// Eq. 2.2's pressure at the back tension (MPa) and ln of the speed (mm/s).
inline constexpr const char* kNominalPressure = "nominal_pressure_MPa";
inline constexpr const char* kLnSpeed = "ln_speed_mm_s";

/// Per-row quantities the model needs, precomputed from the data and maps.
struct Row {
  int pin = 0;           ///< index into Design::pins
  int cell = 0;          ///< index into Design::cells (fixed rows)
  bool rotating = false;
  double fback = 0, y = 0;  ///< back tension and measured outlet force [N]
  double phi = 0;           ///< direction [rad]
  double pw_ref = 0;        ///< map's force-weighted mean pressure at its reference tension [MPa]
  double fref = 0;          ///< the map's reference back tension [N]
  double lgL = 0;           ///< log10 lubricant number, centred over fixed rows
  double sliding = 0;       ///< sliding distance [mm] (0 when absent)
  double cos_phi = 1, sin_phi = 0;  ///< cos and sin of phi (the ellipse's, computed once per row)
  double sin2 = 0;          ///< sin^2(2 phi)
  double four2 = 0;         ///< (cos 2phi - cos 6phi) / 2
  int dir = -1;             ///< index into Design::fixed_directions (fixed rows)
};

/// Sets a row's direction phi [rad] and the functions of it that predictions use.
void set_direction(Row& r, double phi);

/// x -> (x - mean) / sd in place (sd with n - 1; all zeros when sd is 0), in row order.
void zscore_in_place(std::vector<double>& x);

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
  /// Bending force of pins without rotating-pin rows (NaN: the pin has them).
  std::vector<double> bend_fallback;
  std::string bending_label;         ///< how the bending force is obtained, per pin (every output shows it)
  bool missing_rotating = false;     ///< some pin has fixed rows but no rotating rows
  std::vector<double> fixed_directions;  ///< distinct directions of the fixed rows [deg], ascending
  std::vector<int> dir_param;            ///< per fixed direction: its direction_level parameter, -1 at RD/TD
  int n_dir_params = 0;
  /// Level index per row of a categorical column (extra column, "pin", or
  /// "direction_deg"), with the level names; throws InputError when absent.
  std::vector<int> levels(const std::string& column, std::vector<std::string>* names) const;
  /// z-scored numeric column (for drift effects); NaN-free or throws.
  std::vector<double> zscore(const std::string& column) const;
  /// The numeric column's raw values (same columns as zscore); an empty cell
  /// (missing value) takes the mean of the column's values; throws InputError
  /// for a column that is not numeric or has no value.
  std::vector<double> values(const std::string& column) const;
  /// Group index per row of a model input used as an effect's `by`: "pin"
  /// (pin index), "speed_mm_s", "direction_deg" (distinct values of the fixed
  /// rows, or 3 tertiles when more than 6), "lubricant", or "speed_mm_s>=t" /
  /// "direction_deg>=t" (two groups: below t, at or above t); *n receives the count.
  std::vector<int> groups(const std::string& by, int* n) const;
};

/// Bending force for pins without rotating-pin rows:
///   rotating  none given: such pins make make_design throw InputError (exit 2)
///   swift     Eq. 2.1 (Swift 1948), sigma_y 99.71 MPa (Table 5.1), t 1.04 mm,
///             full strip 25.4 mm, 90 deg wrap: constant per pin
///   fe        the map file's '# bending_force_N: <full strip N>' line (our FE
///             rotating-pin run at the map's reference tension): constant per pin
///   none      F_B = 0: the friction coefficient absorbs the bending force
///             (an upper bound of mu; labelled in every output)
enum class BendingSource { rotating, swift, fe, none };
BendingSource bending_source(const std::string& name);  ///< "linear"/"constant" -> rotating
std::string bending_source_name(BendingSource b);

/// Build the design.  Ra_sheet_um is the sheet roughness for the combined
/// roughness of the Stribeck effect (pin Ra from column pin_Ra_um, else 0.1 um,
/// Table 5.2).
Design make_design(const Dataset& d, const MapLibrary& maps, double Ra_sheet_um = 0.4,
                   BendingSource bending = BendingSource::rotating);

/// Map pressure at back tension F with bending force FB and friction force Ff:
/// the map scales with the mean strip tension (Eq. 2.2, (F_x + F_y)/2), i.e. by
/// (2F + FB + Ff) / (2 F_ref + FB(F_ref)).  FE maps measured at two back
/// tensions: see Chapter 7, section on the maps' scaling.
double map_pressure(const Row& r, double FB, double Ff, double FB_ref);

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
  std::vector<std::vector<double>> drift_z;  ///< per effect: its feature per row (z-score, log or exp transform)
  std::vector<std::vector<int>> group;       ///< per effect with a `by`: group index per row
  /// per generic_smooth effect: its spline basis, n_basis columns of one value per row
  std::vector<std::vector<std::vector<double>>> basis;
  bool has_force = false;  ///< the spec has a force_offset effect (rotating rows get its term too)
  std::vector<double> bend_extra;   ///< per row: bending-channel effects' c_pin z (empty: none)
  /// per pin: its base bending line at its mean back tension over the pins'
  /// mean (force_offset with bend_scaled; fixed by the first bending fit of fit_model)
  std::vector<double> bend_scale;
  std::vector<std::vector<int>> level;       ///< level index per row of each categorical effect
  std::vector<std::vector<std::string>> level_names;
  double rss = 0;                   ///< fixed-pin rows
  int n_fixed = 0, n_friction_params = 0;
  bool converged = false;
  std::vector<char> seen;            ///< friction parameter had training rows
};

/// Fit on the rows whose index is in `train` (all rows when empty).  With
/// standard_errors false (a cross-validation fold, a sum of squares) the
/// parameters' standard errors are not computed (f.params holds no friction
/// entry) and neither is the last Jacobian (least_squares.hpp); theta, the
/// bending lines and rss are the same bit for bit, except with a force
/// channel: there they are the joint fit's, without the friction-only refit
/// from it that gives the Jacobian (the same minimum, to the fit's tolerance).
Fit fit_model(const Design& d, const ModelSpec& spec, const std::vector<int>& train = {},
              bool standard_errors = true);
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
/// The same at direction phi [rad] (0 RD, pi/2 TD) instead of the row's own;
/// p_out: the map's force-weighted mean pressure of the row [MPa].
double predict_mu_at(const Design& d, const Fit& f, int i, double phi_rad, double* p_out);

}  // namespace drawbend::loop
