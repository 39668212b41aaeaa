#pragma once
// Rate-independent plasticity with the Yld2004-18p yield function
// (material/yld2004.hpp) in the sheet axes and the combined isotropic-
// kinematic hardening of CombinedPlasticity (material/combined_plasticity.hpp:
// Chaboche terms or the split form with beta; none for isotropic hardening):
//
//   f = sigma_bar(sigma - alpha) - R(eps_p) <= 0,  d eps_p = d lambda n,
//   n = d sigma_bar / d sigma,  d lambda = d eps_p_bar (work-conjugate).
//
// Return map: backward Euler (closest point in the energy norm) solved by
// iterating on the normal.  For a multiplier x and a normal n the end point is
//   sigma = sigma_trial - 2 G x n,  alpha_k = (alpha_k,n + (2/3) C_k x n) / (1 + gamma_k x)
//   (split form: alpha = alpha_n + (2/3) beta (sigma(eps_p + x) - sigma(eps_p)) n),
// and each iteration takes the normal n' and f of that end point, updates
//   x += f / (2 G n':n' + R'(eps_p + x) + n' : d alpha / d x),  n = n',
// until |f| <= 1e-6 R and 2 G x |n' - n| <= 1e-6 R (the end point would
// move by less than that with the new normal): then n is the normal of the
// returned point to that tolerance (associative flow at the end of the step,
// backward Euler).  The tolerance, 1e-6 of the flow stress (0.3 MPa x 1e-3 on
// this sheet), is far below the step's own first-order error; an explicit
// step's increment converges with one evaluation after the trial point's.  It contracts while 2 G x times the surface's
// curvature is below 1, which small increments ensure: when 60 iterations do
// not converge, the elastic trial increment is split into 4, 16, 64 and then
// 256 equal sub-increments, each returned the same way; should even that fail,
// the last iterate is scaled radially onto the yield surface (sigma_bar is
// homogeneous of degree 1), so that the state is always admissible and finite.
// For von Mises (C' = C'' = identity, a = 2) the normal of the trial point is
// that of the returned point, and the iteration is the radial return
// (tests/unit/test_material_yld2004.cpp).
//
// The parameter set is used normalised (Yld2004::normalised(): sigma_bar of
// uniaxial tension along RD equals the hardening curve's stress) and checked
// at set-up (Yld2004::validate(): closed and convex, sampled).
//
// State per point: [eps_p, alpha_1 (6), ..., alpha_n (6), RD (3), ND (3)], as
// CombinedPlasticity's Hill'48; the back stresses and axes turn with the spin.
//
// Lanes: material/lanes/yld2004_lanes.hpp (bind_lanes below) repeats update()
// and tangent_ratio() on the element kernel's vector lanes with the same
// arithmetic in the same order (the principal values are one template for
// both, material/principal_values.hpp), so that each lane gives this file's bits
// for any thread count and instruction set (tests/unit/test_yld2004_lanes.cpp).
// A lane whose first return (the whole increment) does not converge is handed
// to update() here, which repeats it and goes on to the sub-increments.  The
// AVX2 and AVX-512 kernels use the lanes; the baseline kernel (SSE2) runs this
// model point by point, where its lanes were slower (fe/element_kernel.hpp).
#include <atomic>
#include <memory>

#include "material/combined_plasticity.hpp"
#include "material/hardening_curve.hpp"
#include "material/material.hpp"
#include "material/yld2004.hpp"

namespace drawbend::material {

class Yld2004Plasticity final : public Material {
 public:
  /// E [MPa], nu, rho [t/mm^3]; curve: flow stress [MPa] of uniaxial tension along RD against eps_p.
  /// Throws std::invalid_argument for a parameter set that validate() refuses.
  Yld2004Plasticity(double youngs_modulus, double poisson_ratio, double density, HardeningCurve curve,
                    KinematicHardening kinematic, const Yld2004& yield);

