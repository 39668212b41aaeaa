#include "analysis/rope.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace drawbend::analysis {

namespace {
void require_positive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::domain_error(std::string(what) + " must be positive and finite, got " + std::to_string(v));
}
}  // namespace

double basis_width(double full_width_mm, ForceBasis basis) {
  require_positive(full_width_mm, "strip width");
  return basis == ForceBasis::half_model ? 0.5 * full_width_mm : full_width_mm;
}

double swift_bending_force(double sigma_y, double t, double full_width, double r, double theta,
                           ForceBasis basis) {
  require_positive(sigma_y, "yield stress");
  require_positive(t, "thickness");
  require_positive(r, "pin radius");
  if (!(theta > 0.0 && theta < M_PI)) throw std::domain_error("wrap angle must lie in (0, pi)");
  const double w = basis_width(full_width, basis);
  return sigma_y * t * t * w / (2.0 * r) * std::tan(theta / 2.0);
}

double average_pressure(double Fx, double Fy, double r, double full_width, ForceBasis basis) {
  require_positive(r, "pin radius");
  return (Fx + Fy) / (2.0 * r * basis_width(full_width, basis));
}

double mu_rope(double Fx, double Fy, double FB, double theta) {
  require_positive(Fx, "back tension F_x");
  require_positive(theta, "wrap angle");
  const double ratio = (Fy - FB) / Fx;
  if (!(ratio > 0.0)) throw std::domain_error("Eq. (2.3): (F_y - F_B)/F_x must be positive");
  return std::log(ratio) / theta;
}

double mu_from_friction(double Ffric, double Fback, double theta) {
  require_positive(Fback, "back tension");
  return mu_rope(Fback, Fback + Ffric, 0.0, theta);
}

}  // namespace drawbend::analysis
