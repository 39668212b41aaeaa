// `drawbend strip-deck [options] [--out deck.toml]`: write the strip-draw
// deck of Chapter 3's builder (src/sim/strip_draw_case.hpp; Sec. 3.3,
// Fig. 3.2) for any die pressure, drawing speed, friction law and mesh, to
// --out or standard output.  `drawbend run deck.toml --out DIR` runs it; the
// history columns die_tangential_N and die_normal_N give mu = F_t / F_N.
// Units: mm, N, MPa, s.
#include <filesystem>
#include <string>

#include "analysis/stribeck.hpp"
#include "cli/deck_out.hpp"
#include "core/install_paths.hpp"
#include "cli/option_bounds.hpp"
#include "cli/threads.hpp"
#include "core/options.hpp"
#include "io/case_spec.hpp"
#include "io/portable_paths.hpp"
#include "sim/strip_draw_case.hpp"

namespace drawbend::cli {

int strip_deck_command(int argc, char** argv) {
  sim::StripDrawSpec s = sim::default_strip_draw_spec(drawbend::data_dir());
  std::string out;
  Options opt("drawbend strip-deck",
              "Write the strip-draw friction-test deck of Chapter 3 (Sec. 3.3): a strip section pressed by a "
              "force-driven flat die and drawn; the die's friction is the Stribeck law of Table 3.1 unless "
              "--friction names another law. Run it with `drawbend run DECK --out DIR`.");
  opt.add(out, "out", "deck file to write (empty: standard output)");
  opt.add(s.name, "name", "case name");
  opt.add(s.pressure, "pressure", "die pressure: die force / (length x width) [MPa] (> 0)");
  opt.add(s.speed, "speed", "drawing speed [mm/s] (> 0)");
  opt.add(s.slide, "slide", "drawn distance after the speed ramp [mm] (> 0)");
  opt.add(s.length, "length", "strip length under the die [mm] (> 0)");
  opt.add(s.width, "width", "strip width [mm] (> 0)");
  opt.add(s.thickness, "thickness", "strip thickness [mm] (> 0)");
  opt.add(s.nx, "nx", "elements along the strip (>= 1)");
  opt.add(s.ny, "ny", "elements across the strip (>= 1)");
  opt.add(s.nz, "nz", "elements through the thickness (>= 1)");
  std::string friction;  // --friction as given; io::friction_argument reads it below
  opt.add(friction, "friction",
          "die friction as a TOML inline table, e.g. '{ law = \"coulomb\", mu = 0.1 }' (empty: the Stribeck law)");
  opt.add(s.stribeck_table, "stribeck-table", "the Stribeck law's parameters (CSV, Table 3.1 format)");
  opt.add(s.interval, "interval", "the Stribeck law's update interval [cycles] (>= 1)");
  opt.add(s.hardening, "hardening", "hardening curve CSV (plastic strain, true stress [MPa])");
  opt.add(s.time_step, "time-step", "time step [s] (0: 1e-5 below 4 mm/s, 5e-7 above 40 mm/s, else 2.5e-6)");
  opt.add(s.die_mass, "die-mass", "die mass [t] (0: omega dt = 0.5 on its contact springs)");
  opt.add(s.press_time, "press-time", "duration of the press step [s]");
  opt.add(s.force_ramp, "force-ramp", "die force ramp [s] (<= --press-time)");
  opt.add(s.speed_ramp, "speed-ramp", "drawing speed ramp [s]");
  int threads = 0;
  opt.add(threads, "threads", "OpenMP threads written into the deck's [numerics] for `drawbend run` (0: none written, the default)");
  opt.example("drawbend strip-deck --pressure 20 --speed 4 --out my-strip/deck.toml");
  opt.example("drawbend run my-strip/deck.toml --out my-strip/run --quiet");
  using namespace bounds;  // every number range-checked as it is parsed (cli/option_bounds.hpp)
  opt.range("pressure", kMinPressureMPa, kPressureMPa, "MPa", false).range("speed", kMinSpeedMMs, kSpeedMMs, "mm/s", false);
  opt.range("slide", kMinLengthMM, kLengthMM, "mm", false).range("length", kMinLengthMM, kLengthMM, "mm", false);
  opt.range("width", kMinLengthMM, kLengthMM, "mm", false).range("thickness", kMinThicknessMM, kThicknessMM, "mm", false);
  opt.range("nx", 1, kElements).range("ny", 1, kElements).range("nz", 1, kElements);
  opt.range("interval", 1, kIntervalCycles, "cycles").range("time-step", 0, 1e-2, "s", true, false, true);
  opt.range("die-mass", 0, 1e3, "t", true, false, true).range("press-time", 0, kTimeS, "s", true);
  opt.range("force-ramp", 0, kTimeS, "s", true).range("speed-ramp", 0, kTimeS, "s", true);
  if (!opt.parse(argc, argv)) return 0;
  opt.not_empty({"hardening", "stribeck-table"});  // a file option given as '' names the option
  // The default law's options with --friction: refused, not ignored (exit 0 before 2026-12-04).
  opt.only_when(friction.empty(), {"stribeck-table", "interval"}, "without --friction, which replaces the default Stribeck law");
  // The force ramp against the press step, naming the options (the builder's check named its spec fields).
  ramp_within("force-ramp", s.force_ramp, "press-time", s.press_time, false);
  name_input(s.hardening, "--hardening");  // the file gate names the option (core/file_gate.hpp)
  name_input(s.stribeck_table, "--stribeck-table");
  // A regular file of a stated size, named by its option, before the deck is built (a FIFO or a
  // folder was named by the generated deck's line, with "cannot open").
  if (!s.hardening.empty()) (void)read_input(s.hardening);
  if (!s.stribeck_table.empty()) (void)read_input(s.stribeck_table);
  // --friction checked on its own (io/portable_paths.hpp): a problem names the option, not the generated deck.
  s.friction = io::friction_argument(friction, std::filesystem::current_path().string());
  // --stribeck-table checked on its own, so that a problem names the option and
  // the table's file:line, not the generated deck (as block-deck's --surface-nodes).
  if (!s.friction && !s.stribeck_table.empty()) try {
      (void)analysis::load_stribeck(s.stribeck_table);
    } catch (const std::exception& e) {
      const std::string what = e.what();
      throw InputError((what.rfind("--stribeck-table", 0) == 0 ? "" : "--stribeck-table: ") + what);
    }
  check_threads(threads);
  io::CaseSpec deck = sim::strip_draw_case(s);
  io::set_threads(deck, threads);  // the deck's numerics.threads
  return write_deck_out(io::to_toml(deck), out, "strip-deck",
                        {{"numerics", "--time-step"},
                         {"mesh", "--length, --width, --thickness, --nx, --ny or --nz"},
                         {"material", "--hardening"},
                         {"output", "--interval"},
                         {"contact", "--friction or --stribeck-table"},
                         {"tool", "--die-mass or --time-step"},
                         {"step", "--press-time, --force-ramp, --speed-ramp, --slide or --speed"}});
}

}  // namespace drawbend::cli
