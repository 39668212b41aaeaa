// The model-level loop's inputs (src/sim/model_loop.hpp), without FE runs.
// Closed-form answers:
//  - a measured CSV with 2 good rows reads as 2 points (full strip values kept);
//  - a row with a non-number and a row with a negative force are both named
//    by file:line in one InputError;
//  - spec_for_point halves the back tension (1500 N full strip -> 750 N half)
//    and sets the pin (25.4 mm);
//  - "split:0.3/0.6" is two members whose material is j2_combined with
//    beta = 0.3 and 0.6; "ms:2500" sets mass scaling 2500; "across:4" sets 4;
//    unknown names, beta 1.5 and across 2.5 are input errors;
//  - a loop whose points all lie on the fit pin has nothing held out: an
//    input error before any run.
#define BOOST_TEST_MODULE model_loop
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/csv.hpp"
#include "sim/model_loop.hpp"

using namespace drawbend;

namespace {
std::string write_tmp(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / name;
  std::ofstream(p) << text;
  return p.string();
}
}  // namespace

BOOST_AUTO_TEST_CASE(reads_points) {
  const auto p = write_tmp("ml_good.csv", "# c\npin_diameter_mm,back_tension_N,bending_force_N\n12.7,1500,303.1\n42,1900,47.7\n");
  const auto pts = sim::read_fb_points(p);
  BOOST_REQUIRE_EQUAL(pts.size(), 2u);
  BOOST_TEST(pts[1].pin_mm == 42.0);
  BOOST_TEST(pts[0].bending_N == 303.1);
}

BOOST_AUTO_TEST_CASE(bad_rows_named) {
  const auto p = write_tmp("ml_bad.csv", "pin_diameter_mm,back_tension_N,bending_force_N\n12.7,abc,303\n25.4,1800,-1\n");
  try {
    sim::read_fb_points(p);
    BOOST_FAIL("no error");
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("ml_bad.csv:2") != std::string::npos);
    BOOST_TEST(m.find("ml_bad.csv:3") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(spec_and_candidates) {
  sim::DrawBendSpec base;
  const auto s = sim::spec_for_point(base, {25.4, 1500, 100, ""});
  BOOST_TEST(s.back_tension == 750.0);
  BOOST_TEST(s.pin_diameter == 25.4);
  const auto c = sim::named_candidate("split:0.3/0.6", "/data");
  BOOST_REQUIRE_EQUAL(c.members.size(), 2u);
  sim::DrawBendSpec t = base;
  c.members[1].apply(t);
  BOOST_TEST(t.material == "{ type = \"j2_combined\", kinematic = { beta = 0.6 } }");
  t = base;
  sim::named_candidate("ms:2500", "/data").members[0].apply(t);
  BOOST_TEST(t.mass_scaling == 2500.0);
  sim::named_candidate("across:4", "/data").members[0].apply(t);
  BOOST_TEST(t.across == 4);
  BOOST_CHECK_THROW(sim::named_candidate("chaboche", "/data"), InputError);
  BOOST_CHECK_THROW(sim::named_candidate("split:1.5", "/data"), InputError);
  BOOST_CHECK_THROW(sim::named_candidate("split:0.3/x", "/data"), InputError);
  BOOST_CHECK_THROW(sim::named_candidate("across:2.5", "/data"), InputError);
}

BOOST_AUTO_TEST_CASE(nothing_held_out) {
  sim::ModelLoopConfig cfg;
  cfg.fit_pin = 12.7;
  cfg.run_root = (std::filesystem::temp_directory_path() / "ml_none").string();
  BOOST_CHECK_THROW(sim::run_model_loop(sim::DrawBendSpec{}, {{12.7, 1500, 303, ""}}, {}, cfg), InputError);
}
