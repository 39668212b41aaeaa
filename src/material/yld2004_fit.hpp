#pragma once
// Calibration of Yld2004-18p (material/yld2004.hpp) on a sheet's material
// tests, and the same tests predicted by any calibrated yield function.
//
// Tests (a CSV like data/materials/aa6016_t4_esaform2021.csv, columns
// test, angle_deg, stress_ratio, r_value; '#' comment lines): rows
//   uniaxial,<angle>,<sigma_t/sigma_0>,<r_t>      (either value may be empty)
//   balanced_biaxial,,<sigma_b/sigma_0>,<rb>      (rb = d eps_TD / d eps_RD; may be empty)
//   plane_strain,<angle>,<sigma_major/sigma_0>,   (plane strain across the loading direction)
// Bad rows are InputErrors naming file:line: column.
//
// Fit: weighted least squares on relative residuals,
//   cost = sum_d w_d ((p_d - m_d) / m_d)^2,
// w_d the weight of the datum's kind (FitWeights, printed by the callers), p_d
// the prediction of the normalised set (material/yield_points.hpp), over the
// 14 in-plane coefficients c12..c32 and c66 of C' and C''; c44 = c55 = 1 in
// both (no sheet test sees the out-of-plane shears).  Levenberg-Marquardt
// with a forward-difference Jacobian (step 1e-7), from the isotropic set and
// 15 deterministic starts around it (uniform +-0.5 on every coefficient,
// mt19937 seed 2004); the best converged set that Yld2004::validate() accepts
// (closed and convex) is returned, as found (c44 = c55 = 1) and normalised.
#include <string>
#include <vector>

#include "material/hill48.hpp"
#include "material/yld2004.hpp"

namespace drawbend::material {

struct SheetDatum {
  enum Kind { uniaxial_stress, uniaxial_r, biaxial_stress, biaxial_r, plane_strain } kind;
  double angle_deg = 0;  ///< to RD (uniaxial, plane strain)
  double value = 0;      ///< measured ratio to sigma_0, or r-value
  std::string where;     ///< file:line: column
  std::string label() const;  ///< e.g. "r(45)", "sigma(15)/sigma0", "sigma_b/sigma0"
};

struct SheetTests {
  std::string path;
  std::vector<SheetDatum> data;
  /// Lookups of the measured values (NaN when absent).
  double uniaxial_stress(double angle_deg) const;
  double r_value(double angle_deg) const;
  double biaxial_stress() const;
};
SheetTests load_sheet_tests(const std::string& csv_path);

struct FitWeights {
  double stress = 1.0;        ///< each uniaxial yield-stress ratio
  double r = 1.0;             ///< each uniaxial r-value
  double biaxial = 1.0;       ///< sigma_b / sigma_0 and rb
  double plane_strain = 1.0;  ///< each plane-strain stress ratio
  double of(SheetDatum::Kind k) const;
};

/// Prediction of one datum by a yield function (Yld2004 or Hill48).
double predict(const Yld2004& y, const SheetDatum& d);
double predict(const Hill48& h, const SheetDatum& d);

struct Yld2004Fit {
  Yld2004 yield;     ///< normalised (sigma_bar of unit RD tension = 1)
  Yld2004 raw;       ///< the same before normalisation: c44 = c55 = 1 exactly (yield = raw scaled by 1/scale)
  double scale = 1;  ///< sigma_bar of unit RD tension under raw
  double cost = 0;   ///< weighted sum of squared relative residuals
  int starts = 0, accepted = 0;  ///< starts tried, and those that converged to a valid set
  /// Every accepted start's converged set (normalised), in start order: the local minima of the cost, which can
  /// fit the tests about equally well and still differ where no test looks (Chapter v1, the flange's shear).
  struct Local {
    int start = 0;
    double cost = 0;
    Yld2004 yield;
  };
  std::vector<Local> local;
};
/// InputError (naming the file) unless the tests hold sigma and r at 0, 45 and 90 deg and the weights of both
/// kinds are > 0: the least data that fix an orthotropic sheet's in-plane anisotropy (fit_yld2004 calls it).
void require_fittable(const SheetTests& tests, const FitWeights& w);
Yld2004Fit fit_yld2004(const SheetTests& tests, const FitWeights& w, double a = 8.0);

/// Root mean square of the residuals p - m (ratios, r-values) of one kind of datum (NaN when there is none).
double rms_residual(const Yld2004& y, const SheetTests& t, SheetDatum::Kind kind);
double rms_residual(const Hill48& h, const SheetTests& t, SheetDatum::Kind kind);

/// One yield function of the calibration table: a Yld2004 or a Hill48 (exactly one set).
struct NamedYield {
  std::string name;
  const Yld2004* yld = nullptr;
  const Hill48* hill = nullptr;
  double predict(const SheetDatum& d) const;
  double rms(const SheetTests& t, SheetDatum::Kind k) const;
  /// The function's uniaxial sigma_t / sigma_0, r_t and flange_shear_ratio (material/yield_points.hpp) at angle t
  /// to RD [deg]: the curves between the tested angles, and the flange's pure-shear state that no sheet test sees.
  double uniaxial_ratio(double angle_deg) const;
  double r_value(double angle_deg) const;
  double flange_shear_ratio(double angle_deg) const;
};
/// The table of every datum: header {datum, angle_deg, measured, weight, <model names>..., residual (the
/// model at `residual_of` minus measured)}, one row per datum, numbers with 4 decimals.
std::vector<std::vector<std::string>> calibration_table(const SheetTests& t, const FitWeights& w,
                                                        const std::vector<NamedYield>& models, std::size_t residual_of);

}  // namespace drawbend::material
