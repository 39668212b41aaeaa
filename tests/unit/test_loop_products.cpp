// A column that changes how mu depends on the pressure or on the speed
// (forms.cpp FormPlans::products; Effect::times and Effect::level_basis), on
// wild development sets (spent seeds: heldout_record.md, h50-colorder's check,
// read after it), written as a lab file and read back as the CLI reads it,
// stand-in maps, the loop's defaults (the forms on by default since
// h50-prodtie, heldout_record.md).  Expected answers:
//  - Closed form: Design::values of the two multipliers on every row,
//    nominal_pressure_MPa = Eq. 2.2 at F_x = F_y = F_back, i.e. F_back / (r w)
//    with r the pin radius and w = 25.4 mm (1000 N on the 12.7 mm pin:
//    6.2000 MPa), and ln_speed_mm_s = ln(v).
//  - Closed form (invariance).  A level is numbered by its first appearance
//    in the file (Design::levels).  The level basis is an indicator per level
//    but the first, centred, so it spans the centred indicators of every
//    level whichever comes first: moving the first test of another level to
//    the top of the file leaves the residual sum of squares of the base model
//    with the levels-times-pressure form the same (to 1e-6 relative: the sums
//    run in another order).
//  - Set 66200003 (wild channel: mu (1 + a g (p / p_mean - 1)), g a peak at
//    the second of surface_grade's four levels, k 3.6, noise 3 N): the first
//    step names surface_grade with its levels times the centred nominal
//    pressure, and the held-out RMS ends within 2 x the true noise (main
//    before the change: a force offset per pin, 2.30 x).
//  - Set 66200039 (wild channel: mu (1 + a g ln(v / v_geo)), g a U over
//    surface_grade's levels, k 3.6, noise 3 N): the first step names
//    surface_grade with its levels times the centred log speed, within 2 x the
//    true noise (main: levels in one speed group, 2.12 x).
//  - On by default, and off when asked: LoopOptions{}.product_forms is true,
//    and the loop with the forms off (--product-forms false) on set 66200003
//    adds no product form (its first step names surface_grade in another
//    form).
// The sanitizer step (main_run_only.hpp) runs the closed forms and the
// pressure-slope case (the forms' path with the option on, 1.9 s here): the
// speed-slope case runs the same path on another set, and the default case
// main's path (10.7 s here).  Under AddressSanitizer the test took 302 s
// with every case and 34 s with this share (2026-12-06, AMD EPYC); the main
// run checks every answer.
#define BOOST_TEST_MODULE loop_products
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <set>

#include "loop/loop.hpp"
#include "loop/maps.hpp"
#include "loop/measured.hpp"
#include "loop/model.hpp"
#include "loop/wild_synth.hpp"
#include "lab_file.hpp"
#include "main_run_only.hpp"

using namespace drawbend::loop;

namespace {

struct Run {
  LoopResult r;
  double noise = 0;
};

Dataset wild_lab(const std::string& cls, double noise, std::uint64_t seed) {
  BlindTruth t;
  return drawbend::test::lab_file(synthesize_wild({cls, noise, seed}, t), "products_" + std::to_string(seed) + ".csv");
}

Run loop_on_wild(const std::string& cls, double noise, std::uint64_t seed, bool products = true) {
  const Dataset d = wild_lab(cls, noise, seed);
  LoopOptions o;
  o.product_forms = products;
  return {run_loop(make_design(d, drawbend::test::stand_in_maps(d)), o), noise};
}

// The first step names `column` with a level-basis effect times `input`.
bool levels_times(const LoopResult& r, const std::string& column, const std::string& input) {
  if (r.steps.empty() || r.steps[0].variable != column) return false;
  for (const auto& e : r.steps[0].added)
    if (e.level_basis && e.times == input) return true;
  return false;
}

double rss_levels_times_pressure(const Dataset& ds, const std::string& column) {
  const Design d = make_design(ds, drawbend::test::stand_in_maps(ds));
  std::vector<std::string> names;
  d.levels(column, &names);
  ModelSpec s;
  Effect e;
  e.kind = EffectKind::generic_smooth;
  e.variable = column;
  e.times = kNominalPressure;
  e.level_basis = true;
  e.n_basis = static_cast<int>(names.size()) - 1;
  s.effects.push_back(e);
  return fit_model(d, s).rss;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_multipliers_closed_form) {
  const Dataset d = wild_lab("null", 3.0, 66200005);
  const Design des = make_design(d, drawbend::test::stand_in_maps(d));
  const std::vector<double> p = des.values(kNominalPressure), lv = des.values(kLnSpeed);
  BOOST_REQUIRE_EQUAL(p.size(), d.rows.size());
  for (size_t i = 0; i < d.rows.size(); ++i) {
    const auto& s = d.rows[i];
    BOOST_TEST(p[i] == s.back_tension_N / (s.pin_d_mm / 2 * 25.4), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(lv[i] == std::log(s.speed_mm_s), boost::test_tools::tolerance(1e-12));
  }
  BOOST_TEST(1000.0 / (12.7 / 2 * 25.4) == 6.2000, boost::test_tools::tolerance(1e-4));
}

BOOST_AUTO_TEST_CASE(level_basis_does_not_depend_on_the_first_level) {
  const Dataset d = wild_lab("channel", 3.0, 66200003);
  const double a = rss_levels_times_pressure(d, "surface_grade");
  const double b = rss_levels_times_pressure(drawbend::test::another_level_first(d, "surface_grade"), "surface_grade");
  BOOST_TEST(std::isfinite(a));
  BOOST_TEST(a == b, boost::test_tools::tolerance(1e-6));
}

BOOST_AUTO_TEST_CASE(levels_change_the_pressure_slope) {
  const Run on = loop_on_wild("channel", 3.0, 66200003);
  BOOST_TEST(levels_times(on.r, "surface_grade", kNominalPressure));
  BOOST_TEST(on.r.cv.back().rms / on.noise <= 2.0);
}

BOOST_AUTO_TEST_CASE(levels_change_the_speed_slope, *drawbend::test::main_run_only()) {
  const Run on = loop_on_wild("channel", 3.0, 66200039);
  BOOST_TEST(levels_times(on.r, "surface_grade", kLnSpeed));
  BOOST_TEST(on.r.cv.back().rms / on.noise <= 2.0);
}

BOOST_AUTO_TEST_CASE(on_by_default_and_off_when_asked, *drawbend::test::main_run_only()) {
  BOOST_TEST(LoopOptions{}.product_forms);
  const Run off = loop_on_wild("channel", 3.0, 66200003, false);
  BOOST_REQUIRE(!off.r.steps.empty());
  BOOST_TEST(off.r.steps[0].variable == "surface_grade");
  for (const auto& s : off.r.steps)
    for (const auto& e : s.added) BOOST_TEST(e.times.empty());
}
