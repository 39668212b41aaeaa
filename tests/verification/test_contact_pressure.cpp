// Contact pressure under a uniformly loaded flat block (thesis Sec. 3.3.1).
// Closed-form answer: a 2 x 2 x 0.5 mm block loaded by a uniform traction of
// 10 MPa (40 N) on its top face and pressed frictionlessly onto a rigid plane
// carries a uniform contact pressure p = F / A = 10 MPa at every bottom node,
// edges and corners included, when pressure = nodal normal force / tributary
// area and the penalty stiffness scales with the node's own area.  Checked
// within 2 % at every node, statically (dynamic relaxation).
// Second case, a force-driven tool (a blank holder under constant force): a
// rigid plate pushed down by 40 N onto the same block on the fixed floor gives
// 10 MPa on both faces, and the plate's contact force balances the 40 N.
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

BOOST_AUTO_TEST_CASE(force_driven_holder) {
  fe::Model m = block(2, 2, 0.5, 8, 8, 2, elastic());
  m.mass_scaling = 100;
  m.add_rigid_contact("floor", {}, "zmin");
  contact::Surface top;
  top.origin = {0, 0, 0.5};
  top.axis = {0, 0, -1};  // free side below the plate
  auto& cp = m.add_rigid_contact("holder", top, "zmax");
  (void)cp;
  fe::Tool& holder = m.tools.back();
  holder.drive = fe::Tool::Drive::force;
  holder.direction = {0, 0, -1};
  holder.force = {{0.0, 1e-3}, {0.0, 40.0}};
  holder.mass = 1e-5;  // [t]; a light plate, damped by the step
  fe::Step s;
  s.duration = 4e-3;
  s.damping = 3e4;
  m.steps.push_back(s);
  fe::Solver solver(m);
  solver.run();
  double worst = 0;
  for (int p = 0; p < 2; ++p)
    for (const auto& c : solver.contact_nodes(p)) worst = std::max(worst, std::abs(c.pressure - 10.0) / 10.0);
  const double Fz = solver.tool_force("holder")[2];
  BOOST_TEST_MESSAGE("holder offset " << solver.tool_offset("holder")[2]);
  BOOST_TEST_MESSAGE("force-driven holder: largest pressure deviation " << 100 * worst << " %, holder contact force "
                                                                        << Fz << " N");
  BOOST_TEST(worst < 0.02);
  BOOST_TEST(std::abs(Fz - 40.0) / 40.0 < 0.01);
}

// A force-driven tool too light for the time step is refused before it can
// bounce off: omega = sqrt(k/m) with k = sum alpha K A / L = 0.1 * 68627 *
// 4 / 0.25 = 1.1e5 N/mm; a 1e-12 t plate has omega dt >> 2.
BOOST_AUTO_TEST_CASE(too_light_tool_is_refused) {
  fe::Model m = block(2, 2, 0.5, 8, 8, 2, elastic());
  m.mass_scaling = 100;
  contact::Surface top;
  top.origin = {0, 0, 0.5};
  top.axis = {0, 0, -1};
  m.add_rigid_contact("holder", top, "zmax");
  fe::Tool& holder = m.tools.back();
  holder.drive = fe::Tool::Drive::force;
  holder.direction = {0, 0, -1};
  holder.force = fe::History::constant(40.0);
  holder.mass = 1e-12;
  fe::Step s;
  s.duration = 1e-4;
  m.steps.push_back(s);
  fe::Solver solver(m);
  try {
    solver.run();
    BOOST_FAIL("expected the unstable tool to be refused");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST(std::string(e.what()).find("tool 'holder': mass") != std::string::npos);
  }
}
