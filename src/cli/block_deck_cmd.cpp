// `drawbend block-deck [options] [--out deck.toml]`: write the block-sliding
// deck of Chapter 6's builder (src/sim/block_case.hpp; Sec. 6.5, Fig. 6.7) for
// any pressure, sliding speed, direction, friction law and mesh, to --out or
// standard output.  `drawbend run deck.toml --out DIR` runs it; the history
// columns friction_x_N, friction_y_N and normal_N give mu = F_t / F_N.
// Units: mm, N, MPa, s.
#include <filesystem>
#include <string>

#include "cli/deck_out.hpp"
#include "core/install_paths.hpp"
#include "cli/option_bounds.hpp"
#include "cli/threads.hpp"
#include "core/options.hpp"
#include "friction/surface_law.hpp"
#include "io/case_spec.hpp"
#include "io/portable_paths.hpp"
#include "sim/block_case.hpp"

namespace drawbend::cli {

int block_deck_command(int argc, char** argv) {
  sim::BlockSpec s = sim::default_block_spec(drawbend::data_dir());
  std::string out;
  Options opt("drawbend block-deck",
              "Write the block-sliding case deck of Chapter 6 (Sec. 6.5): a cube pressed on a rigid floor and slid "
              "in the floor plane; the floor's friction is the mu(p, v) surface of Table 6.1 unless --friction "
              "names another law. Run it with `drawbend run DECK --out DIR`.");
  opt.add(out, "out", "deck file to write (empty: standard output)");
  opt.add(s.name, "name", "case name");
  opt.add(s.pressure, "pressure", "normal pressure on the top face [MPa] (> 0)");
  opt.add(s.speed, "speed", "sliding speed [mm/s] (> 0)");
  opt.add(s.direction_deg, "direction", "sliding direction from RD (x) towards TD (y) [deg]");
  opt.add(s.size, "size", "edge of the cube [mm] (> 0)");
  opt.add(s.elements, "elements", "elements along each edge (>= 1)");
  opt.add(s.mass_scaling, "mass-scaling", "uniform mass scaling factor (>= 1)");
  opt.add(s.penalty, "penalty", "contact penalty scale (> 0)");
  std::string friction;  // --friction as given; io::friction_argument reads it below
  opt.add(friction, "friction",
          "floor friction as a TOML inline table, e.g. '{ law = \"coulomb\", mu = 0.1 }' (empty: the surface law)");
  opt.add(s.surface_nodes, "surface-nodes", "the surface law's nine nodal values (CSV, Table 6.1 format)");
  opt.add(s.interval, "interval", "the surface law's speed-averaging interval [cycles] (>= 1)");
  opt.add(s.hardening, "hardening", "hardening curve CSV (plastic strain, true stress [MPa])");
  opt.add(s.press_time, "press-time", "duration of the press step [s]");
  opt.add(s.press_ramp, "press-ramp", "load ramp of the press step [s] (< --press-time)");
  opt.add(s.slide_time, "slide-time", "duration of the slide step [s]");
  opt.add(s.speed_ramp, "speed-ramp", "speed ramp of the slide step [s] (< --slide-time)");
  int threads = 0;
  opt.add(threads, "threads", "OpenMP threads written into the deck's [numerics] for `drawbend run` (0: none written, the default)");
  opt.example("drawbend block-deck --pressure 40 --speed 70 --out my-block/deck.toml");
  opt.example("drawbend run my-block/deck.toml --out my-block/run --quiet");
  using namespace bounds;  // every number range-checked as it is parsed (cli/option_bounds.hpp)
  opt.range("pressure", kMinPressureMPa, kPressureMPa, "MPa", false).range("speed", kMinSpeedMMs, kSpeedMMs, "mm/s", false);
  opt.range("direction", -360, 360, "deg").range("size", kMinLengthMM, kLengthMM, "mm", false).range("elements", 1, kElements);
  opt.range("mass-scaling", 1, kMassScaling).range("penalty", 0, kPenalty, "", true);
  opt.range("interval", 1, kIntervalCycles, "cycles").range("press-time", 0, kTimeS, "s", true);
  opt.range("press-ramp", 0, kTimeS, "s", true).range("slide-time", 0, kTimeS, "s", true);
  opt.range("speed-ramp", 0, kTimeS, "s", true);
  if (!opt.parse(argc, argv)) return 0;
  opt.not_empty({"hardening", "surface-nodes"});  // a file option given as '' names the option
  // The default law's options with --friction: refused, not ignored (exit 0 before 2026-12-04).
  opt.only_when(friction.empty(), {"surface-nodes", "interval"}, "without --friction, which replaces the default surface law");
  // The ramps against their steps, naming the options (the builder's check named its spec fields).
  ramp_within("press-ramp", s.press_ramp, "press-time", s.press_time, true);
  ramp_within("speed-ramp", s.speed_ramp, "slide-time", s.slide_time, true);
  name_input(s.hardening, "--hardening");  // the file gate names the option (core/file_gate.hpp)
  // A regular file of a stated size, named by its option, before the deck is built (a FIFO or a
  // folder was named by the generated deck's line, with "cannot open").
  if (!s.hardening.empty()) (void)read_input(s.hardening);
  name_input(s.surface_nodes, "--surface-nodes");
  // --friction and --surface-nodes checked on their own, so that a problem names
  // the option or the user's file and line, not a line of the generated deck.
  s.friction = io::friction_argument(friction, std::filesystem::current_path().string());
  if (!s.friction && !s.surface_nodes.empty()) try {
      (void)friction::load_surface_nodes(s.surface_nodes, friction::SurfaceDomain{});
    } catch (const std::exception& e) {
      const std::string what = e.what();  // the file gate's messages name the option already
      throw InputError((what.rfind("--surface-nodes", 0) == 0 ? "" : "--surface-nodes: ") + what);
    }
  check_threads(threads);
  io::CaseSpec deck = sim::block_case(s);
  io::set_threads(deck, threads);  // the deck's numerics.threads
  return write_deck_out(io::to_toml(deck), out, "block-deck",
                        {{"numerics", "--mass-scaling"},
                         {"mesh", "--size or --elements"},
                         {"material", "--hardening"},
                         {"output", "--interval"},
                         {"contact", "--friction, --surface-nodes or --penalty"},
                         {"step", "--pressure, --speed, --press-time or --slide-time"}});
}

}  // namespace drawbend::cli
