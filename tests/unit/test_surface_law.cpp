// The mu(p, v) friction law of the solver (thesis Eqs. 6.1-6.3, Table 6.1) and
// the corotational texture axis.  Closed-form answers:
//  - inside the domain (p 0-80 MPa, v 6.35-101.6 mm/s) the law returns
//    (mu_RD, mu_TD) = the nine-node surfaces of analysis::FrictionSurface
//    (Eq. 6.2, corrected Eq. 6.3) to rounding (1e-14); at the nodes, the
//    Table 6.1 values exactly (e.g. node 7: RD 0.2142, TD 0.0874 at 80 MPa, 6.35 mm/s);
//  - outside it the inputs are clamped to the edge: mu(120 MPa, v) = mu(80, v),
//    mu(p, 0) = mu(p, 6.35), mu(p, 300) = mu(p, 101.6), and each such evaluation
//    is counted (pressure, low speed, high speed);
//  - interval averaging: with interval 4 and speeds 10, 30, 10, 30 mm/s the
//    speed input after the fourth call is 20 mm/s and stays 20 for the next
//    three calls; before, it is the running mean (10, then 20, then 16.67);
//  - the surfaces of Table 6.1 stay >= 0 over the domain (min on a 161 x 161 grid);
//  - building from the Table 5.16 lines (Sec. 6.2) gives Table 6.1 within half a
//    unit of its last printed digit plus the propagated rounding (2e-4);
//  - file validation: nodes out of order, a negative mu, or speed lines out of
//    order are rejected with the file, line and column named;
//  - the deck reader: `law = "surface"` with `texture = "corotational"` builds the
//    law and the pair's texture; a bad texture name or a bad nodes file is an
//    error naming the deck key (and the CSV file, line and column);
//  - corotational texture: a face rotated rigidly by 35 deg about z turns RD
//    = x into (cos 35, sin 35, 0); a simple shear x += 0.5 y (polar rotation
//    -atan(0.25) = -14.04 deg) turns it by -14.04 deg; a face bent 90 deg about
//    y (normal z -> x) turns RD = x into -z.
#define BOOST_TEST_MODULE surface_law
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>

#include "contact/texture.hpp"
#include "core/csv.hpp"
#include "fe/mesh.hpp"
#include "io/deck.hpp"
#include "friction/surface_law.hpp"

using namespace drawbend;
namespace tt = boost::test_tools;

static const std::string kData = DRAWBEND_DATA_DIR;

static friction::SurfaceLaw table_6_1(int interval = 1) {
  const auto [rd, td] = friction::load_surface_nodes(kData + "/thesis/table_6_1.csv", {});
  return friction::SurfaceLaw(rd, td, interval);
}

BOOST_AUTO_TEST_CASE(matches_nine_node_surface) {
  const auto law = table_6_1();
  for (double p : {0.0, 7.5, 40.0, 63.2, 80.0})
    for (double v : {6.35, 10.0, 53.975, 77.0, 101.6}) {
      const auto lim = law.at(p, v);
      BOOST_TEST(lim.mu1 == law.rd()(p, v), tt::tolerance(1e-13));
      BOOST_TEST(lim.mu2 == law.td()(p, v), tt::tolerance(1e-13));
    }
  BOOST_TEST(law.at(80, 6.35).mu1 == 0.2142, tt::tolerance(1e-12));
  BOOST_TEST(law.at(80, 6.35).mu2 == 0.0874, tt::tolerance(1e-12));
  double lo = 1;
  for (int i = 0; i <= 160; ++i)
    for (int j = 0; j <= 160; ++j) {
      const double p = 0.5 * i, v = 6.35 + (101.6 - 6.35) * j / 160.0;
      lo = std::min({lo, law.rd()(p, v), law.td()(p, v)});
    }
  BOOST_TEST_MESSAGE("min of the Table 6.1 surfaces over the domain: " << lo);
  BOOST_TEST(lo > 0.0);
}

