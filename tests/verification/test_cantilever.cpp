// Elastic cantilever with 4 elements through the thickness.
// Closed-form answer (Euler-Bernoulli, plus Timoshenko shear): a cantilever of
// length L = 10 mm, thickness t = 1.04 mm, width w = 1 mm, clamped at x = 0 and
// loaded by P at the tip deflects by
//   delta = P L^3 / (3 E I) + P L / (kappa G A),  I = w t^3 / 12, kappa = 5/6.
// Checked within 3 % for element lengths 0.25 mm (the draw-bend meshes' bending
// zone: 100 elements in 25 mm), 0.5 mm and 1 mm (the straight ends of the
// strips), solved statically by dynamic relaxation.  The hourglass
// energy is reported and must stay below 10 % of the internal energy.
#define BOOST_TEST_MODULE cantilever
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fixtures.hpp"

using namespace verify;

static void cantilever(double element_length) {
  const double L = 10, t = 1.04, w = 1.0, P = 0.1;
  fe::Model m = block(L, w, t, static_cast<int>(std::lround(L / element_length)), 1, 4, elastic());
  m.mass_scaling = 100;
  const double I = w * t * t * t / 12, G = kE / (2 * (1 + kNu));
  const double delta = P * L * L * L / (3 * kE * I) + P * L / (5.0 / 6.0 * G * w * t);
  // First bending frequency (scaled mass) for critical damping.
  const double rhoA = kRho * m.mass_scaling * w * t;
  const double w1 = 1.875 * 1.875 * std::sqrt(kE * I / (rhoA * L * L * L * L));
  fe::Step s;
  s.duration = 8 * 2 * M_PI / w1;
  s.damping = 2 * w1;
  s.fixed = {{"xmin", {true, true, true}}};
  s.forces.push_back({"xmax", {0, 0, -1}, fe::History::constant(P)});
  m.steps.push_back(s);
  fe::Solver solver(m);
  solver.run();
  double uz = 0;
  const auto& tip = m.mesh.node_set("xmax");
  for (int i : tip) uz += solver.z()[i] - m.mesh.z[i];
  uz /= tip.size();
  const auto& e = solver.energies();
  BOOST_TEST_MESSAGE("element length " << element_length << " mm: tip deflection " << -uz << " mm, theory " << delta
                                       << " mm, error " << 100 * (-uz - delta) / delta << " %, hourglass/internal "
                                       << 100 * e.hourglass / e.internal << " %, KE/IE " << e.kinetic / e.internal);
  BOOST_TEST(std::abs(-uz - delta) / delta < 0.03);
  BOOST_TEST(e.hourglass / e.internal < 0.10);
  BOOST_TEST(e.kinetic / e.internal < 1e-3);  // static: the relaxation converged
}

BOOST_AUTO_TEST_CASE(elements_0p25_mm) { cantilever(0.25); }
BOOST_AUTO_TEST_CASE(elements_0p5_mm) { cantilever(0.5); }
BOOST_AUTO_TEST_CASE(elements_1_mm) { cantilever(1.0); }
