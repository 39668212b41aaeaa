// The quarter-disk blank mesh (fe/disk.hpp) and its deck form.
// Closed-form answers, for radius R = 55.625 mm, thickness t = 1.05 mm, core n = 8,
// ring m = 14, 2 layers:
//  - elements: (n^2 + 2n m) x layers = (64 + 224) x 2 = 576; nodes:
//    ((n+1)^2 + (2n+1) m) x 3 = (81 + 238) x 3 = 957;
//  - the plan is the polygon inscribed in the quarter circle with 2n equal chords,
//    so the volume is t x 2n x R^2 sin(pi/(4n)) / 2 (every element positive);
//  - the rim nodes lie on r = R; xmin nodes on x = 0, ymin nodes on y = 0;
//  - face sets zmin / zmax cover the plan area with normals -z / +z.
#define BOOST_TEST_MODULE quarter_disk
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "fe/disk.hpp"

using namespace drawbend;
namespace tt = boost::test_tools;

// Volume of the mesh; every element's must be positive.
static double positive_volume(const fe::Mesh& m) {
  double V = 0;
  for (const auto& h : m.hex) {
    double ex[8], ey[8], ez[8];
    for (int a = 0; a < 8; ++a) ex[a] = m.x[h[a]], ey[a] = m.y[h[a]], ez[a] = m.z[h[a]];
    const double v = fe::hex_volume(ex, ey, ez);
    BOOST_TEST(v > 0.0);
    V += v;
  }
  return V;
}

BOOST_AUTO_TEST_CASE(geometry_and_sets) {
  fe::QuarterDiskSpec s;
  s.core = 8;
  s.ring = 14;
  s.through = 2;
  s.core_fraction = 0.25;
  const fe::Mesh m = fe::quarter_disk(s);
  BOOST_TEST(m.num_elements() == 576);
  BOOST_TEST(m.num_nodes() == 957);
  const double V = positive_volume(m);
  const double n = s.core, R = s.radius;
  BOOST_TEST(V == s.thickness * 2 * n * R * R * std::sin(M_PI / (4 * n)) / 2, tt::tolerance(1e-12));
  for (int i : m.node_set("rim")) BOOST_TEST(std::hypot(m.x[i], m.y[i]) == R, tt::tolerance(1e-12));
  for (int i : m.node_set("xmin")) BOOST_TEST(m.x[i] == 0.0);
  for (int i : m.node_set("ymin")) BOOST_TEST(m.y[i] == 0.0);
  BOOST_TEST(m.node_set("rim").size() == 3u * (2 * 8 + 1));
  for (const char* f : {"zmin", "zmax"}) {
    double A = 0, nz = 0;
    for (const auto& q : m.face_set(f)) {
      A += fe::quad_area(m.x, m.y, m.z, q);
      const double ax = m.x[q[1]] - m.x[q[0]], ay = m.y[q[1]] - m.y[q[0]];
      const double bx = m.x[q[3]] - m.x[q[0]], by = m.y[q[3]] - m.y[q[0]];
      nz += ax * by - ay * bx;  // z of (q1 - q0) x (q3 - q0)
    }
    BOOST_TEST(A * s.thickness == V, tt::tolerance(1e-12));
    BOOST_TEST((std::string(f) == "zmin" ? nz < 0 : nz > 0));
  }
  s.core_fraction = 0.9;
  BOOST_CHECK_THROW(fe::quarter_disk(s), std::invalid_argument);
}

// Polar outer ring: with polar_radius 24 mm on a 53.75 mm disk, core 0.25 (a = 13.4375 mm), ring 20, the
// rows from floor(20 (24 - a) / (53.75 - a)) = 5 out are circles, radius a + (53.75 - a) r / 20 for row r,
// and node k of a row sits at k x 90 / 12 deg (core 6: 12 ring lines).
BOOST_AUTO_TEST_CASE(quarter_disk_polar_ring_rows_are_circles) {
  fe::QuarterDiskSpec s;
  s.radius = 53.75;
  s.thickness = 1.0;
  s.core = 6;
  s.ring = 20;
  s.through = 3;
  s.core_fraction = 0.25;
  s.polar_radius = 24.0;
  const fe::Mesh m = fe::quarter_disk(s);
  const double a = 0.25 * 53.75;
  const int np = m.num_nodes() / 4, core_nodes = 7 * 7;
  int checked = 0;
  for (int q = core_nodes; q < np; ++q) {
    const int k = (q - core_nodes) / 20, r = (q - core_nodes) % 20 + 1;
    if (r < 5) continue;
    BOOST_TEST(std::hypot(m.x[q], m.y[q]) == a + (53.75 - a) * r / 20.0, tt::tolerance(1e-12));
    BOOST_TEST(std::atan2(m.y[q], m.x[q]) == M_PI / 2 * k / 12.0, tt::tolerance(1e-12));
    ++checked;
  }
  BOOST_TEST(checked == 13 * 16);
  const double V = positive_volume(m);
  // the polygon of 12 chords on the rim, as for the O-grid without a polar part
  BOOST_TEST(V == 12 * 53.75 * 53.75 * std::sin(M_PI / 24) / 2, tt::tolerance(1e-12));
  s.polar_radius = 15.0;  // inside the core's corner (19.0 mm)
  BOOST_CHECK_THROW(fe::quarter_disk(s), std::invalid_argument);
}
