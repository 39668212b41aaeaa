// `drawbend drawbend-deck [options] [--run DIR]`: write the draw-bend case deck
// of the chapters' builder (src/sim/drawbend_case.hpp) for any pin, back
// tension, friction law and mesh, to standard output or, with --run, run it
// into DIR.  Units: mm, N, MPa, s.
//
// Force basis: the model is the top half of the strip (symmetry), but a test
// measures the whole strip.  Forces given and printed are full-strip forces
// by default; `--basis half` takes and prints the half model's (the thesis's
// simulated numbers, Chapters 2-4).  Every output states its basis.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <variant>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "analysis/rope.hpp"
#include "cli/deck_out.hpp"
#include "cli/option_bounds.hpp"
#include "cli/threads.hpp"
#include "core/csv.hpp"
#include "core/file_gate.hpp"
#include "core/options.hpp"
#include "io/case_spec.hpp"
#include "io/portable_paths.hpp"
#include "io/run_result.hpp"
#include "sim/drawbend_case.hpp"
#include "sim/material_choice.hpp"
#include "sim/fe_options.hpp"

namespace drawbend::cli {

namespace {
/// The options behind each key of the deck (cli/deck_out.hpp's user_words).
const std::vector<KeyOptions> kDeckKeys = {{"numerics.mass_scaling", "--speed or --mass-scaling"},
                                           {"numerics", "--speed, --mass-scaling or --element-length"},
                                           {"mesh", "--element-length, --across, --through, --width or --draw-length"},
                                           {"material", "--material or --hardening"},
                                           {"output", "--frames or --draw-length"},
                                           {"contact", "--friction or --penalty"},
                                           {"step", "--speed, --draw-length or --back-tension"}};
// A back tension the strip cannot carry: above its flow stress at 100 % plastic strain
// (beyond any strip's necking strain, so a generous bound) over the modelled section.
// Such a deck was written with exit 0 and its run ended in exit 3 (an element
// inverted) before 2026-12-04.  An elastic material has no bound here.
void check_back_tension(const sim::DrawBendSpec& s, const io::MaterialSpec& m, double given, const std::string& tag) {
  if (!m.curve) return;
  const double sigma = io::make_flow_curve(*m.curve, "").tension_bound();
  const double capacity = sigma * s.width * s.thickness;  // the half model's section
  if (s.back_tension > capacity)
    throw InputError("--back-tension: " + fmt(given, 6) + " N on the " + tag + " is above what the strip can carry, " +
                     fmt(capacity * given / s.back_tension, 6) + " N (the material's flow stress at 100 % plastic strain, " +
                     fmt(sigma, 4) + " MPa, over the " + fmt(s.thickness, 4) + " mm thick strip's section): forces in " +
                     "another unit, or another strip (--width, --thickness)?");
}

}  // namespace

int drawbend_deck_command(int argc, char** argv) {
  sim::DrawBendSpec s = sim::quick_deck_spec();  // the chapters' quick tier (sim/fe_options.hpp)
  s.mass_scaling = 0;  // 0: the quick tier's rule at --speed (set after parsing)
  std::string run_dir, basis = "full";
  double back_tension = 2 * s.back_tension, bending_force = 0, yield_stress = 0;
  int threads = 0;
  Options opt("drawbend drawbend-deck",
              "Write (or, with --run, run) a draw-bend case deck from the chapters' builder. The model is the top "
              "half of the strip; forces are full-strip by default (--basis half: the half model's).");
  opt.add(s.name, "name", "case name");
  opt.add(s.pin_diameter, "pin-diameter", "pin diameter D [mm]");
  opt.add(s.thickness, "thickness", "strip thickness [mm]");
  opt.add(s.width, "width", "modelled half width [mm] (the strip is twice as wide)");
  opt.add(basis, "basis", "force basis of --back-tension, --bending-force and the printed forces: full or half");
  opt.add(back_tension, "back-tension", "back tension F_X [N] on the --basis (default full strip)");
  opt.add(s.speed, "speed", "outlet speed in the draw step [mm/s]");
  opt.add(s.draw_length, "draw-length", "slide in the draw step [mm] (0: 1.5 wrap lengths + 6 mm)");
  std::string friction;  // --friction as given; io::friction_argument reads it below
  opt.add(friction, "friction",
          "pin friction: a TOML inline table (empty: frictionless), e.g. '{ law = \"coulomb\", mu = 0.1 }', or a file "
          "with a [friction] table such as the loop's friction_model.toml; relative table paths are taken from the "
          "current folder (inline) or from that file's folder");
  opt.add(s.element_length, "element-length", "element length along the strip in the bend zone [mm]");
  opt.add(s.across, "across", "elements across the half width");
  opt.add(s.through, "through", "elements through the thickness");
  opt.add(s.mass_scaling, "mass-scaling",
          "uniform mass scaling factor (0: the quick tier's 1e4 at 100 mm/s scaled by (100/v)^2 at --speed)");
  opt.add(s.penalty, "penalty", "contact penalty scale");
  opt.add(s.hardening, "hardening", "hardening curve CSV (plastic strain, true stress [MPa])");
  opt.add(s.material, "material",
          "material: empty = isotropic J2 on --hardening; a TOML inline table of [material] keys, e.g. "
          "'{ type = \"j2_combined\", kinematic = { beta = 0.5 } }', or a TOML file with a [material] table "
          "(data/materials/*.toml)");
  opt.add(s.strip_direction, "strip-direction", "the strip's axis is the rolling direction (rd) or the transverse one (td)");
  opt.add(s.bend_inlet_slides, "bend-inlet-slides",
          "step 1 (bend) with the inlet end sliding under the back tension (true, the default since issue 51) or "
          "clamped (false, the decks before it, for reproduction), which stretches the strip by about 1.3 % before "
          "the test (docs/issue51-large-pin.md)");
  opt.add(s.plane_strain_width, "plane-strain-width",
          "hold the strip's free edge across the width in every step (true: plane strain, the width condition of "
          "plane-strain beam theory) or leave it free as on the real strip (false)");
  opt.add(s.snapshots, "frames",
          "contact maps and .vtu frames written per step (bend, tension, draw): 3 x N + 1 frames in all");
  opt.add(bending_force, "bending-force",
          "F_B [N] on the --basis for mu by Eq. (2.3), e.g. F_Y - F_X of a frictionless run (0: Swift's Eq. (2.1))");
  opt.add(yield_stress, "yield-stress", "yield stress [MPa] of Swift's F_B estimate (0: Table 5.1, RD)");
  opt.add(threads, "threads",
          "OpenMP threads of the run (0: OMP_NUM_THREADS or all); without --run, written into the deck's [numerics]");
  opt.add(run_dir, "run", "run the deck into this directory instead of printing it");
  opt.example("drawbend drawbend-deck --pin-diameter 25.4 --back-tension 1800 --friction '{ law = \"coulomb\", mu = 0.1 }' > my.toml");
  opt.example("drawbend drawbend-deck --pin-diameter 12.7 --element-length 1.5 --through 2 --draw-length 12 --run my-free    # frictionless: prints F_B");
  opt.example("drawbend drawbend-deck --pin-diameter 12.7 --element-length 1.5 --through 2 --draw-length 12 --friction '{ law = \"coulomb\", mu = 0.1 }' "
              "--bending-force 348 --run my-case    # F_B of my-free");
  using namespace bounds;  // every number range-checked as it is parsed (cli/option_bounds.hpp)
  opt.range("pin-diameter", kMinLengthMM, kLengthMM, "mm", false).range("thickness", kMinThicknessMM, kThicknessMM, "mm", false);
  opt.range("width", kMinLengthMM, kLengthMM, "mm", false).range("back-tension", 0, kForceN, "N", true);
  opt.range("speed", kMinSpeedMMs, kSpeedMMs, "mm/s", false).range("draw-length", kMinLengthMM, kLengthMM, "mm", false, false, true);
  opt.range("element-length", kMinLengthMM, kLengthMM, "mm", false).range("across", 1, kElements).range("through", 1, kElements);
  opt.range("mass-scaling", 1, kMassScaling, "", false, false, true).range("penalty", 0, kPenalty, "", true);
  opt.range("frames", 1, 1000).range("bending-force", 0, kForceN, "N").range("yield-stress", 0, 1e4, "MPa");
  if (!opt.parse(argc, argv)) return 0;
  opt.not_empty({"hardening"});  // a file option given as '' names the option
  name_input(s.hardening, "--hardening");  // the file gate names the option (core/file_gate.hpp)
  // A regular file of a stated size, named by its option, before the deck is built (a FIFO or a
  // folder was named by the generated deck's line, with "cannot open").
  if (!s.hardening.empty()) (void)read_input(s.hardening);
  name_input(s.material, "--material");
  check_threads(threads);
  // Relative files are the user's, from the current folder (io/portable_paths.hpp).
  s.friction = io::friction_argument(friction, std::filesystem::current_path().string());
  if (!s.hardening.empty()) s.hardening = std::filesystem::absolute(s.hardening).lexically_normal().string();
  // --hardening is the flow curve of a --material without one; with a --material that has its own
  // (or is elastic) it was ignored with exit 0 before 2026-12-04: refused, naming both options.
  const io::MaterialSpec material = sim::material_choice(s.material, s.hardening);
  if (opt.given("hardening") && !s.material.empty()) {
    const auto* f = material.curve ? std::get_if<io::CurveFile>(&*material.curve) : nullptr;
    if (!f || f->path != s.hardening)
      throw std::invalid_argument(std::string("--hardening: applies only with a --material that has no flow curve of its own (") +
                                  (material.curve ? "this --material names one" : "this --material is elastic") +
                                  "; given here, it would be ignored)");
  }
  if (basis != "full" && basis != "half")
    throw std::invalid_argument("--basis: expected full or half, found '" + basis + "'");
  if (s.strip_direction != "rd" && s.strip_direction != "td")
    throw std::invalid_argument("--strip-direction: expected rd or td, found '" + clip_for_message(s.strip_direction) + "'");
  if (s.snapshots < 1) throw std::invalid_argument("--frames: expected at least 1");
  if (!(s.speed > 0)) throw std::invalid_argument("--speed: expected a number > 0 mm/s, found " + fmt(s.speed));
  if (s.mass_scaling < 0) throw std::invalid_argument("--mass-scaling: expected 0 (the quick tier's rule) or > 0");
  if (s.mass_scaling == 0) s.mass_scaling = sim::mass_scaling_for_speed(sim::kQuickMassScaling, s.speed);
  // One element through the thickness (--through 1) is a warning of the deck
  // itself (io/deck_limits.hpp's mesh_warnings), printed by checked_deck here
  // and by `drawbend run` for every builder's deck and every hand-written one.
  const bool full = basis == "full";
  const double to_half = full ? 0.5 : 1.0;  // given forces -> half model
  const std::string tag = full ? "full strip" : "half model";
  s.back_tension = back_tension * to_half;
  try {
    check_back_tension(s, material, back_tension, tag);  // reads the flow curve
  } catch (const InputError& e) {  // the curve file's own problem, named with its option (the file alone before 2026-12-05)
    const std::string what = e.what();
    if (!s.hardening.empty() && what.rfind(s.hardening, 0) == 0) throw InputError("--hardening: " + what);
    throw;
  }
  if (run_dir.empty()) {
    io::CaseSpec deck = sim::drawbend_case(s);
    io::set_threads(deck, threads);  // the deck's numerics.threads (a run's deck keeps none)
    std::cout << "# back_tension in this deck is on the half model: " << fmt(s.back_tension, 6) << " N ("
              << fmt(back_tension, 6) << " N on the " << tag << ")\n"
              << checked_deck(io::to_toml(deck), "drawbend-deck", kDeckKeys);
    return 0;
  }
  ensure_writable_dir(run_dir, "--run");  // before any work: exit 2, not a file-system error
  // The deck checked as without --run, so that a refusal names the options, not the run's deck.toml line.
  (void)checked_deck(io::to_toml(sim::drawbend_case(s)), "drawbend-deck", kDeckKeys, false);
  apply_threads(threads);
  // The run prints its answer (forces, F_B, mu by Eq. (2.3)) on --basis and writes it to
  // <run>/result.toml on both bases (io/run_result.hpp); `drawbend run` prints the same lines.
  io::ResultOptions res;
  res.basis = basis;
  res.bending_force = bending_force;
  res.yield_stress = yield_stress;
  sim::run_drawbend(s, run_dir, false, false, {}, res);
  return 0;
}

}  // namespace drawbend::cli
