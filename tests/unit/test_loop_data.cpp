// Measured-data reading and pressure maps of the loop (src/loop).
// Known answers:
//  - tests/loop/bad_rows.csv has 10 data rows; lines 6-12 each carry one kind of
//    bad data (unparseable, NaN, duplicate of line 5, outlet < back tension on a
//    fixed pin, negative force, ragged, unknown pin kind): 7 problems, each
//    naming file:line and (where it applies) the column; 3 rows kept, in
//    canonical order (test_id in natural order, then time, sliding, back
//    tension): f2 (line 14), r1 at 1500 N (line 5), r1 at 1700 N (line 13).
//  - canonical order: the same rows in any file order parse to the same
//    sequence; ids "T2" < "T10" < "t10b" (digit runs as numbers, "T" < "t");
//    within a test by time_s.
//  - a file without outlet_force_N: one "required column missing" problem, 0 rows.
//  - FE map directory with pin_12.7mm.csv, pressures 1 and 2 MPa, half-model
//    areas 1 mm^2, reference 1000 N: full-strip S1 = 2(1+2) = 6 N,
//    S2 = 2(1+4) = 10, weighted pressure at 1000 N = 10/6 MPa, at 2000 N 20/6.
//  - stand-in map: belt pressure F_ref/(R w) plus edge peaks, so its weighted
//    pressure exceeds the belt value and scales linearly with back tension.
#define BOOST_TEST_MODULE loop_data
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "loop/maps.hpp"
#include "loop/measured.hpp"

using namespace drawbend;
using namespace drawbend::loop;
namespace tt = boost::test_tools;
namespace fs = std::filesystem;

static bool has_problem(const Dataset& d, int line, const std::string& column, const std::string& text) {
  for (const auto& p : d.problems)
    if (p.line == line && p.column == column && p.message.find(text) != std::string::npos) return true;
  return false;
}

BOOST_AUTO_TEST_CASE(bad_rows_reported_in_one_pass) {
  const std::string path = std::string(DRAWBEND_TEST_DIR) + "/loop/bad_rows.csv";
  const Dataset d = read_measured(path);
  BOOST_TEST(d.rows_read == 10);
  BOOST_TEST(d.rows.size() == 3u);
  BOOST_TEST(d.rows_dropped == 7);
  BOOST_TEST(d.problems.size() == 7u);
  BOOST_TEST(has_problem(d, 6, "outlet_force_N", "'abc' is not a number"));
  BOOST_TEST(has_problem(d, 7, "back_tension_N", "not a finite number"));
  BOOST_TEST(has_problem(d, 8, "", "duplicate of line 5"));
  BOOST_TEST(has_problem(d, 9, "outlet_force_N", "below back tension"));
  BOOST_TEST(has_problem(d, 10, "back_tension_N", "negative force"));
  BOOST_TEST(has_problem(d, 11, "", "has 7 cells"));
  BOOST_TEST(has_problem(d, 12, "pin", "neither 'fixed' nor 'rotating'"));
  BOOST_TEST(d.problems[0].str().find("bad_rows.csv:6: column 'outlet_force_N'") != std::string::npos);
  BOOST_TEST(d.extra_columns.size() == 1u);
  BOOST_TEST(d.extra_columns[0] == "test_order");
  BOOST_TEST(d.rows[0].line == 14);
  BOOST_TEST(d.rows[1].line == 5);
  BOOST_TEST(d.rows[2].line == 13);
}

