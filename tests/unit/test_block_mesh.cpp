// The structured block's numbering (fe/mesh.hpp: block_order, structured_block).
// Closed-form answers:
//  - block_order(ex, ey, ez) (axis 0 = x, 1 = y, 2 = z; fastest first):
//      100 x 16 x 5 -> y, z, x   (x longest; y has 16 >= 8 elements)
//       40 x  8 x 5 -> y, z, x   (y has exactly 8)
//       16 x  5 x 100 -> x, y, z (z longest already: as built)
//       50 x  2 x 4 -> x, y, z   (the other two under 8: as built)
//      100 x 100 x 5 -> x, z, y  (a tie for the longest keeps the later, y,
//                                 slowest; x the longer of the other two)
//        8 x  8 x 8 -> x, y, z   (all tied: as built)
//        5 x 40 x 9 -> z, x, y   (y longest; z has 9 >= 8)
//  - the block of 100 x 16 x 5 unit elements: 101 x 17 x 6 = 10,302 nodes,
//    8,000 elements, volume 8,000 mm^3; node n + 1 lies 1 mm along y from node
//    n inside a row; along each row of 16 elements, element e + 1 has node
//    n + 1 wherever element e has node n; the elements [0, 4000) and
//    [4000, 8000), the halves that two threads take, share exactly the
//    17 x 6 = 102 nodes of the plane x = 50 (numbered x fastest they would
//    share 1,818: a staircase of two half planes of z between the halves);
//  - node sets ascending, xmin has 17 x 6 = 102 nodes all at x = 0; each face
//    set covers its side's area with outward normals;
//  - the block of 50 x 2 x 4 is numbered as built: node i + 51 (j + 3 k);
//  - a checkpoint (fe::Solver::save_state) restores onto the same mesh, and
//    is refused with an InputError naming the mesh onto the same block with
//    its node numbers reversed (same counts, another numbering: what a
//    change of block_order does to an old checkpoint), and refused with its
//    own message when its header says format 1 (no fingerprint).
#define BOOST_TEST_MODULE block_mesh
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <array>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "fe/mesh.hpp"
#include "fe/solver.hpp"
#include "material/linear_elastic.hpp"

using namespace drawbend;
namespace tt = boost::test_tools;

namespace {
std::array<int, 3> order(int ex, int ey, int ez) {
  const fe::BlockOrder o = fe::block_order(ex, ey, ez);
  return {o.axis[0], o.axis[1], o.axis[2]};
}
using A = std::array<int, 3>;
}  // namespace

BOOST_AUTO_TEST_CASE(block_order_rule) {
  BOOST_TEST((order(100, 16, 5) == A{1, 2, 0}));
  BOOST_TEST((order(40, 8, 5) == A{1, 2, 0}));
  BOOST_TEST((order(16, 5, 100) == A{0, 1, 2}));
  BOOST_TEST((order(50, 2, 4) == A{0, 1, 2}));
  BOOST_TEST((order(100, 100, 5) == A{0, 2, 1}));
  BOOST_TEST((order(8, 8, 8) == A{0, 1, 2}));
  BOOST_TEST((order(5, 40, 9) == A{2, 0, 1}));
}

