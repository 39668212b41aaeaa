// Chapter 7: closing the loop with measured data.  The thesis's own loop
// (constant mu leaves a pin-ordered residual; mu(p) through pressure maps
// removes it) is rerun as a capability of the software on the thesis data in
// the sample format, followed by one loop beyond the thesis (the 42 mm pin of
// Sec. 5.6 and the bending force against Swift's Eq. 2.1) and by synthetic
// data sets with undeclared effects, which measure whether the loop finds what
// was hidden and invents nothing on null data.
// Forces are full-strip forces in N; pressures MPa; lengths mm; speeds mm/s.
//
// Recipe:
//   1. Load data/measured/thesis_drawbend.csv (and check its generator
//      reproduces it); pressure maps: --maps DIR or the analytic stand-in.
//   2. The maps' moments per pin.
//   3. Demonstration 1: fit at one back tension per test, hold out the others;
//      constant mu vs mu(p) through the maps; residual ordering by pin.
//   4. The automatic loop on the thesis data (all candidates, no hints).
//   5. Demonstration 2a: the 42 mm pin predicted from the 12.7/25.4 mm pins.
//   6. Demonstration 2b: bending force against back tension vs Swift Eq. 2.1.
//   7. Demonstration 2c: the RD/TD crossover at high speed against pin scatter.
//   8. Demonstration 3: synthetic data with hidden effects and null data.
//   9. Demonstration 4: a second, blind generator with seeds and scoring
//      fixed before the first run (heldout_protocol.md; its seeds are
//      development data since heldout_protocol_v2.md).
//  10. Demonstration 5 (held out): generator 1 on fresh seeds and generator 2
//      ("wild") on its own (heldout_protocol_v2.md, heldout_protocol_v2_wild.md).
//
// Sample runs (from the source folder after `make`; the binaries are in build/chapters/):
//   chapter_ch7_closing_the_loop --maps build/chapters/ch4-new-method/maps
//       (as `ctest -R chapter.ch7-closing-the-loop` runs it, on Chapter 4's FE pressure maps)
//   chapter_ch7_closing_the_loop
//       (no --maps: the analytic pressure-map stand-in)
//   chapter_ch7_closing_the_loop --null-seeds 40 --effect-seeds 5
//       (a heavier synthetic sweep; development seeds only)
#include "ch7_steps.hpp"

int main(int argc, char** argv) {
  drawbend::study::Chapter ch("ch7-closing-the-loop", "Chapter 7: closing the loop with measured data");
  ch7::Config cfg;  // the chapter's options
  ch.options().add(cfg.maps_dir, "maps", "directory of FE pressure maps pin_<d>mm.csv (empty: analytic stand-in)");
  ch.options().add(cfg.null_seeds, "null-seeds", "null data sets per noise level");
  ch.options().add(cfg.effect_seeds, "effect-seeds", "data sets per hidden effect and noise level");
  ch.options().add(cfg.permutations, "permutations", "permutations per candidate");
  ch.options().add(cfg.heldout_sets, "heldout-sets", "held-out blind sets (heldout_protocol.md: 24 quick, 144 full)");
  ch.options().add(cfg.heldout_seed0, "heldout-seed0",
                   "seed of held-out set 0 (the protocol's 50500000; 1..999 only to debug the generator)");
  ch.options().add(cfg.heldout2_sets, "heldout2-sets", "held-out sets per generator of demonstration 5 (24 quick, 144 full)");
  ch.options().add(cfg.heldout2_blind_seed0, "heldout2-blind-seed0",
                   "seed of generator 1's set 0 in demonstration 5 (heldout_protocol_v7.md's 60300000; 52000000+ to develop)");
  ch.options().add(cfg.heldout2_wild_seed0, "heldout2-wild-seed0",
                   "seed of generator 2's set 0 in demonstration 5 (heldout_protocol_v7.md's 60400000; 55000000+ to develop)");
  ch.options().range("null-seeds", 1, 10000).range("effect-seeds", 1, 10000).range("permutations", 19, 1e6);
  ch.options().range("heldout-sets", 1, 10000).range("heldout2-sets", 1, 10000);
  ch.options().range("heldout-seed0", 1, 2e9).range("heldout2-blind-seed0", 1, 2e9).range("heldout2-wild-seed0", 1, 2e9);
  return drawbend::study::run_chapter(ch, argc, argv, [&cfg](drawbend::study::Chapter& c) {
    using namespace ch7;
    const Thesis t = load_thesis_data(c, cfg);  // 1
    map_table(c, t.maps);                       // 2
    thesis_loop_pressure(c, t);                 // 3
    automatic_loop(c, t, cfg);                  // 4
    pin_42_anomaly(c, t);                       // 5
    bending_vs_swift(c, t, cfg);                // 6
    rd_td_crossover(c, t);                      // 7
    synthetic_detection(c, cfg);                // 8
    heldout_study(c, cfg);                      // 9
    heldout2_study(c, cfg);                     // 10
  });
}
