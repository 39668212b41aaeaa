#pragma once
// Isotropic Hooke's law: sigma += C : deps.  No history (state_size() == 0).
#include "material/material.hpp"

namespace drawbend::material {

class LinearElastic final : public Material {
 public:
  /// E in MPa, nu dimensionless, rho in t/mm^3 (aluminium: 70000, 0.33, 2.7e-9).
  LinearElastic(double youngs_modulus, double poisson_ratio, double density);

  int state_size() const override { return 0; }
  using Material::update;
  void update(const double deps[6], const Spin& spin, double sigma[6], double* state) const override;
  void update_many(std::size_t count, const double* deps, double* sigma, double* state) const override;
  double density() const override { return el_.rho; }
  double youngs_modulus() const override { return el_.E; }
  double poisson_ratio() const override { return el_.nu; }
  std::string describe() const override;
  const IsotropicElasticity& elasticity() const { return el_; }

 private:
  IsotropicElasticity el_;
};

}  // namespace drawbend::material
