// Chapter 8: closing the loop at the model level.  The loop of Chapter 7
// adds empirical terms to the analysis; here the candidate effects are
// modelling effects, tested by re-running the finite-element draw-bend model
// (rotating = frictionless pin, Sec. 5.7.1 conditions) against the measured
// bending force of Table 5.3 (src/modelloop/model_loop.hpp, the same code as
// `drawbend model-loop`).  Forces are full-strip forces in N; lengths mm.
//
// Recipe (in the order main runs it):
//   1. Measured points: Table 5.3's fits at the Table 5.13 back tensions
//      (tables/measured_fb.csv, the format of `drawbend model-loop`).
//   2. The residual traced by beam theory (analysis/bending_work.hpp): the
//      FE against the same assumptions in a layered beam, then the transverse
//      constraint and an Armstrong-Frederick back stress on a grid.
//   3. Full tier only, numerics before physics: mass scaling on every pin;
//      2/4/8 elements across on the 25.4 and 42 mm pins.
//   4. The loop: isotropic baseline; candidates fitted on the 12.7 mm pin,
//      and leave one pin out (fit and choice inside the other two pins, each
//      pin's error from the fold that never saw it); before/after table,
//      figure, F_B checks per pin.  4b: per fold, whether its fit pin's one
//      force identifies the back stress (beam grid; ch8_identify.cpp).
//   5. F_B against back tension on the 12.7 mm pin (slope check).
//   6. The cup (Sec. 6.6): why the punch force is high (tool radii, flow
//      curve, combined hardening, Hill'48), and the 2 x 2 attribution of the
//      RD failure to frictional or material anisotropy at 21 mm.
//
// Sample runs (from the source folder after `make`; the binaries are in build/chapters/):
//   chapter_ch8_model_loop --out build/chapters/ch8-model-loop
//       (the quick tier, as `ctest -R chapter.ch8-model-loop` runs it)
//   chapter_ch8_model_loop --tier full --full-study true --fe-mass-scaling 625
//       (the whole full study (hours of CPU; `make test-full`))
//   chapter_ch8_model_loop --cup false
//       (the bending-force loop only, without the cup loop and the 2 x 2)
//   chapter_ch8_model_loop --candidates voce,hill48
//       (only these candidates, trained on the 12.7 mm pin)
#include "ch8_steps.hpp"
#include "sim/fe_options.hpp"

int main(int argc, char** argv) {
  drawbend::study::Chapter ch("ch8-model-loop", "Chapter 8: closing the loop at the model level (bending force)");
  ch8::Config cfg;  // the chapter's options
  auto& o = ch.options();
  drawbend::sim::add_fe_options(o, cfg.base, cfg.run_fe, cfg.reuse_runs);
  o.add(cfg.runs_from, "runs-from",
        "comma-separated folders of runs made before by the same build (CMake passes Chapter 5's runs/ and runs it "
        "first); a case whose deck is one of theirs but for its name is read there, not rerun");
  o.add(cfg.full_study, "full-study",
        "true: the full tier's candidates (back stress, Voce, Hill'48), the slope of the final model, mass scaling and "
        "width convergence; false: the quick tier");
  o.add(cfg.fit_pin, "fit-pin", "pin whose bending force trains the candidates [mm]");
  o.add(cfg.candidates, "candidates",
        "comma-separated candidates (split:B1/B2..., chaboche:X1/X2...[@G1/G2...], voce, hill48, offset, ms:X, across:N); empty: the tier's list");
  o.add(cfg.numerics, "numerics",
        "the mass-scaling and width studies: true, false, or auto (as --full-study); 1, 0, -1 also accepted");
  o.add(cfg.next, "next-candidates",
        "after the back stress the loop tries Voce, then Hill'48 (the full tier's list) on this run's mesh: true, "
        "false, or auto (as --full-study); 1, 0, -1 also accepted");
  o.add(cfg.cup, "cup", "the cup loop and the 2 x 2 attribution (step 6)");
  o.add(cfg.min_gain, "min-gain", "accept a candidate if the held-out RMS relative error falls by more than this");
  o.range("fit-pin", 0, 1000, "mm", true).range("min-gain", 0, 1);
  return drawbend::study::run_chapter(ch, argc, argv, [&cfg](drawbend::study::Chapter& c) {
    using namespace ch8;
    const bool numerics = cfg.run_numerics();  // a bad --numerics or --next-candidates fails before any work
    cfg.run_next();
    const Inputs in = load_inputs(c, cfg);  // 1
    c.value("fe_ran", cfg.run_fe ? "yes" : "no");
    const BeamTrace trace = beam_trace(c, in, cfg);  // 2: the residual traced by beam theory
    if (!cfg.run_fe) return save_beam_trace(c, in, trace, nullptr);
    if (numerics) numerical_convergence(c, in, cfg);  // 3: numerics before physics
    const auto loop = bending_force_loop(c, in, cfg, trace);  // 4
    save_beam_trace(c, in, trace, &loop);                      // 2's table with the FE rows
    tension_slope(c, in, cfg, loop);                       // 5
    if (cfg.cup) cup_loop(c, cfg, loop);                   // 6
  });
}
