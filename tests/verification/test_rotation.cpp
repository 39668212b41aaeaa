// Rigid rotation of a pre-stressed element (objectivity of the stress update).
// Closed-form answer: an element carrying sigma_0 = (xx, yy, zz, xy, yz, zx) =
// (100, 20, -30, 15, 0, 0) MPa and rotated rigidly by 90 deg about z carries
// R sigma_0 R^T = (20, 100, -30, -15, 0, 0) MPa: the stress turns with the
// body and its invariants do not change.  Checked within 0.5 % of |sigma_0|.
#define BOOST_TEST_MODULE rotation
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fixtures.hpp"

using namespace verify;

BOOST_AUTO_TEST_CASE(stress_turns_with_the_body) {
  fe::Model m = block(1, 1, 1, 1, 1, 1, elastic());
  fe::Step s;
  const double T = 1e-3;
  s.duration = T;
  s.rotations.push_back({"all", {0.5, 0.5, 0.5}, {0, 0, 1}, fe::History::constant(M_PI / 2 / T)});
  m.steps.push_back(s);
  fe::Solver solver(m);
  const double s0[6] = {100, 20, -30, 15, 0, 0};
  solver.set_stress(0, s0);
  solver.run();
  const double expect[6] = {20, 100, -30, -15, 0, 0};
  const double scale = 100.0;
  for (int k = 0; k < 6; ++k) BOOST_TEST(std::abs(solver.stress()[k] - expect[k]) < 0.005 * scale);
  // Node 1 (1, 0, 0) ends near (1, 1, 0): the rotation really was 90 deg.
  BOOST_TEST(std::abs(solver.x()[1] - 1.0) < 1e-3);
  BOOST_TEST(std::abs(solver.y()[1] - 1.0) < 1e-3);
}
