// The material update alone: 4,096 integration points driven through a
// cyclic strain path (uniaxial-like increments of 2e-4, reversed every 50
// steps, so every point yields in both directions) with a small spin, timed
// per point update on one thread.  J2 isotropic is the element loop's model
// today; the others are CombinedPlasticity (material/combined_plasticity.hpp):
// the split form, two Chaboche terms, Hill'48 alone and Hill'48 with Chaboche;
// and Yld2004-18p (material/yld2004_plasticity.hpp, scalar path: no lanes) with
// the set fitted to the ESAFORM 2021 AA6016-T4 tests (Chapter v1), a = 8,
// alone and with two Chaboche terms.
// Material constants: AA5754-O-like (E = 70 GPa, nu = 0.33, yield 100 MPa).
#include "bench_material.hpp"

#include <chrono>
#include <iostream>
#include <memory>
#include <vector>

#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"
#include "material/yld2004_plasticity.hpp"

using namespace drawbend;

namespace {
double ns_per_update(const material::Material& m, int points, int steps) {
  const int ns = m.state_size();
  std::vector<double> sig(6 * points, 0.0), st(static_cast<std::size_t>(ns) * points, 0.0);
  for (int p = 0; p < points; ++p) m.init_state(&st[static_cast<std::size_t>(p) * ns]);
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) {
    const double s = ((k / 50) % 2 == 0) ? 1.0 : -1.0;
    for (int p = 0; p < points; ++p) {
      const double f = 1.0 + 0.001 * (p % 17);  // points differ a little
      const double d[6] = {2e-4 * s * f, -1e-4 * s * f, -1e-4 * s * f, 3e-5 * s, 0.0, 1e-5 * s};
      const material::Spin w{10.0 * f, 0.0, -5.0, 1e-5};
      m.update(d, w, &sig[6 * p], &st[static_cast<std::size_t>(p) * ns]);
    }
  }
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return sec / (static_cast<double>(points) * steps) * 1e9;
}
}  // namespace

void bench_material(CsvWriter& w, bool quick) {
  const double E = 70000, nu = 0.33, rho = 2.7e-9;
  auto curve = [] { return material::HardeningCurve::voce(100.0, 180.0, 14.0); };
  const auto hill = material::Hill48::from_r_values(0.65, 0.65, 0.72);
  material::Yld2004 yld;  // fitted to data/materials/aa6016_t4_esaform2021.csv by drawbend calibrate (c44 = c55 = 1)
  yld.a = 8;
  yld.c1 = {1.0059518, 1.1865517, 0.0087202487, 0.75613553, 1.1445682, 0.84840891, 1, 1, 0.17885443};
  yld.c2 = {0.87834346, 1.1811921, 1.0479014, 1.2886127, 0.036486783, 1.5701502, 1, 1, 1.5886608};
  material::KinematicHardening split, chab, none;
  split.beta = 0.3;
  chab.chaboche = {{6000.0, 60.0}, {800.0, 5.0}};
  struct M {
    std::string name;
    std::shared_ptr<const material::Material> m;
  };
  const std::vector<M> models = {
      {"j2_isotropic", std::make_shared<material::J2Isotropic>(E, nu, rho, curve())},
      {"j2_combined_split", std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve(), split)},
      {"j2_combined_chaboche2", std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve(), chab)},
      {"hill48_isotropic", std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve(), none, hill)},
      {"hill48_chaboche2", std::make_shared<material::CombinedPlasticity>(E, nu, rho, curve(), chab, hill)},
      {"yld2004_isotropic", std::make_shared<material::Yld2004Plasticity>(E, nu, rho, curve(), none, yld)},
      {"yld2004_chaboche2", std::make_shared<material::Yld2004Plasticity>(E, nu, rho, curve(), chab, yld)}};
  const int points = 4096, steps = quick ? 100 : 400;
  for (const auto& [name, m] : models) {
    const double ns = ns_per_update(*m, points, steps);
    std::cout << "material " << name << ": " << fmt(ns, 4) << " ns per integration-point update (1 thread)\n";
    w.row({"material_" + name, std::to_string(points), "1", fmt(ns, 5)});
  }
}
