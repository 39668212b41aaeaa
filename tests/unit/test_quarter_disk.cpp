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

BOOST_AUTO_TEST_CASE(geometry_and_sets) {
  fe::QuarterDiskSpec s;
  s.core = 8;
  s.ring = 14;
  s.through = 2;
  s.core_fraction = 0.25;
  const fe::Mesh m = fe::quarter_disk(s);
  BOOST_TEST(m.num_elements() == 576);
  BOOST_TEST(m.num_nodes() == 957);
  double V = 0;
  for (const auto& h : m.hex) {
    double ex[8], ey[8], ez[8];
    for (int a = 0; a < 8; ++a) {
      ex[a] = m.x[h[a]];
      ey[a] = m.y[h[a]];
      ez[a] = m.z[h[a]];
    }
    const double v = fe::hex_volume(ex, ey, ez);
    BOOST_TEST(v > 0.0);
    V += v;
  }
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
