// The case builders of Chapters 3 and 6 (src/sim/block_case, strip_draw_case)
// and the shared rules of src/sim/fe_options.
// Closed-form answers:
//  - Quick tier: element length 1 mm, 2 across, 4 through, mass scaling 1e4;
//    mass scaling for 50 mm/s from 1e4 at 100 mm/s: 1e4 (100/50)^2 = 4e4 exactly.
//  - Block, 40 MPa on a 2 mm cube: normal load 40 x 2 x 2 = 160 N (ramped in
//    the press step, held in the slide); at 70 mm/s and 30 deg from RD the
//    node speeds are 70 cos 30 deg = 60.62 mm/s along x and 35 mm/s along y.
//  - Strip draw, default (case 1 of Table 3.2: 10 MPa, 8 mm/s on a 4 x 2 mm
//    section): die force 10 x 8 = 80 N; time step 2.5e-6 s (4 <= v <= 40);
//    draw step 0.01 + max(0.4 / 8, 0.02) = 0.06 s; die mass 4 k dt^2 with
//    k = 0.1 K A / h, K = E / (3 (1 - 2 nu)) = 70000 / 1.02 MPa, A = 8 mm^2,
//    h = 1.04 / 4 = 0.26 mm: 5.27903e-6 t.
//  - The time-step rule: 1e-5 s below 4 mm/s, 2.5e-6 s from 4 to 40, 5e-7 above.
//  - The default block deck builds the model of data/cases/block_surface.toml
//    (the same mesh, numerics, steps and loads), so the two cannot drift apart.
//  - Bad values throw InputError naming the field and its unit.
//  - Draw-bend deck (src/sim/drawbend_case) with plane_strain_width: the free
//    edge (set ymax) is held in y, and only in y, in each of the 3 steps; the
//    default deck holds it in none.
#define BOOST_TEST_MODULE case_builders
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <string>

#include "core/csv.hpp"
#include "io/deck.hpp"
#include "sim/block_case.hpp"
#include "sim/drawbend_case.hpp"
#include "sim/fe_options.hpp"
#include "sim/strip_draw_case.hpp"

using namespace drawbend;

namespace {
const std::string kData = DRAWBEND_DATA_DIR;

bool throws_naming(const std::function<void()>& f, const std::string& what) {
  try {
    f();
  } catch (const InputError& e) {
    return std::string(e.what()).find(what) != std::string::npos;
  }
  return false;
}
}  // namespace

BOOST_AUTO_TEST_CASE(quick_tier_and_mass_scaling_rule) {
  sim::DrawBendSpec s;
  sim::set_quick_mesh(s);
  BOOST_TEST(s.element_length == 1.0);
  BOOST_TEST(s.across == 2);
  BOOST_TEST(s.through == 4);
  BOOST_TEST(s.mass_scaling == 1e4);
  BOOST_TEST(sim::mass_scaling_for_speed(1e4, 50.0) == 4e4);
  BOOST_TEST(sim::mass_scaling_for_speed(1e4, 100.0) == 1e4);
}

