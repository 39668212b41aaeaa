// Chapter 2: the finite-element study of the draw-bend test.  Steps 1-3 need
// no finite-element solver: they check the arithmetic the text states between
// its own numbers (contact angle, wrap deficit, steady-state ratio, sliding
// distance, mass-scaling speed-up, retrieved friction) and Swift's bending
// force estimate, Eq. (2.1).  Forces are half-model forces in N.
//
// Recipe:
//   1. Scalar statements of Secs. 2.2-2.4 re-derived from their inputs.
//   2. Swift's bending force, Eq. (2.1), with the inputs the chapter implies.
//   3. Sliding distance at the steady-state time, at constant sliding speed.
//
// Sample runs (from the source folder after `make`; the binaries are in build/chapters/):
//   chapter_ch2_fe_study --out build/chapters/ch2-fe-study
//       (the quick tier, as `ctest -R chapter.ch2-fe-study` runs it)
//   chapter_ch2_fe_study --tier full --fe-element-length 0.5 --fe-across 4 --fe-fine-element-length 0.25
//       (the full tier's meshes (`make test-full`))
//   chapter_ch2_fe_study --fe false
//       (steps 1-3 only: the text's arithmetic and Swift's estimate, no FE run)
//   chapter_ch2_fe_study --swift-pin-diameter 25.4
//       (Swift's Eq. (2.1) on another assumed pin: the chapter does not state it)
#include <cmath>

#include "analysis/rope.hpp"
#include "ch2_steps.hpp"
#include "sim/fe_options.hpp"
#include "study/chapter.hpp"
#include "study/thesis_data.hpp"

using namespace drawbend;
using namespace drawbend::analysis;