  int state_size() const override { return ns_; }
  using Material::init_state;
  void init_state(double* state, const SheetAxes& axes) const override;
  using Material::update;
  void update(const double deps[6], const Spin& spin, double sigma[6], double* state) const override;
  double density() const override { return el_.rho; }
  double youngs_modulus() const override { return el_.E; }
  double poisson_ratio() const override { return el_.nu; }
  double plastic_strain(const double* state) const override { return state[0]; }
  bool directional() const override { return true; }
  bool uses_spin() const override { return true; }
  double tangent_ratio(const double* sigma, const double* state) const override;
  std::string describe() const override;

  /// Sum of the back stresses of a state (global axes) [MPa]; current sheet axes of a state.
  void back_stress(const double* state, double alpha[6]) const override;
  bool has_back_stress() const override { return nback_ > 0; }
  bool sheet_axes(const double* state, double rd[3], double nd[3]) const override {
    if (!true) return false;
    const double* a = state + 1 + 6 * nback_;  // [eps_p, alpha_k (6 each), RD (3), ND (3)]
    for (int c = 0; c < 3; ++c) rd[c] = a[c], nd[c] = a[3 + c];
    return true;
  }
  SheetAxes axes(const double* state) const;
  double isotropic_stress(double ep) const;
  /// The normalised parameter set in use, and the factor it was scaled by (1 for a normalised input).
  const Yld2004& yield() const { return yld_; }
  double scaled_by() const { return scale_; }
  /// Plastic updates of this instance since it was built (every thread): all of them, those that needed
  /// sub-increments, and those that fell back to the radial scaling (the return map's health in a run;
  /// relaxed counters, they change no result).  event_counts() gives them as plastic_updates,
  /// split_updates, fallback_updates, which a run writes to its summary.csv.
  struct ReturnCounts {
    long plastic = 0, split = 0, fallback = 0;
  };
  ReturnCounts return_counts() const;
  std::vector<std::pair<std::string, long>> event_counts() const override;

  /// The constants behind update() and tangent_ratio(), for the element kernel's lanes
  /// (material/lanes/yld2004_lanes.hpp and yld2004_function_lanes.hpp repeat both step by step; a change
  /// here must be made there, or test_yld2004_lanes fails).  self: this model, for the lanes it hands
  /// back to update() and for the return counters.
  struct LaneParams {
    double lambda, G, E;    ///< elastic constants [MPa]
    double s0, beta;        ///< initial yield stress [MPa]; split fraction (0: Chaboche or none)
    double C[3], gamma[3];  ///< Chaboche terms: C [MPa], gamma [1]
    int nterms, nback;      ///< Chaboche terms; back stresses in the state
    double a;               ///< the exponent
    bool integral;          ///< a is an integer <= 64 (powers by multiplication)
    double c1[9], c2[9];    ///< the normalised C' and C''
    HardeningCurve::Table curve;
    const Yld2004Plasticity* self;
  };
  LaneParams lane_params() const noexcept;
  void bind_lanes(LaneBinding& b) const override;
  /// Counts `plastic` plastic updates done on the lanes (converged on the whole increment).  Not inline:
  /// the per-instruction-set kernels call it, and must define no code outside their namespaces.
  void count_lane_returns(long plastic) const;

 private:
  // One return from the local trial stress ts and back stresses an (sheet axes, modified in place) at
  // eps_p = ep; adds the plastic multiplier to dl.  False when it did not converge.
  // sb, n_trial: sigma_bar and normal of the trial point ts - sum an.
  bool return_map(double ts[6], double an[][6], double ep, double& dl, double sb, const double n_trial[6]) const;
  double kinematic_rate(const double n[6], const double an[][6], double ep, double dl, double out[][6]) const;

  IsotropicElasticity el_;
  HardeningCurve curve_;
  KinematicHardening kin_;
  Yld2004 yld_;
  double scale_ = 1;
  int nback_;
  int ns_;
  double s0_;
  // The counters, on a cache line of their own (the constants above are read by every thread).
  struct alignas(64) Counters {
    std::atomic<long> plastic{0}, split{0}, fallback{0};
  };
  std::unique_ptr<Counters> counts_ = std::make_unique<Counters>();
};

}  // namespace drawbend::material
