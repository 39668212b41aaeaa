// `drawbend cup-deck [options]`: write the cup-drawing deck of the chapters'
// builder (src/sim/cup_case.hpp: quarter model of the thesis's Sec. 6.6 cup,
// 20 kN blank holder) for any punch speed, stroke, tool radii, material,
// friction and mesh, to standard output; run it with `drawbend run`.
// Sample: drawbend cup-deck --die-radius 8 --material data/materials/aa5754_o_hill48_hou2020.toml > cup.toml
// Units: mm, N, MPa, s.
#include <cmath>
#include <iostream>

#include "cli/deck_out.hpp"
#include "core/install_paths.hpp"
#include "cli/option_bounds.hpp"
#include "cli/threads.hpp"
#include "core/csv.hpp"
#include "core/options.hpp"
#include "friction/surface_law.hpp"
#include "sim/cup_case.hpp"

namespace drawbend::cli {

int cup_deck_command(int argc, char** argv) {
  sim::CupSpec s;
  s.deck = drawbend::data_dir() + "/cases/cup_draw.toml";
  double punch_radius = 0, die_radius = 0;
  int cycles = static_cast<int>(s.cycles);
  Options opt("drawbend cup-deck",
              "Write a cup-drawing deck (quarter model, thesis Sec. 6.6) from the chapters' builder to standard "
              "output; forces in its history are the quarter model's (x 4 for the full blank).");
  opt.add(s.deck, "base", "base deck (TOML) whose mesh, tools and contacts are used");
  opt.add(s.speed, "speed", "punch speed [mm/s] (Table 6.5: 6.4 to 101.6)");
  opt.add(s.stroke, "stroke", "punch travel [mm]");
  opt.add(cycles, "cycles", "cycles per stroke: sets the time step and so the mass scaling");
  opt.add(s.refine, "refine", "the base deck's element counts times this (in-plane and through the thickness)");
  opt.add(punch_radius, "punch-radius", "punch corner radius [mm] (0: the base deck's, an ASSUMED 5 mm)");
  opt.add(die_radius, "die-radius", "upper-die corner radius [mm] (0: the base deck's, an ASSUMED 5 mm)");
  opt.add(s.material, "material",
          "material: empty = the base deck's (isotropic J2, Table 5.1 RD); a TOML inline table of [material] keys "
          "or a TOML file with a [material] table (data/materials/*.toml)");
  opt.add(s.friction, "friction",
          "friction on every contact: empty = the base deck's (Table 6.1 mu(p, v), RD along x); none = "
          "frictionless; or a Table 6.1-format nodes CSV");
  int threads = 0;
  opt.add(threads, "threads", "OpenMP threads written into the deck's [numerics] for `drawbend run` (0: none written, the default)");
  opt.example("drawbend cup-deck --die-radius 8 --stroke 1 --cycles 600 > my-cup.toml");
  opt.example("drawbend run my-cup.toml --out my-cup --quiet");
  using namespace bounds;  // every number range-checked as it is parsed (cli/option_bounds.hpp)
  opt.range("speed", kMinSpeedMMs, kSpeedMMs, "mm/s", false).range("stroke", kMinLengthMM, kLengthMM, "mm", false);
  opt.range("cycles", 100, 1e8).range("refine", 1, 8);
  opt.range("punch-radius", kMinLengthMM, kLengthMM, "mm", false, false, true).range("die-radius", kMinLengthMM, kLengthMM, "mm", false, false, true);
  if (!opt.parse(argc, argv)) return 0;
  opt.not_empty({"base"});  // a file option given as '' names the option
  name_input(s.deck, "--base");  // the file gate names the option (core/file_gate.hpp)
  name_input(s.material, "--material");
  name_input(s.friction, "--friction");
  // The nodes file checked on its own: a problem names --friction and the file's
  // line, not the base deck's contact lines (three times, before issue 53).
  if (!s.friction.empty() && s.friction != "none") try {
      (void)friction::load_surface_nodes(s.friction, friction::SurfaceDomain{});
    } catch (const std::exception& e) {
      const std::string what = e.what();  // the file gate's messages name the option already
      throw InputError((what.rfind("--friction", 0) == 0 ? "" : "--friction: ") + what +
                       " (expected none or a Table 6.1-format nodes CSV)");
    }
  check_threads(threads);
  s.cycles = cycles;
  if (!(s.speed > 0)) throw std::invalid_argument("--speed: expected a punch speed > 0 mm/s, found " + fmt(s.speed));
  if (!(s.stroke > 0)) throw std::invalid_argument("--stroke: expected a travel > 0 mm, found " + fmt(s.stroke));
  if (s.cycles < 100) throw std::invalid_argument("--cycles: expected at least 100, found " + std::to_string(s.cycles));
  if (s.refine < 1 || s.refine > 8) throw std::invalid_argument("--refine: expected 1 to 8, found " + std::to_string(s.refine));
  if (punch_radius < 0 || die_radius < 0) throw std::invalid_argument("--punch-radius/--die-radius: expected >= 0 mm");
  if (punch_radius > 0) s.punch_radius = punch_radius;
  if (die_radius > 0) s.die_radius = die_radius;
  s.threads = threads;  // set in the deck's [numerics] by the builder
  // The builder reads the base deck's spec back through the deck reader under the base deck's
  // name, with line numbers of the spec it wrote, not of any file the user has: its messages,
  // as the written deck's, name the options.
  std::vector<KeyOptions> keys = {{"numerics", "--cycles, --stroke, --speed or --material"},
                                  {"mesh", "--refine"},
                                  {"material", "--material"},
                                  {"contact", "--friction"},
                                  {"output", "--cycles or --stroke"},
                                  {"tool", "--material or --cycles"}};
  if (opt.given("base"))  // the user's base deck sets every key the options leave
    for (auto& k : keys) k.options += " (or the --base deck's " + k.key + ")";
  // A --base deck the builder or the deck it writes refuses: when the base deck is itself refused
  // by the deck reader, its own file:line: key is said (before 2026-12-05 a hand-edited base deck's
  // bad value was named only as "--material or --cycles (or the --base deck's tool)").
  const auto base_problem = [&]() -> std::string {
    if (!opt.given("base")) return {};
    try {
      (void)io::read_deck(s.deck);
    } catch (const std::exception& e) {
      return std::string("--base: ") + e.what();
    }
    return {};
  };
  std::string text;
  try {
    text = sim::cup_deck_text(s);
  } catch (const InputError& e) {
    if (const std::string b = base_problem(); !b.empty()) throw InputError(b);
    std::string what = user_words(e.what(), s.deck, "cup-deck", keys);
    // The tool radii the builder checks against the base deck's punch wall and die hole.
    if (const std::size_t at = what.find(s.deck + ": punch radius "); at == 0 && punch_radius > 0)
      what = "--punch-radius: " + what.substr(s.deck.size() + 2) + " (the punch wall radius of " + s.deck + ")";
    else if (const std::size_t dt = what.find(s.deck + ": die radius "); dt == 0 && die_radius > 0)
      what = "--die-radius: " + what.substr(s.deck.size() + 2);
    throw InputError(what);
  }
  try {
    checked_deck(text, "cup-deck", keys);
  } catch (const InputError&) {
    if (const std::string b = base_problem(); !b.empty()) throw InputError(b);
    throw;
  }
  std::cout << text;
  return 0;
}

}  // namespace drawbend::cli
