// Elastic-plastic bending of a 4-layer strip: the fully plastic moment.
// Closed-form answer: a strip of thickness t = 1.04 mm and width w = 1 mm of an
// elastic-perfectly plastic material (sigma_y = 100 MPa) bent to a radius r =
// 10 mm (surface strain t/2r = 5.2 %, 37 times the yield strain) carries the
// fully plastic moment M_p = sigma_y t^2 w / 4 = 27.04 N mm (the elastic core is
// 2.7 % of the thickness; M/M_p = 1 - (e_y/e_s)^2/3 = 0.9998).  Pure bending:
// one end is a symmetry plane (x fixed), the other face rotates about its
// mid-thickness point.  The moment is read from the reactions at the symmetry
// plane, M = sum_i (z_i - z_mid) R_x,i.  Checked within 5 %.
#define BOOST_TEST_MODULE plastic_bending
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fixtures.hpp"

using namespace verify;

BOOST_AUTO_TEST_CASE(fully_plastic_moment) {
  const double Lb = 5.0, t = 1.04, w = 1.0, sy = 100, r = 10;
  fe::Model m = block(Lb, w, t, 20, 1, 4, j2_linear(sy, 0.0));
  m.mass_scaling = 100;
  fe::Step s;
  const double theta = Lb / r, T = 2e-2;
  s.duration = T;
  s.fixed = {{"xmin", {true, false, false}}};
  m.mesh.node_sets["anchor"] = {0};
  s.fixed.push_back({"anchor", {false, true, false}});
  // The end face turns about its mid-thickness point; bending upward means a
  // rotation about -y.
  s.rotations.push_back({"xmax", {Lb, 0.0, t / 2}, {0, -1, 0}, {{0.0, 0.2 * T, T}, {0.0, theta / (0.9 * T), theta / (0.9 * T)}}, {1, 0, 0}});
  m.steps.push_back(s);
  fe::Solver solver(m);
  solver.run();
  double M = 0, zmid = 0;
  const auto& set = m.mesh.node_set("xmin");
  for (int i : set) zmid += solver.z()[i] / set.size();
  for (int i : set) M += (solver.z()[i] - zmid) * solver.node_reaction(i)[0];
  const double Mp = sy * t * t * w / 4;
  const auto& e = solver.energies();
  BOOST_TEST_MESSAGE("moment " << M << " N mm, fully plastic " << Mp << " N mm, error " << 100 * (std::abs(M) - Mp) / Mp
                               << " %, hourglass/internal " << 100 * e.hourglass / e.internal << " %, KE/IE "
                               << e.kinetic / e.internal);
  BOOST_TEST(std::abs(std::abs(M) - Mp) / Mp < 0.05);
  BOOST_TEST(e.kinetic / e.internal < 0.01);  // quasi-static
}