BOOST_AUTO_TEST_CASE(long_bar_numbered_across) {
  const fe::Mesh m =
      fe::structured_block(fe::uniform_lines(0, 100, 100), fe::uniform_lines(0, 16, 16), fe::uniform_lines(0, 5, 5));
  BOOST_TEST(m.num_nodes() == 10302);
  BOOST_TEST(m.num_elements() == 8000);
  double V = 0;
  for (const auto& h : m.hex) {
    double ex[8], ey[8], ez[8];
    fe::gather(m.x, m.y, m.z, h, ex, ey, ez);
    const double v = fe::hex_volume(ex, ey, ez);
    BOOST_TEST(v > 0.0);
    V += v;
  }
  BOOST_TEST(V == 8000.0, tt::tolerance(1e-12));
  // y fastest: node 1 is 1 mm along y from node 0.
  BOOST_TEST(m.x[1] == m.x[0]);
  BOOST_TEST(m.y[1] == m.y[0] + 1.0);
  BOOST_TEST(m.z[1] == m.z[0]);
  // Rows of 16 elements along y, their nodes running on with them.
  int runs = 0;
  for (int e = 0; e + 1 < m.num_elements(); ++e) {
    if (e % 16 == 15) continue;
    bool on = true;
    for (int a = 0; a < 8; ++a) on = on && m.hex[e + 1][a] == m.hex[e][a] + 1;
    runs += on;
  }
  BOOST_TEST(runs == 8000 - 500);
  // The halves meet on one cross-section.
  std::set<int> first, shared;
  for (int e = 0; e < 4000; ++e) first.insert(m.hex[e].begin(), m.hex[e].end());
  for (int e = 4000; e < 8000; ++e)
    for (int n : m.hex[e])
      if (first.count(n)) shared.insert(n);
  BOOST_TEST(shared.size() == 102u);
  for (int n : shared) BOOST_TEST(m.x[n] == 50.0);
  // Node sets ascending and on their sides; faces outward.
  for (const auto& [name, set] : m.node_sets) BOOST_TEST(std::is_sorted(set.begin(), set.end()), name);
  BOOST_TEST(m.node_set("xmin").size() == 102u);
  for (int n : m.node_set("xmin")) BOOST_TEST(m.x[n] == 0.0);
  for (int n : m.node_set("zmax")) BOOST_TEST(m.z[n] == 5.0);
  const struct {
    const char* name;
    int axis;
    double sign, area;
  } sides[] = {{"xmin", 0, -1, 80}, {"xmax", 0, 1, 80},    {"ymin", 1, -1, 500},
               {"ymax", 1, 1, 500}, {"zmin", 2, -1, 1600}, {"zmax", 2, 1, 1600}};
  for (const auto& s : sides) {
    double area = 0, normal = 0;
    for (const auto& q : m.face_set(s.name)) {
      area += fe::quad_area(m.x, m.y, m.z, q);
      const double d1[3] = {m.x[q[2]] - m.x[q[0]], m.y[q[2]] - m.y[q[0]], m.z[q[2]] - m.z[q[0]]};
      const double d2[3] = {m.x[q[3]] - m.x[q[1]], m.y[q[3]] - m.y[q[1]], m.z[q[3]] - m.z[q[1]]};
      const double nrm[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                             d1[0] * d2[1] - d1[1] * d2[0]};
      normal += 0.5 * nrm[s.axis];
    }
    BOOST_TEST(area == s.area, tt::tolerance(1e-12));
    BOOST_TEST(normal == s.sign * s.area, tt::tolerance(1e-12));
  }
}

BOOST_AUTO_TEST_CASE(narrow_strip_as_built) {
  const fe::Mesh m =
      fe::structured_block(fe::uniform_lines(0, 50, 50), fe::uniform_lines(0, 2, 2), fe::uniform_lines(0, 4, 4));
  for (int k = 0; k <= 4; ++k)
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 50; ++i) {
        const int n = i + 51 * (j + 3 * k);
        BOOST_TEST((m.x[n] == i && m.y[n] == j && m.z[n] == k));
      }
  BOOST_TEST((m.hex[1][0] == 1 && m.hex[50][0] == 51));
}

namespace {
fe::Model small_block() {
  fe::Model m;
  m.mesh = fe::structured_block(fe::uniform_lines(0, 10, 10), fe::uniform_lines(0, 8, 8), fe::uniform_lines(0, 1, 1));
  m.material = std::make_shared<material::LinearElastic>(70000.0, 0.33, 2.7e-9);
  fe::Step s;
  s.duration = 2e-6;
  s.velocities.push_back({"xmax", {1, 0, 0}, fe::History::constant(100.0)});
  m.steps.push_back(s);
  return m;
}

bool names_mesh(const InputError& e) { return std::string(e.what()).find("mesh") != std::string::npos; }
bool names_format_1(const InputError& e) { return std::string(e.what()).find("format 1") != std::string::npos; }
}  // namespace

BOOST_AUTO_TEST_CASE(checkpoint_of_another_numbering_is_refused) {
  fe::Model m = small_block();
  fe::Solver a(m);
  a.run();
  std::string state;
  a.save_state(state);
  fe::Model same = small_block();
  fe::Solver b(same);
  BOOST_CHECK_NO_THROW(b.load_state(state, "same"));
  BOOST_TEST(b.x() == a.x(), tt::per_element());
  // The same block, node n numbered N - 1 - n.
  fe::Model rev = small_block();
  fe::Mesh& r = rev.mesh;
  const int N = r.num_nodes();
  std::reverse(r.x.begin(), r.x.end());
  std::reverse(r.y.begin(), r.y.end());
  std::reverse(r.z.begin(), r.z.end());
  for (auto& h : r.hex)
    for (int& n : h) n = N - 1 - n;
  for (auto& [name, set] : r.node_sets) {
    for (int& n : set) n = N - 1 - n;
    std::sort(set.begin(), set.end());
  }
  for (auto& [name, faces] : r.face_sets)
    for (auto& q : faces)
      for (int& n : q) n = N - 1 - n;
  BOOST_TEST(fe::mesh_fingerprint(r) != fe::mesh_fingerprint(m.mesh));
  fe::Solver c(rev);
  BOOST_CHECK_EXCEPTION(c.load_state(state, "reversed"), InputError, names_mesh);
  std::string v1 = state;
  v1.replace(0, std::string("drawbend-solver-state 2\n").size(), "drawbend-solver-state 1\n");
  fe::Solver d(same);
  BOOST_CHECK_EXCEPTION(d.load_state(v1, "v1"), InputError, names_format_1);
}