BOOST_AUTO_TEST_CASE(block_loads_and_speeds) {
  sim::BlockSpec s = sim::default_block_spec(kData);
  s.pressure = 40;
  s.size = 2;
  s.speed = 70;
  s.direction_deg = 30;
  const io::Deck d = sim::block_deck(s);
  const fe::Model& m = d.model;
  BOOST_TEST(m.steps.size() == 2u);
  BOOST_TEST(m.steps[0].forces.at(0).magnitude(1.0) == 160.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.steps[1].forces.at(0).magnitude(0.0) == 160.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.steps[1].velocities.at(0).speed(1.0) == 70.0 * std::sqrt(3.0) / 2, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.steps[1].velocities.at(1).speed(1.0) == 35.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(block_default_is_the_data_deck) {
  const io::Deck b = sim::block_deck(sim::default_block_spec(kData));
  const io::Deck f = io::read_deck(kData + "/cases/block_surface.toml");
  BOOST_TEST(b.model.mesh.x == f.model.mesh.x);
  BOOST_TEST(b.model.mesh.y == f.model.mesh.y);
  BOOST_TEST(b.model.mesh.z == f.model.mesh.z);
  BOOST_TEST(b.model.mass_scaling == f.model.mass_scaling);
  BOOST_TEST(b.model.dt_safety == f.model.dt_safety);
  BOOST_REQUIRE(b.model.steps.size() == f.model.steps.size());
  for (std::size_t k = 0; k < b.model.steps.size(); ++k) {
    const fe::Step &x = b.model.steps[k], &y = f.model.steps[k];
    BOOST_TEST(x.duration == y.duration);
    BOOST_TEST(x.damping == y.damping);
    BOOST_TEST(x.forces.at(0).magnitude.t == y.forces.at(0).magnitude.t);
    BOOST_TEST(x.forces.at(0).magnitude.v == y.forces.at(0).magnitude.v);
  }
  // The data deck's RD slide: x at 50 mm/s after 5e-4 s; y held (a constant 0 there, a ramp to 0 here).
  BOOST_TEST(b.model.steps[1].velocities.at(0).speed.t == f.model.steps[1].velocities.at(0).speed.t);
  BOOST_TEST(b.model.steps[1].velocities.at(0).speed.v == f.model.steps[1].velocities.at(0).speed.v);
  BOOST_TEST(b.model.steps[1].velocities.at(1).speed(1.0) == 0.0);
}

BOOST_AUTO_TEST_CASE(strip_draw_force_time_step_and_die_mass) {
  const io::Deck d = sim::strip_draw_deck(sim::default_strip_draw_spec(kData));
  const fe::Model& m = d.model;
  BOOST_REQUIRE(m.tools.size() == 2u);
  BOOST_TEST(m.tools[0].name == "die");
  BOOST_TEST(m.tools[0].force(1.0) == 80.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m.target_dt == 2.5e-6);
  BOOST_TEST(m.steps.at(1).duration == 0.06, boost::test_tools::tolerance(1e-12));
  const double K = 70000.0 / (3 * (1 - 2 * 0.33)), k = 0.1 * K * 8.0 / 0.26;
  BOOST_TEST(m.tools[0].mass == 4 * k * 2.5e-6 * 2.5e-6, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(sim::strip_draw_time_step(3.9) == 1e-5);
  BOOST_TEST(sim::strip_draw_time_step(4.0) == 2.5e-6);
  BOOST_TEST(sim::strip_draw_time_step(40.0) == 2.5e-6);
  BOOST_TEST(sim::strip_draw_time_step(41.0) == 5e-7);
}

BOOST_AUTO_TEST_CASE(bad_values_name_the_field) {
  sim::BlockSpec b = sim::default_block_spec(kData);
  b.speed = 0;
  BOOST_TEST(throws_naming([&] { sim::block_deck_text(b); }, "speed [mm/s]"));
  b = sim::default_block_spec(kData);
  b.speed_ramp = 1.0;
  BOOST_TEST(throws_naming([&] { sim::block_deck_text(b); }, "speed_ramp"));
  sim::StripDrawSpec s = sim::default_strip_draw_spec(kData);
  s.pressure = -1;
  BOOST_TEST(throws_naming([&] { sim::strip_draw_deck_text(s); }, "pressure [MPa]"));
  s = sim::default_strip_draw_spec(kData);
  s.nz = 0;
  BOOST_TEST(throws_naming([&] { sim::strip_draw_deck_text(s); }, "nz"));
}

BOOST_AUTO_TEST_CASE(drawbend_plane_strain_width_holds_the_edge) {
  auto edge_holds = [](bool plane_strain) {
    sim::DrawBendSpec s;
    s.hardening = kData + "/materials/aa5754_o_rd.csv";
    s.plane_strain_width = plane_strain;
    const io::Deck d = io::parse_deck(sim::deck_text(s), "drawbend.toml");
    int held = 0;
    for (const auto& step : d.model.steps)
      for (const auto& f : step.fixed)
        if (f.set == "ymax") held += (!f.dof[0] && f.dof[1] && !f.dof[2]) ? 1 : 100;
    return std::make_pair(d.model.steps.size(), held);
  };
  const auto [steps, held] = edge_holds(true);
  BOOST_TEST(steps == 3u);
  BOOST_TEST(held == 3);
  BOOST_TEST(edge_holds(false).second == 0);
}
