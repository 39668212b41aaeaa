#pragma once
// Shared set-up of the verification problems: aluminium-like materials and
// small structured models.  Units: mm, N, MPa, s, t/mm^3.
#include <memory>

#include "fe/model.hpp"
#include "fe/solver.hpp"
#include "material/j2_isotropic.hpp"
#include "material/linear_elastic.hpp"

namespace verify {

using namespace drawbend;

inline constexpr double kE = 70000.0, kNu = 0.33, kRho = 2.7e-9;

inline std::shared_ptr<const material::Material> elastic() {
  return std::make_shared<material::LinearElastic>(kE, kNu, kRho);
}
/// J2 with linear hardening: sigma_y = y0 + H eps_p.
inline std::shared_ptr<const material::Material> j2_linear(double y0, double H) {
  return std::make_shared<material::J2Isotropic>(kE, kNu, kRho, material::HardeningCurve({0.0, 1.0}, {y0, y0 + H}));
}

inline fe::Model block(double lx, double ly, double lz, int nx, int ny, int nz,
                       std::shared_ptr<const material::Material> mat) {
  fe::Model m;
  m.mesh = fe::structured_block(fe::uniform_lines(0, lx, nx), fe::uniform_lines(0, ly, ny), fe::uniform_lines(0, lz, nz));
  m.material = std::move(mat);
  return m;
}

}  // namespace verify
