// Rigid rotation of a pre-stressed element (objectivity of the stress update).
// Closed-form answer: an element carrying sigma_0 = (xx, yy, zz, xy, yz, zx) =
// (100, 20, -30, 15, 0, 0) MPa and rotated rigidly by 90 deg about z carries
// R sigma_0 R^T = (20, 100, -30, -15, 0, 0) MPa: the stress turns with the
// body and its invariants do not change.  Checked within 0.5 % of |sigma_0|.
//
// With a back stress (CombinedPlasticity, Hill'48 with one Armstrong-Frederick
// term): the element is first stretched plastically along x (affine velocity,
// eps_p about 1 %), then turned rigidly by 90 deg about z.  Closed form: the
// stress, the back stress and the sheet axes all turn with the body,
//   sigma_1 -> R sigma_1 R^T,  alpha_1 -> R alpha_1 R^T,  RD x -> y,
// and the turn adds no plastic strain.  Checked: stress and back stress within
// 0.5 % of their largest component (the first-order rotation's drift over the
// turn, as above), RD within 0.2 deg of y, plastic strain change below 1e-3 of
// the pre-strain.
#define BOOST_TEST_MODULE rotation
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fixtures.hpp"
#include "material/combined_plasticity.hpp"

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

BOOST_AUTO_TEST_CASE(back_stress_and_axes_turn_with_the_body) {
  material::KinematicHardening k;
  k.chaboche = {{6000.0, 40.0}};
  auto mat = std::make_shared<material::CombinedPlasticity>(kE, kNu, kRho, material::HardeningCurve({0.0, 1.0}, {100.0, 300.0}),
                                                           k, material::Hill48::from_r_values(0.69, 0.73, 0.87));
  fe::Model m = block(1, 1, 1, 1, 1, 1, mat);
  const double T = 1e-3, rate = 12.0;  // 1/s: 1.2 % stretch along x in T
  fe::Step stretch;
  stretch.duration = T;
  fe::AffineBC a;
  a.set = "all";
  a.G = {{{rate, 0, 0}, {0, -0.5 * rate, 0}, {0, 0, -0.5 * rate}}};
  a.centre = {0.5, 0.5, 0.5};
  stretch.affine.push_back(a);
  fe::Step turn;
  turn.duration = T;
  turn.rotations.push_back({"all", {0.5, 0.5, 0.5}, {0, 0, 1}, fe::History::constant(M_PI / 2 / T)});
  m.steps = {stretch};
  fe::Solver s1(m);
  s1.run();
  const int ns = mat->state_size();
  const std::vector<double> sig1 = s1.stress();
  double al1[6];
  mat->back_stress(&s1.material_state()[0], al1);
  const double ep1 = s1.material_state()[0];
  BOOST_TEST_REQUIRE(ep1 > 0.005);
  m.steps = {stretch, turn};
  fe::Solver s2(m);
  s2.run();
  const std::vector<double> sig2 = s2.stress();
  double al2[6];
  mat->back_stress(&s2.material_state()[0], al2);
  // R (90 deg about z): xx <-> yy, xy -> -xy, yz <-> zx up to sign: (yz, zx) -> (-zx... ) below.
  auto turned = [](const double v[6], double out[6]) {
    out[0] = v[1]; out[1] = v[0]; out[2] = v[2]; out[3] = -v[3]; out[4] = v[5]; out[5] = -v[4];
  };
  double se[6], ae[6];
  turned(sig1.data(), se);
  turned(al1, ae);
  double smax = 0, amax = 0;
  for (int c = 0; c < 6; ++c) {
    smax = std::max(smax, std::abs(sig1[c]));
    amax = std::max(amax, std::abs(al1[c]));
  }
  for (int c = 0; c < 6; ++c) {
    BOOST_TEST(std::abs(sig2[c] - se[c]) < 0.005 * smax, "stress " << c << ": " << sig2[c] << " vs " << se[c]);
    BOOST_TEST(std::abs(al2[c] - ae[c]) < 0.005 * amax, "back stress " << c << ": " << al2[c] << " vs " << ae[c]);
  }
  for (int gp = 0; gp < 2; ++gp) {
    const material::SheetAxes ax = mat->axes(&s2.material_state()[gp * ns]);
    BOOST_TEST(std::abs(std::atan2(ax.rd[1], ax.rd[0]) * 180 / M_PI - 90.0) < 0.2);
    BOOST_TEST(std::abs(s2.material_state()[gp * ns] - s1.material_state()[gp * ns]) < 1e-3 * ep1);
  }
}
