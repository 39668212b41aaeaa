// A force-driven tool too light for the time step is refused.
// The contact-pressure problems themselves (a uniformly loaded block on a
// rigid plane, and the same block under a force-driven holder: 10 MPa at every
// node, the holder's force balancing its 40 N) are decks run by `verify`:
// spec.toml entries contact_pressure_uniform and contact_pressure_holder.*.
#define BOOST_TEST_MODULE contact_pressure
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fixtures.hpp"

using namespace verify;

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
