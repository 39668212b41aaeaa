#pragma once
// Rate-independent plasticity with combined isotropic-kinematic hardening and
// a von Mises or Hill'48 yield function, for solids (3D).
//
//   f = sigma_bar(sigma - alpha) - R(eps_p) <= 0,   alpha = sum_k alpha_k,
//   sigma_bar: Hill'48 in the sheet axes (material/hill48.hpp; von Mises as
//   its special case), associative flow d eps_p = d lambda d sigma_bar/d sigma,
//   d lambda = d eps_p_bar (work-conjugate equivalent plastic strain).
//
// Kinematic hardening, one of (KinematicHardening):
//  - Chaboche: one to three Armstrong-Frederick back stresses,
//      d alpha_k = (2/3) C_k d eps_p - gamma_k alpha_k d eps_p_bar,
//    on top of the isotropic curve R(eps_p) = the hardening curve itself.  In
//    uniaxial loading the scalar back stress X_k = (3/2) alpha_k,11 follows
//    X_k = (C_k/gamma_k)(1 - exp(-gamma_k eps_p)) (linear C_k eps_p for gamma_k = 0);
//  - the split with a mixing fraction beta in [0, 1]:
//      R(eps_p) = sigma_0 + (1 - beta)(sigma(eps_p) - sigma_0),
//      d alpha = (2/3) beta (d sigma/d eps_p) d eps_p,
//    so that monotonic proportional loading reproduces sigma(eps_p) exactly
//    for every beta, and a reversal after eps_p re-yields at
//    sigma(eps_p) - 2 R(eps_p) (Bauschinger effect; beta = 0 isotropic,
//    beta = 1 linear-kinematic along the curve).
//
// Return mapping (backward Euler).  With a_k = 1/(1 + gamma_k dl), the
// secant dS = sigma(eps_p + dl) - sigma(eps_p) of the split form, and
//   xi* = sigma_tr - sum_k a_k alpha_k,n - alpha_beta,n,
//   kappa = (2 G dl + (2/3)(sum_k a_k C_k dl + beta dS)) / R(eps_p + dl),
// the relative stress solves (I + kappa T M) xi = xi* (M the Hill matrix, T
// halving the shears: a 3x3 system for the normals and three divisions), and
// dl is the root of the scalar consistency condition
//   sigma_bar(xi(dl)) - R(eps_p + dl) = 0,
// found by a bracketed, safeguarded secant (Illinois) iteration to round-off
// (no step-size restriction), on the residual times 1 + kappa (F + G + H):
// the same root, and for von Mises a residual linear in dl on a curve segment
// (isotropic and split forms), so that the secant's first step lands on it.
// For the split form the secant dS makes the monotonic uniaxial back stress
// telescope to beta (sigma(eps_p) - sigma_0) exactly.  Hill'48 is evaluated in the sheet axes carried in the state.
//
// Objectivity (material/objectivity.hpp): update() rotates every back stress
// and the sheet axes with the point's spin before the return mapping, the same
// rotation the element applied to the stress.
//
// State per point: [eps_p, alpha_1 (6), ..., alpha_n (6), RD (3), ND (3)];
// the axes only for Hill'48 (von Mises has no preferred direction).
#include <vector>

#include "material/hardening_curve.hpp"
#include "material/hill48.hpp"
#include "material/material.hpp"

namespace drawbend::material {

struct KinematicHardening {
  struct Term {
    double C = 0;      ///< initial kinematic modulus [MPa]
    double gamma = 0;  ///< dynamic recovery [1]
  };
  std::vector<Term> chaboche;  ///< 0 to 3 Armstrong-Frederick terms
  double beta = 0;             ///< split form: kinematic fraction of the curve's hardening, in [0, 1]
  /// Throws std::invalid_argument for C < 0, gamma < 0, beta outside [0, 1],
  /// more than three terms, or both forms at once.
  void validate() const;
  bool none() const { return chaboche.empty() && beta == 0.0; }
};

class CombinedPlasticity final : public Material {
 public:
  /// E [MPa], nu, rho [t/mm^3]; curve: flow stress [MPa] against eps_p (the
  /// isotropic part for Chaboche, the monotonic curve for the split form).
  CombinedPlasticity(double youngs_modulus, double poisson_ratio, double density, HardeningCurve curve,
                     KinematicHardening kinematic, Hill48 yield = Hill48::von_mises());

