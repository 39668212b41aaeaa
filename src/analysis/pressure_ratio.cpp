#include "analysis/pressure_ratio.hpp"

#include <stdexcept>

namespace drawbend::analysis {

double pressure_ratio(double Fx_fixed, double Fy_fixed, double Fx_rot, double Fy_rot) {
  const double den = Fx_rot + Fy_rot;
  if (!(den > 0.0)) throw std::domain_error("pressure_ratio: rotating-pin force sum must be positive");
  return (Fx_fixed + Fy_fixed) / den;
}

double pressure_ratio_from_fits(double Fback, double Ffric, double Fbend) {
  return pressure_ratio(Fback, Fback + Fbend + Ffric, Fback, Fback + Fbend);
}

double implied_rotating_bending(double Fback, double Ffric, double Fbend_num, double c) {
  if (!(c > 0.0)) throw std::domain_error("implied_rotating_bending: c must be positive");
  return (2.0 * Fback + Fbend_num + Ffric) / c - 2.0 * Fback;
}

}  // namespace drawbend::analysis
