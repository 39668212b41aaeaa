// A force-driven tool too light for the time step is refused.
// The contact-pressure problems themselves (a uniformly loaded block on a
// rigid plane, and the same block under a force-driven holder: 10 MPa at every
// node, the holder's force balancing its 40 N) are decks run by `verify`:
// spec.toml entries contact_pressure_uniform and contact_pressure_holder.*.
#define BOOST_TEST_MODULE contact_pressure
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fe/contact_springs.hpp"
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

// The one stiffness rule (fe/contact_springs.hpp) in closed form: on a flat
// block of 8 x 8 x 2 elements, 2 x 2 x 0.5 mm, every contact node's tributary
// areas sum to the face area A = 4 mm^2 and every element below the face is
// L = 0.25 mm high, so k = alpha K A / L = 16 alpha K (K the bulk modulus).
// A tool sized by tool_mass_half_omega_dt sits at omega dt = 0.5 exactly and
// the solver's guard (limit omega dt <= 2 x safety) lets it run.
BOOST_AUTO_TEST_CASE(tool_contact_stiffness_closed_form) {
  fe::Model m = block(2, 2, 0.5, 8, 8, 2, elastic());
  contact::Surface top;
  top.origin = {0, 0, 0.5};
  top.axis = {0, 0, -1};
  m.add_rigid_contact("holder", top, "zmax");
  const double alpha = m.contacts.back().penalty, K = m.material->bulk_modulus();
  const double k = fe::tool_contact_stiffness(m, "holder");
  BOOST_TEST(k == 16 * alpha * K, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(fe::tool_contact_stiffness(m, "nothing") == 0.0);
  const double dt = 1e-6, mass = fe::tool_mass_half_omega_dt(k, dt);
  BOOST_TEST(std::sqrt(k / mass) * dt == 0.5, boost::test_tools::tolerance(1e-12));

  fe::Tool& holder = m.tools.back();
  holder.drive = fe::Tool::Drive::force;
  holder.direction = {0, 0, -1};
  holder.force = fe::History::constant(40.0);
  holder.mass = 1.0;  // provisional, for the probe
  m.mass_scaling = 100;
  m.steps.push_back(fe::Step{});
  m.steps.back().duration = 1.0;
  const double dt_run = fe::Solver(m).stable_dt();  // the solver's own time step, then the tool sized on it
  holder.mass = fe::tool_mass_half_omega_dt(k, dt_run);
  m.steps.back().duration = 20 * dt_run;
  fe::Solver solver(m);
  BOOST_CHECK_NO_THROW(solver.run());
}
