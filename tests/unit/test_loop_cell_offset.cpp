// The one-cell forms' own factor (Effect::cell_offset; forms.cpp in_cell and
// union_of_cells), on wild development set 51600044 (spent: heldout_record.md
// h50-bend's check, read after it; an effect on mu in the 12.7 mm pin only,
// mu (1 + a g), g random levels of the three-valued column pre_strain_pct,
// k 4.1, noise 8 N), written as a lab file and read back as the CLI reads it,
// stand-in maps.  Expected answers:
//  - Closed form (invariance).  A factor level is numbered by its first
//    appearance in the file (Design::levels).  With its own factor the
//    one-cell levels form spans every level of the cell, so its model space,
//    hence its least-squares fit, does not depend on which level comes first:
//    moving the first test of another level to the top of the file leaves the
//    residual sum of squares the same (to 1e-6 relative: the sums run in
//    another order).  Without it (main's form) the first level is held at mu
//    itself and the fit changes with the file's order (measured: RSS 7.18e5
//    against 1.06e5 N^2; with its own factor 5.46e4 both ways; asked: more
//    than 1 % apart).
//  - The loop (defaults): the first step is pre_strain_pct and the held-out
//    RMS ends within 2 x the true noise (measured 1.04 x; main 3.15 x, its step
//    a bending-force offset on every pin, its one-cell form holding out at
//    30.0 N).
#define BOOST_TEST_MODULE loop_cell_offset
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>

#include "loop/loop.hpp"
#include "loop/maps.hpp"
#include "loop/measured.hpp"
#include "loop/model.hpp"
#include "loop/wild_synth.hpp"
#include "lab_file.hpp"

using namespace drawbend::loop;

namespace {

const std::uint64_t kSeed = 51600044;

// The residual sum of squares of the base model with pre_strain_pct's levels in the 12.7 mm pin only.
double rss_in_cell(const Dataset& ds, bool own_factor) {
  const Design d = make_design(ds, drawbend::test::stand_in_maps(ds));
  int n = 0;
  const std::vector<int> g = d.groups("pin", &n);
  int cell = -1;
  for (size_t i = 0; i < ds.rows.size(); ++i)
    if (std::abs(ds.rows[i].pin_d_mm - 12.7) < 1e-9) cell = g[i];
  BOOST_REQUIRE(cell >= 0);
  std::vector<std::string> names;
  d.levels("pre_strain_pct", &names);
  ModelSpec s;
  s.bending_linear = true;
  Effect e;
  e.kind = EffectKind::categorical_by;
  e.variable = "pre_strain_pct";
  e.by = "pin";
  e.n_groups = n;
  e.n_levels = static_cast<int>(names.size());
  e.cell = cell;
  e.cell_offset = own_factor;
  s.effects.push_back(e);
  return fit_model(d, s).rss;
}

}  // namespace

BOOST_AUTO_TEST_CASE(own_factor_makes_the_fit_independent_of_the_first_level) {
  BlindTruth t;
  const Dataset ds = drawbend::test::lab_file(synthesize_wild({"interaction", 8.0, kSeed}, t), "cell_offset_" + std::to_string(kSeed) + ".csv");
  const Dataset moved = drawbend::test::another_level_first(ds, "pre_strain_pct");
  const double a = rss_in_cell(ds, true), b = rss_in_cell(moved, true);
  BOOST_TEST_MESSAGE("own factor: RSS " << a << " and " << b << " N^2");
  BOOST_TEST(std::abs(a - b) <= 1e-6 * a);
  const double a0 = rss_in_cell(ds, false), b0 = rss_in_cell(moved, false);
  BOOST_TEST_MESSAGE("without: RSS " << a0 << " and " << b0 << " N^2");
  BOOST_TEST(std::abs(a0 - b0) > 0.01 * std::min(a0, b0));
  BOOST_TEST(a <= std::min(a0, b0) * (1 + 1e-9));  // a larger model space fits no worse
}

BOOST_AUTO_TEST_CASE(the_loop_finds_the_one_pin_effect) {
  BlindTruth t;
  const Dataset ds = drawbend::test::lab_file(synthesize_wild({"interaction", 8.0, kSeed}, t), "cell_offset_" + std::to_string(kSeed) + ".csv");
  const LoopResult r = run_loop(make_design(ds, drawbend::test::stand_in_maps(ds)), LoopOptions{});
  BOOST_REQUIRE(!r.steps.empty());
  BOOST_TEST_MESSAGE("first step " << r.steps[0].variable << ", held-out RMS " << r.cv.back().rms / 8.0 << " x the noise");
  BOOST_TEST(r.steps[0].variable == "pre_strain_pct");
  BOOST_TEST(r.cv.back().rms / 8.0 <= 2.0);
}
