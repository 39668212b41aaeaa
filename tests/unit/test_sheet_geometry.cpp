// The sheet's thickness, strain and tool surfaces of the ParaView frames
// (io/sheet_geometry.hpp, io/tool_mesh.hpp), on a block of 2 x 1 x 3 hexahedra:
// 1 mm along x and y, three 0.3 mm layers through z (t = 0.9 mm; the shortest
// row of elements is the z one, 0.9 mm against 1 mm across y and 2 mm along x).
// Closed-form answers:
//  - reference: every node's sheet thickness 0.9 mm (1e-12);
//  - a stretch x 1.2 along x and x 0.8 through z: thickness 0.72 mm, log strain
//    diag(ln 1.2, 0, ln 0.8) in every element (1e-12);
//  - a rigid rotation of 90 deg about y: thickness 0.9 mm, log strain 0 (1e-12:
//    the measure is objective);
//  - a simple shear x += tan(5 deg) z: the node-pair thickness reads
//    0.9 / cos(5 deg) (1e-12; the documented 1/cos(gamma) of a tilted path),
//    and the log strain's trace is ln J = 0 (1e-12);
//  - tools: a cylinder R = 6.35 about y has every corner at 6.35 from the axis
//    (1e-12) and spans y from the box's -0.5 - 12.7 to 13.2 + 12.7 (margin 2 R);
//    a plane annulus r_min = 2, r_max = 5 about (1, 0, -3) has every corner at
//    z = -3 and radius in [2, 5] with both ends reached; a torus R = 10, r = 2
//    over tube angles 0..pi/2 has every corner at 2 from its core circle.
#define BOOST_TEST_MODULE sheet_geometry
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "io/sheet_geometry.hpp"
#include "io/tool_mesh.hpp"

using namespace drawbend;

namespace {

fe::Mesh block() {
  fe::Mesh m;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) m.x.push_back(i), m.y.push_back(j), m.z.push_back(0.3 * k);
  auto n = [](int i, int j, int k) { return i + 3 * j + 6 * k; };
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 2; ++i)
      m.hex.push_back({n(i, 0, k), n(i + 1, 0, k), n(i + 1, 1, k), n(i, 1, k), n(i, 0, k + 1), n(i + 1, 0, k + 1),
                       n(i + 1, 1, k + 1), n(i, 1, k + 1)});
  return m;
}

struct Moved {
  std::vector<double> x, y, z;
};
template <class F>
Moved move(const fe::Mesh& m, F f) {
  Moved c;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const Vec3 p = f(Vec3{m.x[i], m.y[i], m.z[i]});
    c.x.push_back(p[0]), c.y.push_back(p[1]), c.z.push_back(p[2]);
  }
  return c;
}

void check_thickness(const fe::Mesh& m, const Moved& c, double expected) {
  const auto h = io::node_thickness(io::sheet_columns(m), c.x.data(), c.y.data(), c.z.data());
  BOOST_REQUIRE(h.size() == 24u);
  for (double v : h) BOOST_TEST(std::abs(v - expected) < 1e-12);
}

}  // namespace

BOOST_AUTO_TEST_CASE(thickness_and_strain) {
  const fe::Mesh m = block();
  check_thickness(m, move(m, [](Vec3 p) { return p; }), 0.9);
  const Moved s = move(m, [](Vec3 p) { return Vec3{1.2 * p[0], p[1], 0.8 * p[2]}; });
  check_thickness(m, s, 0.72);
  for (int e = 0; e < m.num_elements(); ++e) {
    double eps[6];
    io::log_strain(m, s.x.data(), s.y.data(), s.z.data(), e, eps);
    const double want[6] = {std::log(1.2), 0, std::log(0.8), 0, 0, 0};
    for (int c = 0; c < 6; ++c) BOOST_TEST(std::abs(eps[c] - want[c]) < 1e-12);
  }
  const Moved r = move(m, [](Vec3 p) { return Vec3{p[2], p[1], -p[0]}; });  // 90 deg about y
  check_thickness(m, r, 0.9);
  const double g = std::tan(5 * M_PI / 180);
  const Moved sh = move(m, [g](Vec3 p) { return Vec3{p[0] + g * p[2], p[1], p[2]}; });
  check_thickness(m, sh, 0.9 / std::cos(5 * M_PI / 180));
  for (int e = 0; e < m.num_elements(); ++e) {
    double eps[6];
    io::log_strain(m, r.x.data(), r.y.data(), r.z.data(), e, eps);
    for (double v : eps) BOOST_TEST(std::abs(v) < 1e-12);
    io::log_strain(m, sh.x.data(), sh.y.data(), sh.z.data(), e, eps);
    BOOST_TEST(std::abs(eps[0] + eps[1] + eps[2]) < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(tool_surfaces) {
  const Vec3 lo{-1, -0.5, -2}, hi{3, 13.2, 1};
  fe::Tool pin;
  contact::Surface cyl;
  cyl.kind = contact::Surface::Kind::cylinder;
  cyl.axis = {0, 1, 0};
  cyl.R = 6.35;
  pin.surfaces.push_back(cyl);
  const io::ToolMesh t = io::tool_mesh(pin, {0, 0, 0}, lo, hi);
  BOOST_REQUIRE(t.quads.size() == 4 * t.surface.size());
  double ymin = 1e30, ymax = -1e30;
  for (std::size_t i = 0; i < t.x.size(); ++i) {
    BOOST_TEST(std::abs(std::hypot(t.x[i], t.z[i]) - 6.35) < 1e-12);
    ymin = std::min(ymin, t.y[i]), ymax = std::max(ymax, t.y[i]);
  }
  BOOST_TEST(std::abs(ymin - (-0.5 - 12.7)) < 1e-12);
  BOOST_TEST(std::abs(ymax - (13.2 + 12.7)) < 1e-12);

  fe::Tool die;
  contact::Surface pl;
  pl.kind = contact::Surface::Kind::plane;
  pl.origin = {1, 0, -3};
  pl.r_min = 2, pl.r_max = 5;
  die.surfaces.push_back(pl);
  const io::ToolMesh d = io::tool_mesh(die, {0, 0, 0}, lo, hi);
  double rmin = 1e30, rmax = 0;
  for (std::size_t i = 0; i < d.x.size(); ++i) {
    BOOST_TEST(d.z[i] == -3.0);
    const double r = std::hypot(d.x[i] - 1, d.y[i]);
    rmin = std::min(rmin, r), rmax = std::max(rmax, r);
  }
  BOOST_TEST(std::abs(rmin - 2) < 1e-12);
  BOOST_TEST(std::abs(rmax - 5) < 1e-12);

  fe::Tool punch;
  contact::Surface to;
  to.kind = contact::Surface::Kind::torus;
  to.R = 10, to.r = 2, to.a_min = 0, to.a_max = M_PI / 2;
  punch.surfaces.push_back(to);
  const io::ToolMesh p = io::tool_mesh(punch, {0, 0, 1}, lo, hi);  // moved 1 mm up
  for (std::size_t i = 0; i < p.x.size(); ++i)
    BOOST_TEST(std::abs(std::hypot(std::hypot(p.x[i], p.y[i]) - 10, p.z[i] - 1) - 2) < 1e-12);
}