  int state_size() const override { return ns_; }
  void init_state(double* state, const SheetAxes& axes) const override;
  using Material::update;
  void update(const double deps[6], const Spin& spin, double sigma[6], double* state) const override;
  double density() const override { return el_.rho; }
  double youngs_modulus() const override { return el_.E; }
  double poisson_ratio() const override { return el_.nu; }
  double plastic_strain(const double* state) const override { return state[0]; }
  bool directional() const override { return aniso_; }
  bool uses_spin() const override { return aniso_ || nback_ > 0; }
  double tangent_ratio(const double* sigma, const double* state) const override;
  std::string describe() const override;

  /// Sum of the back stresses of a state (global axes, Voigt, tensor shears) [MPa].
  void back_stress(const double* state, double alpha[6]) const override;
  bool has_back_stress() const override { return nback_ > 0; }
  bool sheet_axes(const double* state, double rd[3], double nd[3]) const override {
    if (!aniso_) return false;
    const double* a = state + 1 + 6 * nback_;  // [eps_p, alpha_k (6 each), RD (3), ND (3)]
    for (int c = 0; c < 3; ++c) rd[c] = a[c], nd[c] = a[3 + c];
    return true;
  }
  /// Current sheet axes of a state (global components); von Mises: the x, y, z axes.
  SheetAxes axes(const double* state) const;
  /// Isotropic yield stress R(eps_p) [MPa].
  double isotropic_stress(double ep) const;
  const Hill48& yield() const { return hill_; }
  const KinematicHardening& kinematic() const { return kin_; }
  bool anisotropic() const { return aniso_; }

  /// The constants behind update() and tangent_ratio(), for code that must
  /// compute their bits in another form (the element kernel's lanes:
  /// material/lanes/combined_lanes.hpp and material/lanes/hill48_lanes.hpp repeat both step by step;
  /// a change here must be made there, or test_element_kernel fails).
  struct LaneParams {
    double lambda, G, E;     ///< elastic constants [MPa]
    double s0, beta;         ///< initial yield stress [MPa]; split fraction (0: Chaboche or none)
    double C[3], gamma[3];   ///< Chaboche terms: C [MPa], gamma [1]
    int nterms, nback;       ///< Chaboche terms; back stresses in the state
    bool aniso;              ///< Hill'48 in the sheet axes carried in the state
    Hill48 hill;
    HardeningCurve::Table curve;
  };
  LaneParams lane_params() const noexcept;
  void bind_lanes(LaneBinding& b) const override;

 private:
  double equivalent(const double xi[6]) const;  // sigma_bar in the sheet axes
  void solve_relative(double kappa, const double xs[6], double xi[6]) const;  // (I + kappa T M) xi = xs
  // The steps of update(), in its order (combined_plasticity.cpp); an: the back stresses in the sheet axes.
  void turn_history(const Spin& spin, double* back, double Q[3][3]) const;
  void trial_in_sheet_axes(const double Q[3][3], const double tr[6], const double* back, double ts[6],
                           double (*an)[6]) const;
  double plastic_multiplier(double ep, double s_ep, double f0, const double ts[6], const double (*an)[6], double xi[6],
                            double& Rv) const;
  void harden_and_rotate_back(const double Q[3][3], double ep, double s_ep, double dl, const double xi[6], double Rv,
                              double (*an)[6], double sigma[6], double* back) const;

  IsotropicElasticity el_;
  HardeningCurve curve_;
  KinematicHardening kin_;
  Hill48 hill_;
  bool aniso_;
  int nback_;   // back stresses in the state (Chaboche terms, or 1 for the split form)
  int ns_;
  double s0_;   // initial yield stress
};

}  // namespace drawbend::material
