// Single element, uniaxial tension with the AA5754-O RD hardening curve.
// Closed-form answer: in uniaxial stress the axial true stress equals the flow
// stress of the input table at the current equivalent plastic strain,
// sigma_xx = sigma_y(eps_p), and eps_p = ln(L/L0) - sigma_xx/E.  Checked within
// 0.5 % from first yield to a plastic strain of 0.3.
#define BOOST_TEST_MODULE uniaxial
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fixtures.hpp"

using namespace verify;

BOOST_AUTO_TEST_CASE(reproduces_hardening_curve) {
  const auto curve = material::HardeningCurve::load(std::string(DRAWBEND_DATA_DIR) + "/materials/aa5754_o_rd.csv");
  fe::Model m = block(1, 1, 1, 1, 1, 1, std::make_shared<material::J2Isotropic>(kE, kNu, kRho, curve));
  m.mass_scaling = 1e4;
  fe::Step s;
  s.duration = 0.4;
  s.fixed = {{"xmin", {true, false, false}}, {"ymin", {false, true, false}}, {"zmin", {false, false, true}}};
  s.velocities.push_back({"xmax", {1, 0, 0}, {{0.0, 0.01}, {0.0, 1.0}}});  // 1 mm/s after a short ramp
  m.steps.push_back(s);
  fe::Solver solver(m);
  int checked = 0;
  double next = 0.002;
  solver.run([&](const fe::Progress&) {
    const double ep = solver.plastic_strain(0);
    if (ep < next) return;
    next += 0.03;
    const double sxx = solver.stress()[0];
    BOOST_TEST(std::abs(sxx - curve.stress(ep)) / curve.stress(ep) < 0.005);
    const double L = solver.x()[1] - solver.x()[0];
    BOOST_TEST(std::abs(ep - (std::log(L) - sxx / kE)) < 0.005 * ep + 1e-5);
    BOOST_TEST(std::abs(solver.stress()[1]) < 0.005 * sxx);  // lateral stress free
    ++checked;
  });
  BOOST_TEST(checked >= 8);
  BOOST_TEST(solver.plastic_strain(0) > 0.3);
}