BOOST_AUTO_TEST_CASE(rows_in_canonical_order_whatever_the_file_order) {
  const std::string head = "test_id,pin_diameter_mm,pin,direction_deg,speed_mm_s,lubricant,back_tension_N,outlet_force_N,time_s,coil\n";
  const std::vector<std::string> rows = {
      "T10,12.7,fixed,0,25.4,oil,1500,1800,2.0,A\n", "T2,12.7,fixed,0,25.4,oil,1600,1900,1.0,B\n",
      "T10,12.7,fixed,0,25.4,oil,1400,1750,1.0,A\n", "t10b,12.7,fixed,0,25.4,oil,1500,1850,0.5,C\n",
      "T2,12.7,fixed,0,25.4,oil,1500,1810,2.0,B\n"};
  std::string forward = head, backward = head;
  for (size_t i = 0; i < rows.size(); ++i) forward += rows[i], backward += rows[rows.size() - 1 - i];
  const Dataset a = parse_measured(forward, "forward.csv"), b = parse_measured(backward, "backward.csv");
  BOOST_REQUIRE(a.rows.size() == 5u);
  BOOST_REQUIRE(b.rows.size() == 5u);
  const std::vector<std::pair<std::string, double>> expect = {
      {"T2", 1.0}, {"T2", 2.0}, {"T10", 1.0}, {"T10", 2.0}, {"t10b", 0.5}};
  for (size_t i = 0; i < 5; ++i) {
    BOOST_TEST(a.rows[i].test_id == expect[i].first);
    BOOST_TEST(a.rows[i].time_s == expect[i].second);
    BOOST_TEST(b.rows[i].test_id == a.rows[i].test_id);
    BOOST_TEST(b.rows[i].back_tension_N == a.rows[i].back_tension_N);
    BOOST_TEST(b.rows[i].extra == a.rows[i].extra);
    BOOST_TEST(b.rows[i].line == 8 - a.rows[i].line);  // each row keeps its own file line (2-6)
  }
}

BOOST_AUTO_TEST_CASE(missing_required_column) {
  const std::string path = (fs::temp_directory_path() / "drawbend_loop_missing.csv").string();
  std::ofstream(path) << "test_id,pin_diameter_mm,pin,direction_deg,speed_mm_s,lubricant,back_tension_N\n"
                         "a,12.7,fixed,0,25.4,oil,1500\n";
  const Dataset d = read_measured(path);
  BOOST_TEST(d.rows.empty());
  BOOST_TEST(d.rows_dropped == 1);
  BOOST_TEST(has_problem(d, 1, "outlet_force_N", "required column missing"));
  BOOST_CHECK_THROW(read_measured("/nonexistent/x.csv"), InputError);
}

BOOST_AUTO_TEST_CASE(fe_map_directory) {
  const fs::path dir = fs::temp_directory_path() / "drawbend_loop_maps";
  fs::create_directories(dir);
  std::ofstream(dir / "pin_12.7mm.csv") << "# reference_back_tension_N: 1000\n"
                                           "node,x_mm,y_mm,z_mm,surface,u_tool,v_tool_mm,pressure_MPa,area_mm2,normal_force_N\n"
                                           "1,0,0,0,pin,0,0,1,1,1\n2,0,0,0,pin,0,0,2,1,2\n3,0,0,0,pin,0,0,0,1,0\n";
  const MapLibrary lib = MapLibrary::load_dir(dir.string());
  const PinMap& m = lib.at(12.7);
  BOOST_TEST(m.S1 == 6.0, tt::tolerance(1e-12));
  BOOST_TEST(m.S2 == 10.0, tt::tolerance(1e-12));
  BOOST_TEST(m.weighted_pressure(1000) == 10.0 / 6.0, tt::tolerance(1e-12));
  BOOST_TEST(m.weighted_pressure(2000) == 20.0 / 6.0, tt::tolerance(1e-12));
  BOOST_TEST(!lib.is_stand_in());
  BOOST_CHECK_THROW(lib.at(25.4), InputError);
}

BOOST_AUTO_TEST_CASE(stand_in_maps) {
  StandInParams p;
  const MapLibrary lib = MapLibrary::stand_in({12.7, 42});
  BOOST_TEST(lib.is_stand_in());
  BOOST_TEST(lib.label().find("analytic stand-in, not FE") != std::string::npos);
  for (double d : {12.7, 42.0}) {
    const PinMap& m = lib.at(d);
    const double belt = p.fref_N / (d / 2 * p.width_mm);
    BOOST_TEST(m.weighted_pressure(p.fref_N) > belt);
    BOOST_TEST(m.weighted_pressure(2 * p.fref_N) == 2 * m.weighted_pressure(p.fref_N), tt::tolerance(1e-12));
    BOOST_TEST(m.map.label.find("not FE") != std::string::npos);
  }
}