namespace {

// The chapter's options (main registers them; the body reads them).
struct Config {
  double swift_pin_mm = 12.7;  ///< assumption for Eq. (2.1) [mm]; --swift-pin-diameter
  bool run_fe = true;          ///< --fe: steps 4-8
  ch2::FeOptions fe;           ///< mesh, numerics and --reuse-runs of steps 4-8
};

void body(study::Chapter& c, const Config& cfg) {
  const double swift_pin_mm = cfg.swift_pin_mm;
  // 1. Statements that follow from other printed numbers.
  using V = std::vector<double>;
  c.rederive_scalar("ch2.contact_angle", "real contact angle = end - start (Sec. 2.3.1)", "ch2_contact_angle",
                    {"ch2_contact_end", "ch2_contact_start"}, [](const V& x) { return x[0] - x[1]; }, "deg");
  c.rederive_scalar("ch2.contact_angle_deficit", "contact angle below the wrap angle, percent (Sec. 2.3.1)",
                    "ch2_contact_angle_deficit", {"ch2_wrap_angle", "ch2_contact_angle"},
                    [](const V& x) { return 100.0 * (x[0] - x[1]) / x[0]; }, "%");
  c.rederive_scalar("ch2.steady_ratio", "steady sliding distance / wrap length (Sec. 2.3.2)", "ch2_steady_ratio",
                    {"ch2_steady_sliding_distance", "ch2_wrap_length"}, [](const V& x) { return x[0] / x[1]; }, "-");
  c.rederive_scalar("ch2.step3_slide", "step-3 slide = mean of outlet and inlet travel (Sec. 2.2)",
                    "ch2_step3_slide", {"ch2_step3_outlet_travel", "ch2_step3_inlet_travel"},
                    [](const V& x) { return 0.5 * (x[0] + x[1]); }, "mm");
  const double speedup =
      c.rederive_scalar("ch2.mass_scaling_speedup", "speed-up sqrt(mass scaling) (Sec. 2.2)", "ch2_speedup",
                        {"ch2_mass_scaling_high"}, [](const V& x) { return std::sqrt(x[0]); }, "-");
  c.value("speedup_ours", fmt_fixed(speedup, 1));
  c.value("speedup_thesis", study::scalar(c.data("thesis/scalars.csv"), "ch2_speedup").text);
  {
    // The input mu = 0.1 is a set value of the simulation, exact, not a
    // rounded measurement: only the retrieved 0.096 and the printed 96 % carry
    // rounding (rederive_scalar would treat "0.1" as 0.05-0.15, +-65 %).
    const std::string sc = c.data("thesis/scalars.csv");
    const auto got = study::scalar(sc, "ch2_mu_retrieved"), in = study::scalar(sc, "ch2_mu_input");
    const auto ratio = study::scalar(sc, "ch2_mu_retrieved_ratio");
    c.checks().rederive("ch2.mu_retrieved_ratio", "retrieved mu / input mu, percent (Sec. 2.4.3)", ratio.value,
                        100.0 * got.value / in.value, 100.0 * got.half_ulp / in.value + ratio.half_ulp, "%",
                        "printed-digit rounding of ch2_mu_retrieved and of the printed result; the input 0.1 is exact");
  }

  // 2. Swift, Eq. (2.1).  Chapter 2 states neither the yield stress nor the pin;
  // we take the 12.7 mm pin of Chapters 3-5, the 1.04 x 25.4 mm strip on the half
  // model and the 0.2 % yield stress of Table 5.1.  RD and TD yield stresses
  // differ, so the spread between them is part of the tolerance.
  const CsvTable t51 = read_csv(c.data("thesis/table_5_1.csv"));
  double ys_rd = 0, ys_td = 0;
  for (const auto& r : t51.rows) (t51.text(r, "direction") == "RD" ? ys_rd : ys_td) = t51.number(r, "YS02_MPa");
  const std::string sc = c.data("thesis/scalars.csv");
  const double t = study::scalar(sc, "ch5_strip_thickness").value, w = study::scalar(sc, "ch5_strip_width").value;
  const double theta = study::scalar(sc, "ch2_wrap_angle").value * M_PI / 180.0;
  const double r = swift_pin_mm / 2;
  const double F_rd = swift_bending_force(ys_rd, t, w, r, theta, ForceBasis::half_model);
  const double F_td = swift_bending_force(ys_td, t, w, r, theta, ForceBasis::half_model);
  const auto swift = study::scalar(sc, "ch2_swift_bending_force");
  // Chapter 2 states neither pin nor yield stress, so this is not a test of
  // the thesis's arithmetic alone: it asks whether Eq. (2.1) with the thesis's
  // own strip (Table 5.1) gives the printed 107 N on some pin of the thesis.
  // Only the 12.7 mm pin does (the 25.4 and 42 mm pins give about half and a
  // third of it, see swift_other_pins); the assumed pin is an input of this
  // check, and ch2.fe.FB is run on the same pin.
  c.checks().agree(study::Kind::rederived, "ch2.swift_bending_force",
                   "Swift bending force, Eq. (2.1), half model, assumed 12.7 mm pin",
                   swift.value, F_rd, std::abs(F_rd - F_td) + swift.half_ulp, "N",
                   "inputs not stated in Ch. 2 (pin assumed): RD/TD yield-stress spread plus rounding to 1 N");
  c.value("swift_other_pins",
          fmt_fixed(swift_bending_force(ys_rd, t, w, 25.4 / 2, theta, ForceBasis::half_model), 1) + "\u00a0N (25.4\u00a0mm), " +
              fmt_fixed(swift_bending_force(ys_rd, t, w, 42.0 / 2, theta, ForceBasis::half_model), 1) +
              "\u00a0N (42\u00a0mm)");
  c.value("swift_thesis", swift.text, "N");
  c.value("swift_pin", fmt(swift_pin_mm), "mm");
  c.value("strip", fmt(t) + "\u00a0mm \u00d7 " + fmt(w) + "\u00a0mm");
  c.value("swift_rd", fmt_fixed(F_rd, 1), "N");
  c.value("swift_td", fmt_fixed(F_td, 1), "N");
  c.value("ys_rd", fmt(ys_rd), "MPa");
  c.value("ys_td", fmt(ys_td), "MPa");

  // 3. Where was the strip at the steady-state time, if it slid at constant speed?
  const double t0 = study::scalar(sc, "ch2_step1_time").value + study::scalar(sc, "ch2_step2_time").value;
  const double t3 = study::scalar(sc, "ch2_step3_time").value;
  const double slide = 0.5 * (study::scalar(sc, "ch2_step3_outlet_travel").value +
                              study::scalar(sc, "ch2_step3_inlet_travel").value);
  const double t_steady = study::scalar(sc, "ch2_steady_time").value;
  c.value("slide_at_steady", fmt_fixed(slide * (t_steady - t0) / t3, 1), "mm");
  c.value("t_step3_start", fmt(t0), "s");
  c.value("t_steady", study::scalar(sc, "ch2_steady_time").text, "s");
  c.value("d_steady", study::scalar(sc, "ch2_steady_sliding_distance").text, "mm");

  // 4-8. Our simulations.
  if (cfg.run_fe) ch2::fe_study(c, cfg.fe);
}

}  // namespace

int main(int argc, char** argv) {
  study::Chapter ch("ch2-fe-study", "Chapter 2: the draw-bend FE study, re-derived and with our own simulations");
  Config cfg;
  auto& o = ch.options();
  o.add(cfg.swift_pin_mm, "swift-pin-diameter", "pin diameter [mm] assumed for Swift's Eq. (2.1); Chapter 2 does not state it");
  sim::add_fe_options(o, cfg.fe.base, cfg.run_fe, cfg.fe.reuse);
  o.add(cfg.fe.low_mass_scaling, "fe-low-mass-scaling", "mass scaling of the comparison run");
  o.add(cfg.fe.fine_element_length, "fe-fine-element-length", "element length of the convergence runs [mm]");
  o.range("swift-pin-diameter", 0, 1000, "mm", true).range("fe-low-mass-scaling", 1, 1e9);
  o.range("fe-fine-element-length", 0, 20, "mm", true);
  return study::run_chapter(ch, argc, argv, [&cfg](study::Chapter& c) { body(c, cfg); });
}