BOOST_AUTO_TEST_CASE(clamps_and_counts) {
  const auto law = table_6_1();
  std::vector<double> st(7, 0.0);
  friction::ContactState s;
  s.state = st.data();
  struct Case { double p, v, rp, rv; };
  for (const Case c : {Case{120, 50, 80, 50}, Case{30, 0, 30, 6.35}, Case{30, 300, 30, 101.6}, Case{30, 50, 30, 50}}) {
    s.pressure = c.p;
    s.slip_speed = c.v;
    const auto lim = law.limit(s);
    BOOST_TEST(lim.mu1 == law.rd()(c.rp, c.rv), tt::tolerance(1e-13));
    BOOST_TEST(lim.mu2 == law.td()(c.rp, c.rv), tt::tolerance(1e-13));
  }
  const auto n = law.counters(st);
  BOOST_REQUIRE(n.size() == 4u);
  BOOST_TEST(n[0].second == 4.0);  // evaluations
  BOOST_TEST(n[1].second == 1.0);  // pressure
  BOOST_TEST(n[2].second == 1.0);  // speed below v_min
  BOOST_TEST(n[3].second == 1.0);  // speed above v_max
}

BOOST_AUTO_TEST_CASE(interval_average) {
  const auto law = table_6_1(4);
  std::vector<double> st(7, 0.0);
  friction::ContactState s;
  s.pressure = 40;
  s.state = st.data();
  const double speeds[4] = {10, 30, 10, 30}, expect[4] = {10, 20, 50.0 / 3.0, 20};
  for (int k = 0; k < 4; ++k) {
    s.slip_speed = speeds[k];
    BOOST_TEST(law.limit(s).mu1 == law.rd()(40, expect[k]), tt::tolerance(1e-13));
  }
  for (double v : {0.0, 90.0, 7.0}) {
    s.slip_speed = v;
    BOOST_TEST(law.limit(s).mu1 == law.rd()(40, 20), tt::tolerance(1e-13));
  }
  BOOST_CHECK_THROW(table_6_1(0), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(from_lines_gives_table_6_1) {
  const auto [rd, td] = friction::load_surface_lines(kData + "/thesis/table_5_16.csv", 0, 80);
  const auto [nrd, ntd] = friction::load_surface_nodes(kData + "/thesis/table_6_1.csv", {});
  BOOST_TEST(rd.v_min == 6.35);
  BOOST_TEST(rd.v_max == 101.6);
  for (int k = 0; k < 9; ++k) {
    BOOST_TEST(std::abs(rd.mu[k] - nrd.mu[k]) < 2e-4);
    BOOST_TEST(std::abs(td.mu[k] - ntd.mu[k]) < 2e-4);
  }
}

static std::string temp_csv(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / ("drawbend_test_" + name + ".csv");
  std::ofstream(p) << text;
  return p.string();
}

static void expect_error(const std::function<void()>& f, const std::string& must_contain) {
  try {
    f();
    BOOST_ERROR("no error; expected one containing '" << must_contain << "'");
  } catch (const InputError& e) {
    BOOST_TEST_MESSAGE(e.what());
    BOOST_TEST(std::string(e.what()).find(must_contain) != std::string::npos, "message: " << e.what());
  }
}

BOOST_AUTO_TEST_CASE(file_validation) {
  std::string rows = "node,mu_RD,mu_TD\n";
  for (int k : {1, 2, 3, 5, 4, 6, 7, 8, 9}) rows += std::to_string(k) + ",0.1,0.05\n";
  const auto swapped = temp_csv("swapped", rows);
  expect_error([&] { friction::load_surface_nodes(swapped, {}); }, swapped + ":5: column 'node'");
  std::string neg = "node,mu_RD,mu_TD\n";
  for (int k = 1; k <= 9; ++k) neg += std::to_string(k) + "," + (k == 6 ? "-0.01" : "0.1") + ",0.05\n";
  const auto negative = temp_csv("negative", neg);
  expect_error([&] { friction::load_surface_nodes(negative, {}); }, negative + ":7: column 'mu_RD'");
  const auto lines = temp_csv("lines", "direction,speed_mm_s,a0,a1_per_MPa\nRD,6.35,0.01,0.002\nRD,101.6,0.02,0.001\n"
                                       "RD,25.4,0.02,0.001\nTD,6.35,0.01,0.001\nTD,25.4,0.01,0.001\nTD,101.6,0.01,0.001\n");
  expect_error([&] { friction::load_surface_lines(lines, 0, 80); }, lines + ":4: column 'speed_mm_s'");
}

// One face (nodes 0-3, counter-clockwise seen from +z) and its texture axis after moving it by f.
static contact::Vec3 moved(const std::function<contact::Vec3(const contact::Vec3&)>& f, const contact::Vec3& rd) {
  fe::Mesh m;
  m.x = {0, 1, 1, 0};
  m.y = {0, 0, 1, 1};
  m.z = {0, 0, 0, 0};
  m.face_sets["f"] = {{0, 1, 2, 3}};
  const auto refs = contact::texture_refs(m.face_set("f"), m.x.data(), m.y.data(), m.z.data(), {0, 1, 2, 3}, rd, "f");
  std::vector<double> x(4), y(4), z(4);
  for (int i = 0; i < 4; ++i) {
    const auto p = f({m.x[i], m.y[i], m.z[i]});
    x[i] = p[0];
    y[i] = p[1];
    z[i] = p[2];
  }
  const auto e = contact::texture_axis(refs[2], x.data(), y.data(), z.data());
  BOOST_TEST_MESSAGE("e1 = (" << e[0] << ", " << e[1] << ", " << e[2] << ")");
  return e;
}

BOOST_AUTO_TEST_CASE(corotational_axis) {
  const double a = 35 * M_PI / 180;
  auto e = moved([&](const contact::Vec3& p) {
    return contact::Vec3{p[0] * std::cos(a) - p[1] * std::sin(a) + 3, p[0] * std::sin(a) + p[1] * std::cos(a) - 1, p[2]};
  }, {1, 0, 0});
  BOOST_TEST(e[0] == std::cos(a), tt::tolerance(1e-12));
  BOOST_TEST(e[1] == std::sin(a), tt::tolerance(1e-12));
  BOOST_TEST(std::abs(e[2]) < 1e-12);
  // Simple shear x += g y: polar rotation angle -atan(g/2).
  e = moved([](const contact::Vec3& p) { return contact::Vec3{p[0] + 0.5 * p[1], p[1], p[2]}; }, {1, 0, 0});
  const double w = -std::atan(0.25);
  BOOST_TEST(e[0] == std::cos(w), tt::tolerance(1e-12));
  BOOST_TEST(e[1] == std::sin(w), tt::tolerance(1e-12));
  // Bent 90 deg about y: (x, y, z) -> (z, y, -x).
  e = moved([](const contact::Vec3& p) { return contact::Vec3{p[2], p[1], -p[0]}; }, {1, 0, 0});
  BOOST_TEST(std::abs(e[0]) < 1e-12);
  BOOST_TEST(std::abs(e[1]) < 1e-12);
  BOOST_TEST(e[2] == -1.0, tt::tolerance(1e-12));
}

// The example deck, with its relative paths made absolute and one substitution.
static std::string deck_with(const std::string& from, const std::string& to) {
  std::string text = read_file(kData + "/cases/block_surface.toml");
  for (const std::string rel : {"../thesis/", "../materials/"})
    for (auto at = text.find(rel); at != std::string::npos; at = text.find(rel))
      text.replace(at, rel.size(), kData + "/" + rel.substr(3));
  const auto at = text.find(from);
  BOOST_REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  const auto p = std::filesystem::temp_directory_path() / "drawbend_test_deck.toml";
  std::ofstream(p) << text;
  return p.string();
}

BOOST_AUTO_TEST_CASE(deck_reader) {
  const auto ok = io::read_deck(deck_with("texture = \"fixed\"", "texture = \"corotational\""));
  BOOST_REQUIRE(ok.model.contacts.size() == 1u);
  BOOST_TEST((ok.model.contacts[0].texture == fe::ContactPair::Texture::corotational));
  const auto* law = dynamic_cast<const friction::SurfaceLaw*>(ok.model.contacts[0].friction.get());
  BOOST_REQUIRE(law);
  BOOST_TEST(law->interval() == 100);
  BOOST_TEST(law->at(80, 6.35).mu1 == 0.2142, tt::tolerance(1e-12));
  expect_error([] { io::read_deck(deck_with("texture = \"fixed\"", "texture = \"sideways\"")); }, "contact.texture");
  std::string rows = "node,mu_RD,mu_TD\n";
  for (int k : {1, 2, 3, 4, 5, 6, 8, 7, 9}) rows += std::to_string(k) + ",0.1,0.05\n";
  const auto bad = temp_csv("deck_nodes", rows);
  expect_error([&] { io::read_deck(deck_with(kData + "/thesis/table_6_1.csv", bad)); },
               "contact.friction.nodes: " + bad + ":8: column 'node'");
  expect_error([] { io::read_deck(deck_with("interval = 100", "interval = 100, lines = \"x.csv\"")); },
               "exactly one of 'nodes'");
}
