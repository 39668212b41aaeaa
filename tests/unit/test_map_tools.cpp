// Contact-map reductions and the draw-bend builder (src/sim).
// Closed-form answers:
//  - contact arc of a row whose pressure is 0 at 0 deg, 10 at 10 deg, ..., 0 at
//    90 deg with threshold 5 MPa: the crossings are interpolated at 5 deg and
//    85 deg, an arc of 80 deg;
//  - peaks of that row: entry maximum before 45 deg, exit maximum after;
//  - area by pressure: nodes of 1 mm^2 at 5, 15, 15, 25 MPa with bins [0,10),
//    [10,20), [20,...) give 1, 2, 1 mm^2, and nodes at zero pressure count nowhere;
//  - the builder's deck parses, and its wrap length is (D/2 + t/2) pi/2;
//  - the heat-map grid: rows at y = 0 (nodes at 0, 10, 20 deg, p = 0, 10, 0)
//    and y = 5 (nodes at 5, 15, 25 deg, p = 0, 20, 0) share one angle grid of
//    5 deg steps (half the 10 deg spacing) from 0 to 25 deg; the y = 5 row
//    reads 0 at 0 deg (before its first node) and 10 at 10 deg (halfway up).
#define BOOST_TEST_MODULE map_tools
#include <boost/test/unit_test.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "core/csv.hpp"
#include "io/deck.hpp"
#include "sim/drawbend_case.hpp"
#include "sim/map_tools.hpp"

using namespace drawbend;

namespace {
sim::Row ramp_row() {
  sim::Row r;
  const double p[] = {0, 10, 20, 15, 8, 12, 25, 30, 10, 0};
  for (int i = 0; i < 10; ++i) r.nodes.push_back({10.0 * i, 0.0, p[i], 1.0});
  return r;
}
}  // namespace

BOOST_AUTO_TEST_CASE(contact_arc_interpolates_crossings) {
  const auto a = sim::contact_arc(ramp_row(), 5.0);
  BOOST_TEST(a.start_deg == 5.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(a.end_deg == 85.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(a.angle() == 80.0, boost::test_tools::tolerance(1e-12));
  sim::Row none;
  none.nodes = {{0, 0, 0, 1}, {10, 0, 0, 1}};
  BOOST_TEST(sim::contact_arc(none, 1.0).angle() == 0.0);
}

BOOST_AUTO_TEST_CASE(entry_exit_peaks_and_middle) {
  const auto p = sim::peaks(ramp_row());
  BOOST_TEST(p.entry == 20.0);
  BOOST_TEST(p.entry_deg == 20.0);
  BOOST_TEST(p.exit == 30.0);
  BOOST_TEST(p.exit_deg == 70.0);
  BOOST_TEST(p.middle == 10.0, boost::test_tools::tolerance(1e-12));  // halfway between 8 (40 deg) and 12 (50 deg)
}

BOOST_AUTO_TEST_CASE(area_by_pressure_bins) {
  const std::vector<sim::MapNode> m{{0, 0, 5, 1}, {1, 0, 15, 1}, {2, 0, 15, 1}, {3, 0, 25, 1}, {4, 0, 0, 7}};
  const auto a = sim::area_by_pressure(m, {0, 10, 20});
  BOOST_TEST(a[0] == 1.0);
  BOOST_TEST(a[1] == 2.0);
  BOOST_TEST(a[2] == 1.0);
}

BOOST_AUTO_TEST_CASE(rows_group_by_y) {
  const std::vector<sim::MapNode> m{{20, 1.0, 1, 1}, {10, 0.0, 2, 1}, {0, 1.0, 3, 1}, {0, 0.0, 4, 1}};
  const auto rows = sim::rows_of(m);
  BOOST_TEST(rows.size() == 2u);
  BOOST_TEST(rows[0].y == 0.0);
  BOOST_TEST(rows[0].nodes[0].pressure == 4.0);  // sorted by angle
  BOOST_TEST(rows[1].nodes[1].angle_deg == 20.0);
}

BOOST_AUTO_TEST_CASE(builder_deck_parses) {
  sim::DrawBendSpec s;
  s.pin_diameter = 25.4;
  s.friction = io::coulomb_friction(0.1);
  s.hardening = std::string(DRAWBEND_DATA_DIR) + "/materials/aa5754_o_rd.csv";
  const io::Deck d = io::parse_deck(sim::deck_text(s), "builder.toml");
  BOOST_TEST(d.model.steps.size() == 3u);
  BOOST_TEST(sim::wrap_length(s) == (12.7 + 0.52) * M_PI / 2, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(sim::draw_length(s) == 1.5 * sim::wrap_length(s) + 6.0, boost::test_tools::tolerance(1e-12));
  sim::DrawBendSpec bad = s;
  bad.pin_diameter = -1;
  BOOST_CHECK_THROW(sim::deck_text(bad), InputError);
}

BOOST_AUTO_TEST_CASE(map_grid_is_regular_in_angle) {
  std::vector<sim::MapNode> map;
  for (int i = 0; i < 3; ++i) {
    map.push_back({10.0 * i, 0.0, i == 1 ? 10.0 : 0.0, 1.0});
    map.push_back({5.0 + 10.0 * i, 5.0, i == 1 ? 20.0 : 0.0, 1.0});
  }
  const std::string path = (std::filesystem::temp_directory_path() / "drawbend_map_grid.dat").string();
  sim::save_map_grid(map, path, "test");
  std::istringstream in(read_file(path));
  std::string line;
  std::vector<std::vector<std::array<double, 3>>> blocks(1);
  while (std::getline(in, line)) {
    if (line.empty()) {
      blocks.emplace_back();
      continue;
    }
    if (line[0] == '#') continue;
    std::array<double, 3> v{};
    std::sscanf(line.c_str(), "%lf,%lf,%lf", &v[0], &v[1], &v[2]);
    blocks.back().push_back(v);
  }
  while (!blocks.empty() && blocks.back().empty()) blocks.pop_back();
  BOOST_TEST_REQUIRE(blocks.size() == 2u);
  BOOST_TEST_REQUIRE(blocks[0].size() == 6u);  // 0, 5, ..., 25 deg
  BOOST_TEST_REQUIRE(blocks[1].size() == 6u);
  for (std::size_t k = 0; k < 6; ++k) {
    BOOST_TEST(blocks[0][k][0] == 5.0 * k);
    BOOST_TEST(blocks[1][k][0] == 5.0 * k);  // the same angles in every row
  }
  BOOST_TEST(blocks[1][0][2] == 0.0);
  BOOST_TEST(blocks[1][2][2] == 10.0);  // y = 5 row at 10 deg: halfway from 0 (5 deg) to 20 (15 deg)
  BOOST_TEST(blocks[0][2][2] == 10.0);  // y = 0 row at its node
}
