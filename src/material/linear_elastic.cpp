#include "material/linear_elastic.hpp"

#include "core/csv.hpp"

namespace drawbend::material {

LinearElastic::LinearElastic(double youngs_modulus, double poisson_ratio, double density)
    : el_(youngs_modulus, poisson_ratio, density) {}

void LinearElastic::update(const double deps[6], const Spin&, double sigma[6], double* /*state*/) const {
  el_.add_elastic(deps, sigma);
}

void LinearElastic::update_many(std::size_t count, const double* deps, double* sigma, double* /*state*/) const {
  for (std::size_t i = 0; i < count; ++i) el_.add_elastic(deps + 6 * i, sigma + 6 * i);
}

std::string LinearElastic::describe() const {
  return "linear elastic (E = " + fmt(el_.E) + " MPa, nu = " + fmt(el_.nu) + ", rho = " + fmt(el_.rho) +
         " t/mm^3)";
}

}  // namespace drawbend::material
