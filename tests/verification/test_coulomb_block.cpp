// Coulomb friction: a block pressed on a rigid plane and slid.
// Closed-form answer: a 1 x 1 x 1 mm block pressed by 10 N (10 MPa) onto a rigid
// plane and slid steadily by its top face at 10 mm/s transmits a friction force
// of magnitude mu F_N = 1.0 N (mu = 0.1), opposite to the sliding direction, for
// sliding along x and along 45 deg.  Checked: |F_t|/F_n within 1 % of mu, and
// the friction force direction within 1 deg of the sliding direction.
#define BOOST_TEST_MODULE coulomb_block
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fixtures.hpp"

using namespace verify;

static void slide(double angle_deg) {
  fe::Model m = block(1, 1, 1, 4, 4, 4, j2_linear(100, 500));
  m.mass_scaling = 100;
  m.add_rigid_contact("floor", {}, "zmin", std::make_shared<friction::Coulomb>(0.1));  // plane z = 0, normal +z
  const double a = angle_deg * M_PI / 180;
  fe::Step press;
  press.duration = 2e-3;
  press.damping = 2e4;
  press.forces.push_back({"zmax", {0, 0, -1}, {{0.0, 1e-3}, {0.0, 10.0}}});
  fe::Step go;
  go.duration = 4e-3;
  go.forces.push_back({"zmax", {0, 0, -1}, fe::History::constant(10.0)});
  go.velocities.push_back({"zmax", {std::cos(a), std::sin(a), 0}, {{0.0, 5e-4}, {0.0, 10.0}}});
  m.steps = {press, go};
  fe::Solver s(m);
  s.run();
  const auto F = s.tool_force("floor");  // force of the block on the floor
  const double ft = std::hypot(F[0], F[1]), fn = std::abs(F[2]);
  const double dir = std::atan2(F[1], F[0]) * 180 / M_PI;
  BOOST_TEST_MESSAGE(angle_deg << " deg: F_t/F_n = " << ft / fn << ", direction " << dir << " deg");
  BOOST_TEST(std::abs(ft / fn - 0.1) < 0.001);
  BOOST_TEST(std::abs(dir - angle_deg) < 1.0);
}

BOOST_AUTO_TEST_CASE(along_x) { slide(0); }
BOOST_AUTO_TEST_CASE(along_45_deg) { slide(45); }
