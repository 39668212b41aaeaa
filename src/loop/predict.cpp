// The loop's public predictions (model.hpp) from predict_row (predict_row.hpp).
#include <cmath>

#include "analysis/friction_surface.hpp"
#include "analysis/pressure_ratio.hpp"
#include "loop/predict_row.hpp"

namespace drawbend::loop {

double ellipse(double a, double b, double phi) { return ellipse_cs(a, b, std::cos(phi), std::sin(phi)); }

double ellipse_cs(double a, double b, double c, double s) { return analysis::ellipse_mu(a, b, c, s); }

double map_pressure(const Row& r, double FB, double Ff, double FB_ref) {
  return analysis::pressure_at_tension(r.pw_ref, r.fback, FB, Ff, r.fref, FB_ref);
}

double predict(const Design& d, const Fit& f, int i) {
  const detail::Layout L = detail::layout(d, f.spec);
  return detail::predict_row(d, f, L, f.theta, i, nullptr);
}

double predict_mu(const Design& d, const Fit& f, int i) {
  const detail::Layout L = detail::layout(d, f.spec);
  double mu = std::nan("");
  detail::predict_row(d, f, L, f.theta, i, &mu);
  return mu;
}

double predict_mu_at(const Design& d, const Fit& f, int i, double phi_rad, double* p_out) {
  const detail::Layout L = detail::layout(d, f.spec);
  Row r = d.rows[i];
  set_direction(r, phi_rad);
  r.dir = -1;  // RD and TD carry no direction-level factor
  double mu = std::nan("");
  detail::predict_row(d, f, L, f.theta, i, &mu, &r, p_out);
  return mu;
}

}  // namespace drawbend::loop
