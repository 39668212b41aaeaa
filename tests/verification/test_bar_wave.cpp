// Undamped elastic bar: energy conservation and wave speed.
// Closed-form answer: a 1-D (laterally constrained) bar of length L = 50 mm
// moving at v0 = -1000 mm/s hits a rigid support at x = 0.  Plane-strain
// elasticity gives the dilatational wave speed c = sqrt((lambda + 2 mu)/rho);
// the support reaction is the impedance force rho c v0 A, and it vanishes when
// the reflected wave returns from the free end, at t = 2L/c.  Total energy
// KE + IE + HG stays equal to the initial kinetic energy (the support does no
// work).  Checked: energy within 0.5 %, c from the reaction within 1 % and from
// the unloading time within 2 %.
#define BOOST_TEST_MODULE bar_wave
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fixtures.hpp"

using namespace verify;

BOOST_AUTO_TEST_CASE(energy_and_wave_speed) {
  const double L = 50, v0 = -1000;
  fe::Model m = block(L, 1, 1, 100, 1, 1, elastic());
  m.dt_safety = 0.5;
  fe::Step s;
  const double lam = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double c = std::sqrt((lam + 2 * mu) / kRho);
  s.duration = 2.6 * L / c;
  s.fixed = {{"all", {false, true, true}}, {"xmin", {true, false, false}}};
  m.steps.push_back(s);
  fe::Solver solver(m);
  double ke0 = 0;
  for (int i = 0; i < m.mesh.num_nodes(); ++i)
    if (m.mesh.x[i] > 0) {
      solver.set_velocity(i, {v0, 0, 0});
      ke0 += 0.5 * solver.mass()[i] * v0 * v0;
    }
  double plateau = 0, n = 0, t_drop = -1, max_err = 0;
  solver.run([&](const fe::Progress& p) {
    const double R = solver.reaction("xmin")[0];
    if (p.time > 0.5 * L / c && p.time < 1.5 * L / c) {
      plateau += R;
      ++n;
    }
    if (p.time > 1.5 * L / c && t_drop < 0 && std::abs(R) < 0.5 * std::abs(plateau / n)) t_drop = p.time;
    const auto& e = solver.energies();
    max_err = std::max(max_err, std::abs(e.kinetic + e.internal + e.hourglass - ke0) / ke0);
  });
  plateau /= n;
  const double c_force = std::abs(plateau) / (kRho * std::abs(v0) * 1.0);
  BOOST_TEST_MESSAGE("c exact " << c << ", from reaction " << c_force << ", from 2L/t_drop " << 2 * L / t_drop
                                << ", max energy error " << max_err);
  BOOST_TEST(std::abs(c_force - c) / c < 0.01);
  BOOST_TEST(std::abs(2 * L / t_drop - c) / c < 0.02);
  BOOST_TEST(max_err < 0.005);
}
