// The far-from-noise rule (LoopOptions::far_ratio, far_share; loop.cpp
// forward_round), on wild development sets (spent seeds, heldout_record.md
// h50-cvperm and h50-far), written as a lab file and read back as the CLI
// reads it, stand-in maps, the loop's defaults otherwise (far_ratio 2, three
// contenders gated by half the first's gain, since h50-fardefault; the cases
// set far_ratio themselves, -1 keeps the default).  Expected answers:
//  - set 57600044 (wild interaction: mu + 0.1 a g of ra_strip_um at speed 10
//    mm/s only, k 5.7, noise 8 N): the permutation screen passes no column
//    (ra_strip_um p 0.003 against 0.05 / 31), so with far_ratio 0 the loop adds
//    no step and ends above 4 x the true noise; with the rule (held-out RMS
//    6.7 x the measured noise, above 2 x) the first step is ra_strip_um, taken
//    by the rule (far_note set), and the held-out RMS ends within 2 x the true
//    noise (1.05 x measured).
//  - set 57600002 (ra_strip_um on the bending force in one direction, noise
//    3 N; 90 % of its effect in two tests): the rule's first step takes more
//    than half of the excess MSE over the noise; every later candidate takes
//    less, so the rule adds exactly one step (three contenders and no share
//    gate took six, five of them decoys: heldout_record.md, h50-far), and no
//    step names another column of the data.  A later step on the model's
//    own inputs (class "base model") is not the rule's and not a decoy: since
//    h50-forcecell the first step is ra_strip_um's force in that direction
//    only (its own channel), and the pressure law (pressure_mu) then passes
//    the screen as a second step (measured 2026-12-06: 2.90 x the noise,
//    main 3.98 x with one step).
//  - the default options are the rule on (far_ratio 2): set 57600044 with
//    LoopOptions{} untouched gives ra_strip_um as above (main before
//    h50-fardefault: no step).
//  - set 51400034 (wild test-level, one supporting test, noise 8 N; a
//    development set of h50-farsimple): with far_max_params 100 the rule's
//    step is a 25-parameter smooth per direction of a decoy column
//    (oil_age_days); with the default 9, no step the rule takes has more
//    than 9 parameters.
//  - null set 57600005 (noise 3 N): the base model's held-out RMS is within
//    1.25 x the noise, so the rule cannot fire: no step with a far note.
// The sanitizer step (main_run_only.hpp) runs the first and the last case:
// the rule's path, on and off, and a set where it cannot fire.  The other
// three run the same path on other sets and options (166 of the 208 s this
// test took there, 2026-12-05); the main run checks their answers.
#define BOOST_TEST_MODULE loop_far
#include <boost/test/unit_test.hpp>

#include "loop/loop.hpp"
#include "loop/maps.hpp"
#include "loop/measured.hpp"
#include "loop/wild_synth.hpp"
#include "lab_file.hpp"
#include "main_run_only.hpp"

using namespace drawbend::loop;

namespace {

struct Run {
  LoopResult r;
  double noise = 0;
};

Run loop_on_wild(const std::string& cls, double noise, std::uint64_t seed, double far_ratio, int far_max_params = -1) {
  BlindTruth t;
  const Dataset d = drawbend::test::lab_file(synthesize_wild({cls, noise, seed}, t), "far_" + std::to_string(seed) + ".csv");
  const MapLibrary maps = drawbend::test::stand_in_maps(d);
  LoopOptions o;
  if (far_ratio >= 0) o.far_ratio = far_ratio;
  if (far_max_params >= 0) o.far_max_params = far_max_params;
  return {run_loop(make_design(d, maps), o), noise};
}

int far_steps(const LoopResult& r) {
  int n = 0;
  for (const auto& s : r.steps) n += !s.far_note.empty();
  return n;
}

}  // namespace

BOOST_AUTO_TEST_CASE(one_cell_effect_found_by_the_rule) {
  const Run off = loop_on_wild("interaction", 8.0, 57600044, 0.0);
  BOOST_TEST(off.r.steps.empty());
  BOOST_TEST(off.r.cv.back().rms / off.noise > 4.0);
  const Run on = loop_on_wild("interaction", 8.0, 57600044, 2.0);
  BOOST_REQUIRE(!on.r.steps.empty());
  BOOST_TEST(on.r.steps[0].variable == "ra_strip_um");
  BOOST_TEST(!on.r.steps[0].far_note.empty());
  BOOST_TEST(on.r.cv.back().rms / on.noise <= 2.0);
}

BOOST_AUTO_TEST_CASE(the_rule_is_the_default, *drawbend::test::main_run_only()) {
  BOOST_TEST(LoopOptions{}.far_ratio == 2.0);
  const Run def = loop_on_wild("interaction", 8.0, 57600044, -1.0);
  BOOST_REQUIRE(!def.r.steps.empty());
  BOOST_TEST(def.r.steps[0].variable == "ra_strip_um");
  BOOST_TEST(!def.r.steps[0].far_note.empty());
  BOOST_TEST(def.r.cv.back().rms / def.noise <= 2.0);
}

BOOST_AUTO_TEST_CASE(the_share_gate_stops_decoys, *drawbend::test::main_run_only()) {
  const Run on = loop_on_wild("interaction", 3.0, 57600002, 2.0);
  BOOST_REQUIRE(!on.r.steps.empty());
  BOOST_TEST(on.r.steps[0].variable == "ra_strip_um");
  BOOST_TEST(far_steps(on.r) == 1);
  for (size_t k = 1; k < on.r.steps.size(); ++k)
    BOOST_TEST(on.r.steps[k].cls == "base model", "step " << k + 1 << ": " << on.r.steps[k].variable);
}

BOOST_AUTO_TEST_CASE(the_rule_takes_simple_forms_only, *drawbend::test::main_run_only()) {
  BOOST_TEST(LoopOptions{}.far_max_params == 9);
  const Run wide = loop_on_wild("test-level", 8.0, 51400034, -1.0, 100);
  int widest = 0;
  for (const auto& s : wide.r.steps)
    if (!s.far_note.empty()) widest = std::max(widest, static_cast<int>(s.params.size()));
  BOOST_TEST(widest == 25);
  const Run simple = loop_on_wild("test-level", 8.0, 51400034, -1.0);
  BOOST_TEST(far_steps(simple.r) >= 1);
  for (const auto& s : simple.r.steps)
    if (!s.far_note.empty()) BOOST_TEST(s.params.size() <= 9u);
}

BOOST_AUTO_TEST_CASE(null_set_never_fires) {
  const Run on = loop_on_wild("null", 3.0, 57600005, 2.0);
  BOOST_TEST(far_steps(on.r) == 0);
  BOOST_TEST(on.r.cv.front().rms / on.noise <= 1.25);
}
