#include "material/material.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/csv.hpp"

namespace drawbend::material {

void Material::init_state(double* state, const SheetAxes&) const {
  for (int i = 0; i < state_size(); ++i) state[i] = 0.0;
}

void Material::update_many(std::size_t count, const double* deps, double* sigma, double* state) const {
  const auto ns = static_cast<std::size_t>(state_size());
  for (std::size_t i = 0; i < count; ++i) update(deps + 6 * i, sigma + 6 * i, state + ns * i);
}

double Material::bulk_modulus() const { return youngs_modulus() / (3.0 * (1.0 - 2.0 * poisson_ratio())); }
double Material::shear_modulus() const { return youngs_modulus() / (2.0 * (1.0 + poisson_ratio())); }
double Material::wave_speed() const {
  return std::sqrt((bulk_modulus() + 4.0 * shear_modulus() / 3.0) / density());
}

std::string Material::describe() const {
  return "material (E = " + fmt(youngs_modulus()) + " MPa, nu = " + fmt(poisson_ratio()) +
         ", rho = " + fmt(density()) + " t/mm^3)";
}

IsotropicElasticity::IsotropicElasticity(double youngs_modulus, double poisson_ratio, double density)
    : E(youngs_modulus), nu(poisson_ratio), rho(density) {
  if (!(E > 0.0) || !std::isfinite(E))
    throw std::invalid_argument("material: Young's modulus must be positive and finite, got " + std::to_string(E));
  if (!(nu > -1.0 && nu < 0.5))
    throw std::invalid_argument("material: Poisson's ratio must lie in (-1, 0.5), got " + std::to_string(nu));
  if (!(rho > 0.0) || !std::isfinite(rho))
    throw std::invalid_argument("material: density must be positive and finite (t/mm^3), got " +
                                std::to_string(rho));
  G = E / (2.0 * (1.0 + nu));
  K = E / (3.0 * (1.0 - 2.0 * nu));
  lambda = K - 2.0 * G / 3.0;
}

double Material::tangent_ratio(const double* /*sigma*/, const double* /*state*/) const { return 1.0; }

void Material::back_stress(const double* /*state*/, double alpha[6]) const {
  for (int c = 0; c < 6; ++c) alpha[c] = 0.0;
}

void Material::bind_lanes(LaneBinding& /*b*/) const {}

std::vector<std::pair<std::string, long>> Material::event_counts() const { return {}; }

double von_mises(const double s[6]) noexcept {
  const double p = (s[XX] + s[YY] + s[ZZ]) / 3.0;
  const double a = s[XX] - p, b = s[YY] - p, c = s[ZZ] - p;
  return std::sqrt(1.5 * (a * a + b * b + c * c) + 3.0 * (s[XY] * s[XY] + s[YZ] * s[YZ] + s[ZX] * s[ZX]));
}

}  // namespace drawbend::material
