// Patch test on a distorted mesh.
// Closed-form answer: a 2 x 2 x 2 block whose interior node is moved off-centre
// (distorted elements) has its 26 boundary nodes driven by the linear field
// v = G X (G symmetric, constant).  The interior node is free.  The exact
// solution is homogeneous: every element has the same stress, and the interior
// node follows the linear field, x = (I + t G) X, with zero acceleration.
// The uniform-gradient element reproduces this to round-off (the nodal forces
// of a constant stress balance exactly; hourglass rates vanish for linear fields).
// Elastic stress: sigma = C : (t G) to first order in the strain (1e-3 here).
#define BOOST_TEST_MODULE patch
#include <boost/test/unit_test.hpp>

#include "fixtures.hpp"

using namespace verify;

BOOST_AUTO_TEST_CASE(distorted_patch_constant_stress) {
  fe::Model m = block(1, 1, 1, 2, 2, 2, elastic());
  const int centre = 13;  // (1, 1, 1) of the 3 x 3 x 3 nodes
  m.mesh.x[centre] += 0.12;
  m.mesh.y[centre] -= 0.07;
  m.mesh.z[centre] += 0.09;
  auto& boundary = m.mesh.node_sets["boundary"];
  for (int i = 0; i < m.mesh.num_nodes(); ++i)
    if (i != centre) boundary.push_back(i);
  const std::array<std::array<double, 3>, 3> G{{{1e-3, 2e-4, 0}, {2e-4, -5e-4, 1e-4}, {0, 1e-4, 3e-4}}};
  fe::Step s;
  s.duration = 1e-3;
  s.affine.push_back({"boundary", G, {0, 0, 0}, fe::History::constant(1000.0)});  // strain rate 1/s * 1000
  m.steps.push_back(s);
  fe::Solver solver(m);
  for (int i = 0; i < m.mesh.num_nodes(); ++i) {
    const double X[3] = {m.mesh.x[i], m.mesh.y[i], m.mesh.z[i]};
    fe::Vec3 v{};
    for (int r = 0; r < 3; ++r) v[r] = 1000.0 * (G[r][0] * X[0] + G[r][1] * X[1] + G[r][2] * X[2]);
    solver.set_velocity(i, v);
  }
  solver.run();
  const double t = solver.time();
  // Interior node on the linear field.
  const double X[3] = {m.mesh.x[centre], m.mesh.y[centre], m.mesh.z[centre]};
  const double xs[3] = {solver.x()[centre], solver.y()[centre], solver.z()[centre]};
  for (int r = 0; r < 3; ++r) {
    const double expect = X[r] + 1000.0 * t * (G[r][0] * X[0] + G[r][1] * X[1] + G[r][2] * X[2]);
    BOOST_TEST(std::abs(xs[r] - expect) < 1e-12);
  }
  // Uniform stress, equal to C : eps to first order.
  const auto& sg = solver.stress();
  for (int e = 1; e < m.mesh.num_elements(); ++e)
    for (int k = 0; k < 6; ++k) BOOST_TEST(std::abs(sg[6 * e + k] - sg[k]) < 1e-9 * 100.0);
  const double lam = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double eps[3][3] = {{G[0][0], G[0][1], G[0][2]}, {G[1][0], G[1][1], G[1][2]}, {G[2][0], G[2][1], G[2][2]}};
  const double tr = (eps[0][0] + eps[1][1] + eps[2][2]) * 1000.0 * t;
  const double expect[6] = {lam * tr + 2 * mu * eps[0][0] * 1000 * t, lam * tr + 2 * mu * eps[1][1] * 1000 * t,
                            lam * tr + 2 * mu * eps[2][2] * 1000 * t, 2 * mu * eps[0][1] * 1000 * t,
                            2 * mu * eps[1][2] * 1000 * t, 2 * mu * eps[2][0] * 1000 * t};
  for (int k = 0; k < 6; ++k) BOOST_TEST(std::abs(sg[k] - expect[k]) < 2e-3 * 100.0);  // first-order in strain
  BOOST_TEST(solver.energies().hourglass < 1e-12);
}
