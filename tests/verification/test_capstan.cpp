// Capstan with a real strip, in the thesis's conditions (Chapters 2 and 4): a
// 1.04 mm AA5754-O strip (RD curve; half model, 12.7 mm wide) pulled over a
// 12.7 mm pin with a 90 deg wrap under the back tension of Table 4.1,
// F_x = 756.2 N (57 MPa), its outlet end moving at 100 mm/s.  Forces are the
// mean of the last third of the slide (the thesis's Chapters 3-4), after the
// strip has slid 1.5 wrap lengths (Sec. 2.3.2).
// Closed-form answers:
//  - frictionless: the bending force F_B = F_y - F_x.  The thesis's own
//    simulation of exactly this case (Table 4.1, 0.5" pin) gave 161.6 N; checked
//    within 10 % (another code, 2 instead of 8 elements across the width, and
//    our Swift fit of the hardening curve).  Swift's Eq. (2.1) with the 0.2 %
//    yield stress, sigma_y t^2 w / (2r) tan(45 deg) = 107.8 N on the half model,
//    assumes a perfectly plastic strip; AA5754-O hardens to about twice its
//    yield stress at the 8 % bending strain, so F_B must exceed it (checked,
//    and the ratio is reported).
//  - Coulomb mu = 0.1: Eq. (2.3), mu = (2/pi) ln((F_y - F_B)/F_x), retrieves
//    the input within 5 % (the thesis got 0.096).  The retrieval is not exact
//    even here: the bending reactions at entry and exit add normal force that
//    the rope formula does not know (measured: +5.7 % at 500 N back tension on
//    an elastic-perfectly plastic strip, mesh-converged).
#define BOOST_TEST_MODULE capstan
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "analysis/rope.hpp"
#include "core/csv.hpp"
#include "fe/strip.hpp"
#include "fixtures.hpp"

using namespace verify;

namespace {

struct Forces {
  double Fx, Fy;
};

Forces pull(double mu) {
  fe::StripSpec spec;
  spec.across = 2;
  spec.element_length = 0.5;
  spec.inlet_length = 22;
  spec.outlet_length = 6;
  fe::Model m;
  m.mesh = fe::wrapped_strip(spec);
  m.material = std::make_shared<material::J2Isotropic>(
      kE, kNu, kRho, material::HardeningCurve::load(std::string(DRAWBEND_DATA_DIR) + "/materials/aa5754_o_rd.csv"));
  m.mass_scaling = 1e4;
  contact::Surface pin;
  pin.kind = contact::Surface::Kind::cylinder;
  pin.axis = {0, 1, 0};
  pin.R = spec.pin_radius;
  m.add_rigid_contact("pin", pin, "zmin", mu > 0 ? std::make_shared<friction::Coulomb>(mu) : nullptr);
  const double Fback = 756.2, v = 100, slide = 1.5 * fe::wrap_length(spec) + 6.0;
  fe::Step tension;
  tension.duration = 0.04;
  tension.damping = 150;
  tension.fixed = {{"ymin", {false, true, false}}, {"xmax", {true, true, true}}, {"xmin", {false, false, true}}};
  tension.forces.push_back({"xmin", {-1, 0, 0}, {{0.0, 0.02}, {0.0, Fback}}});
  fe::Step draw;
  draw.duration = slide / v;
  draw.fixed = {{"ymin", {false, true, false}}, {"xmax", {true, true, false}}, {"xmin", {false, false, true}}};
  draw.forces.push_back({"xmin", {-1, 0, 0}, fe::History::constant(Fback)});
  draw.velocities.push_back({"xmax", {0, 0, -1}, {{0.0, 0.01}, {0.0, v}}});
  m.steps = {tension, draw};
  fe::Solver s(m);
  s.run_step(0);
  double sum = 0;
  long n = 0;
  const double t_draw = s.time();
  s.run_step(1, [&](const fe::Progress& p) {
    if (p.step_time > draw.duration * 2.0 / 3.0) {
      sum += -s.reaction("xmax")[2];  // the outlet grip pulls along -z
      ++n;
    }
  });
  BOOST_TEST_MESSAGE("mu = " << mu << ": F_y = " << sum / n << " N over " << n << " cycles, slide "
                             << slide << " mm in " << s.time() - t_draw << " s, KE/IE "
                             << s.energies().kinetic / s.energies().internal << ", energy balance error "
                             << s.energies().balance_error() << ", hourglass/internal "
                             << s.energies().hourglass / s.energies().internal);
  BOOST_TEST(s.energies().balance_error() < 0.01);
  return {Fback, sum / n};
}

}  // namespace

BOOST_AUTO_TEST_CASE(bending_force_and_friction) {
  const Forces free = pull(0.0), fric = pull(0.1);
  const double FB = free.Fy - free.Fx;
  const double swift = analysis::swift_bending_force(99.71, 1.04, 25.4, 6.35, M_PI / 2, analysis::ForceBasis::half_model);
  const double mu = analysis::mu_rope(fric.Fx, fric.Fy, FB, M_PI / 2);
  BOOST_TEST_MESSAGE("F_B = " << FB << " N, Swift " << swift << " N (ratio " << FB / swift << "); mu from Eq. (2.3) = "
                              << mu);
  const CsvTable t41 = read_csv(std::string(DRAWBEND_DATA_DIR) + "/thesis/table_4_1.csv");
  const double FB_thesis = t41.number(t41.rows.front(), "FB_N");  // 0.5" (12.7 mm) pin
  BOOST_TEST_MESSAGE("F_B thesis (Table 4.1) " << FB_thesis << " N, ours " << FB << " N ("
                                                << 100 * (FB - FB_thesis) / FB_thesis << " %)");
  BOOST_TEST(std::abs(FB - FB_thesis) / FB_thesis < 0.10);
  BOOST_TEST(FB > swift);
  BOOST_TEST(std::abs(mu - 0.1) / 0.1 < 0.05);
}
