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

// A force-driven tool with a stop (a blank holder pressed onto spacers, deck
// key `stop`): pushed by a constant force F = 10 N along +z with nothing in
// contact, a tool of m = 1e-7 t would travel F t^2 / (2 m) = 2 mm in
// t = 2e-4 s; with stop = 0.2 mm it ends at the stop exactly (to rounding)
// and at rest.  Pushed the other way it leaves the stop freely: after the same
// time it is at -(F t^2 / (2 m)) within the first-order error of the speed
// ramp of one cycle (1 %).
BOOST_AUTO_TEST_CASE(force_driven_tool_rests_on_its_stop) {
  for (const double sign : {1.0, -1.0}) {
    fe::Model m = block(2, 2, 0.5, 4, 4, 1, elastic());
    m.mass_scaling = 100;
    contact::Surface far;
    far.origin = {0, 0, 5.0};
    far.axis = {0, 0, -1};
    m.add_rigid_contact("holder", far, "zmax");
    fe::Tool& holder = m.tools.back();
    holder.drive = fe::Tool::Drive::force;
    holder.direction = {0, 0, 1};
    holder.force = fe::History::constant(10.0 * sign);
    holder.mass = 1e-7;
    holder.stop = 0.2;
    m.steps.push_back(fe::Step{});
    m.steps.back().duration = 2e-4;
    fe::Solver solver(m);
    solver.run();
    const double z = solver.tool_offset("holder")[2];
    if (sign > 0) {
      BOOST_TEST(z == 0.2, boost::test_tools::tolerance(1e-12));
    } else {
      BOOST_TEST(z == -2.0, boost::test_tools::tolerance(0.01));
    }
  }
}
