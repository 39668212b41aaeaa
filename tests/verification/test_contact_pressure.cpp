// Contact pressure under a uniformly loaded flat block (thesis Sec. 3.3.1).
// Closed-form answer: a 2 x 2 x 0.5 mm block loaded by a uniform traction of
// 10 MPa (40 N) on its top face and pressed frictionlessly onto a rigid plane
// carries a uniform contact pressure p = F / A = 10 MPa at every bottom node,
// edges and corners included, when pressure = nodal normal force / tributary
// area and the penalty stiffness scales with the node's own area.  Checked
// within 2 % at every node, statically (dynamic relaxation).
#define BOOST_TEST_MODULE contact_pressure
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fixtures.hpp"

using namespace verify;

BOOST_AUTO_TEST_CASE(uniform_pressure_edges_included) {
  fe::Model m = block(2, 2, 0.5, 8, 8, 2, elastic());
  m.mass_scaling = 100;
  m.add_rigid_contact("floor", {}, "zmin");  // frictionless plane z = 0
  fe::Step s;
  s.duration = 4e-3;
  s.damping = 3e4;
  // A traction is an area-weighted load; the top face's nodal masses are
  // proportional to their tributary volumes, i.e. to area for a uniform layer.
  s.forces.push_back({"zmax", {0, 0, -1}, {{0.0, 1e-3}, {0.0, 40.0}}});
  m.steps.push_back(s);
  fe::Solver solver(m);
  solver.run();
  double worst = 0;
  for (const auto& c : solver.contact_nodes(0)) worst = std::max(worst, std::abs(c.pressure - 10.0) / 10.0);
  BOOST_TEST_MESSAGE("largest nodal pressure deviation " << 100 * worst << " %, max penetration "
                                                         << solver.max_penetration() << " mm");
  BOOST_TEST(worst < 0.02);
}
