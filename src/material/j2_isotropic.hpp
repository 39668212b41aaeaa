#pragma once
// Von Mises (J2) plasticity with isotropic hardening, associative flow, and an
// exact radial return for a piecewise-linear hardening curve.
//
// State: state[0] = equivalent plastic strain eps_p (state_size() == 1).
//
// Return mapping (backward Euler, exact for the multilinear curve):
//   trial   sigma_tr = sigma_n + C : deps,  q_tr = von Mises of sigma_tr;
//   elastic if q_tr <= sigma_y(eps_p,n);
//   else find d(eps_p) > 0 with  q_tr - 3 G d(eps_p) = sigma_y(eps_p,n + d(eps_p)).
//   Both sides are linear on one curve segment, so the root is found segment
//   by segment: solve on the current segment; if it lies past the segment's
//   end, move to the next segment and solve again.  No iteration tolerance,
//   no fixed Newton count: the result satisfies the consistency condition to
//   round-off, however many segments one step crosses.  The deviator is then
//   scaled radially: s = s_tr * sigma_y / q_tr.
#include "material/hardening_curve.hpp"
#include "material/material.hpp"

namespace drawbend::material {

class J2Isotropic final : public Material {
 public:
  /// E in MPa, nu dimensionless, rho in t/mm^3, curve = flow stress vs eps_p.
  J2Isotropic(double youngs_modulus, double poisson_ratio, double density, HardeningCurve curve);

  int state_size() const override { return 1; }
  using Material::update;
  void update(const double deps[6], const Spin& spin, double sigma[6], double* state) const override;
  void update_many(std::size_t count, const double* deps, double* sigma, double* state) const override;
  double density() const override { return el_.rho; }
  double youngs_modulus() const override { return el_.E; }
  double poisson_ratio() const override { return el_.nu; }
  double plastic_strain(const double* state) const override { return state[0]; }
  /// H/(E + H) when the von Mises stress is on the yield surface (relative 1e-9), else 1.
  double tangent_ratio(const double* sigma, const double* state) const override;
  std::string describe() const override;

  const HardeningCurve& curve() const { return curve_; }
  /// The constants of update_point() and tangent_ratio() as plain numbers, for
  /// the element kernel's lane version of both (material/lanes/j2_lanes.hpp), which
  /// gives their bits.  Valid while this material lives.
  /// ratio_one_q2: a q^2 at or below which tangent_ratio() is exactly 1 for
  /// any ep >= 0, so the lanes need no curve look-up, square root or division
  /// for it.  Why: the curve is non-decreasing from ep = 0 (checked when it is
  /// built), so sigma_y(ep) >= sigma_y(0) = y0, and the rounding of
  /// stress_on() keeps that (a sum of non-negative terms); with
  /// q^2 <= 0.81 y0^2 (1 - 1e-9), f = sqrt(q2) / sigma_y <= 0.9 (1 - 4.9e-10)
  /// after the square root's and the division's roundings (each 1.1e-16), and
  /// yield_proximity_ratio(f <= 0.90) is 1.
  struct LaneParams {
    double lambda, G, g3, y0_sq, E, ratio_one_q2;
    HardeningCurve::Table curve;
  };
  LaneParams lane_params() const noexcept {
    return {el_.lambda, el_.G, g3_, y0_sq_, el_.E, 0.81 * y0_sq_ * (1.0 - 1e-9), curve_.table()};
  }
  const IsotropicElasticity& elasticity() const { return el_; }
  void bind_lanes(LaneBinding& b) const override;

 private:
  inline void update_point(const double deps[6], double sigma[6], double* state) const noexcept;

  IsotropicElasticity el_;
  HardeningCurve curve_;
  double g3_;        // 3 G
  double y0_sq_;     // initial yield stress squared: below it, no curve lookup is needed
};

}  // namespace drawbend::material
