#include "material/j2_isotropic.hpp"

#include <cmath>

#include "core/csv.hpp"
#include "material/lane_binding.hpp"

namespace drawbend::material {

J2Isotropic::J2Isotropic(double youngs_modulus, double poisson_ratio, double density, HardeningCurve curve)
    : el_(youngs_modulus, poisson_ratio, density),
      curve_(std::move(curve)),
      g3_(3.0 * el_.G),
      y0_sq_(curve_.initial_yield() * curve_.initial_yield()) {}

inline void J2Isotropic::update_point(const double d[6], double s[6], double* state) const noexcept {
  // Elastic trial stress.
  const double lt = el_.lambda * (d[XX] + d[YY] + d[ZZ]);
  const double g2 = 2.0 * el_.G;
  const double t0 = s[XX] + lt + g2 * d[XX];
  const double t1 = s[YY] + lt + g2 * d[YY];
  const double t2 = s[ZZ] + lt + g2 * d[ZZ];
  const double t3 = s[XY] + el_.G * d[XY];
  const double t4 = s[YZ] + el_.G * d[YZ];
  const double t5 = s[ZX] + el_.G * d[ZX];
  const double p = (t0 + t1 + t2) * (1.0 / 3.0);
  const double a0 = t0 - p, a1 = t1 - p, a2 = t2 - p;
  const double q2 = 1.5 * (a0 * a0 + a1 * a1 + a2 * a2) + 3.0 * (t3 * t3 + t4 * t4 + t5 * t5);

  const double ep = state[0];
  int k = 0;
  bool elastic = q2 <= y0_sq_;  // below the initial yield stress: no curve lookup
  if (!elastic) {
    k = curve_.segment(ep);
    const double sy = curve_.stress_on(k, ep);
    elastic = q2 <= sy * sy;
  }
  if (elastic) {
    s[XX] = t0; s[YY] = t1; s[ZZ] = t2; s[XY] = t3; s[YZ] = t4; s[ZX] = t5;
    return;
  }

  // Plastic: solve q_tr - 3G (e - ep) = sigma_y(e) segment by segment.
  const double q = std::sqrt(q2);
  double start = ep;                                   // start of the search on segment k
  double r = q - curve_.stress_on(k, ep);              // residual at `start` (> 0)
  double e;
  for (;;) {
    e = start + r / (g3_ + curve_.segment_slope(k));
    const double end = curve_.segment_end(k);          // +inf on the extrapolated segment
    // The last segment ends the search whatever e is: a NaN e (a non-finite
    // strain increment, from loads no step can carry) would otherwise walk
    // k off the table.  The NaN stress then reaches the run's non-finite
    // guard (exit 3), and every finite e gives the same bits as before.
    if (e <= end || std::isinf(end)) break;
    ++k;
    start = end;
    r = q - g3_ * (start - ep) - curve_.segment_stress(k);
  }
  const double f = curve_.stress_on(k, e) / q;         // radial scaling: new q = sigma_y(e)
  s[XX] = p + f * a0; s[YY] = p + f * a1; s[ZZ] = p + f * a2;
  s[XY] = f * t3; s[YZ] = f * t4; s[ZX] = f * t5;
  state[0] = e;
}

// No history with a direction: the spin (already applied to sigma) is not needed.
void J2Isotropic::update(const double deps[6], const Spin&, double sigma[6], double* state) const {
  update_point(deps, sigma, state);
}

void J2Isotropic::update_many(std::size_t count, const double* deps, double* sigma, double* state) const {
  for (std::size_t i = 0; i < count; ++i) update_point(deps + 6 * i, sigma + 6 * i, state + i);
}

double J2Isotropic::tangent_ratio(const double* s, const double* state) const {
  const double ep = state[0];
  const int k = curve_.segment(ep);
  const double sy = curve_.stress_on(k, ep);
  const double p = (s[XX] + s[YY] + s[ZZ]) * (1.0 / 3.0);
  const double a0 = s[XX] - p, a1 = s[YY] - p, a2 = s[ZZ] - p;
  const double q2 = 1.5 * (a0 * a0 + a1 * a1 + a2 * a2) + 3.0 * (s[XY] * s[XY] + s[YZ] * s[YZ] + s[ZX] * s[ZX]);
  // The ratio serves the element's hourglass stabilisation, which needs the
  // state's distance from the yield surface, not the sign of the last increment.
  const double H = curve_.segment_slope(k);
  return yield_proximity_ratio(std::sqrt(q2) / sy, H / (el_.E + H));
}

std::string J2Isotropic::describe() const {
  return "J2 isotropic hardening (E = " + fmt(el_.E) + " MPa, nu = " + fmt(el_.nu) + ", rho = " + fmt(el_.rho) +
         " t/mm^3, " + std::to_string(curve_.size()) + "-point curve, initial yield " +
         fmt(curve_.initial_yield()) + " MPa)";
}

void J2Isotropic::bind_lanes(LaneBinding& b) const {
  b.j2 = true;
  b.j2_params = lane_params();
}

}  // namespace drawbend::material
