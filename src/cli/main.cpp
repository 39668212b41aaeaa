// drawbend: the command-line front end.
//   drawbend run CASE.toml [--out DIR] [--threads N] [--quiet]
// Runs one case deck, printing progress and an end summary (energy balance,
// hourglass and kinetic energy ratios, added mass).  Exit codes: 0 ok,
// 2 bad input (one clear message), 3 numerical failure.
#include <iostream>
#include <string>

#include "cli/loop_cmd.hpp"
#include "core/csv.hpp"
#include "core/options.hpp"
#include "io/deck.hpp"
#include "io/run_case.hpp"

namespace drawbend::cli {
int drawbend_deck_command(int argc, char** argv);
}

int main(int argc, char** argv) {
  using namespace drawbend;
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << "usage: drawbend run CASE.toml [--out DIR] [--threads N] [--quiet]\n"
                 "  Runs an explicit finite-element case deck (format: data/cases/README.md).\n"
                 "       drawbend drawbend-deck [--pin-diameter D ...] [--run DIR]\n"
                 "  Writes (or runs) the draw-bend deck of the chapters' builder; --help lists its options.\n"
                 "       drawbend loop DATA.csv --out DIR [options]  (see drawbend loop --help)\n"
                 "       drawbend synth --effect E | --from-thesis --out DIR  (see drawbend synth --help)\n";
    return argc < 2 ? 2 : 0;
  }
  const std::string cmd = argv[1];
  if (cmd == "drawbend-deck") {
    try {
      return cli::drawbend_deck_command(argc - 1, argv + 1);
    } catch (const InputError& e) {
      std::cerr << "input error: " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      return 3;
    }
  }
  if (cmd == "loop") return cli::loop_main(argc - 1, argv + 1);    // loop_cmd.cpp
  if (cmd == "synth") return cli::synth_main(argc - 1, argv + 1);  // loop_cmd.cpp
  if (cmd != "run") {
    std::cerr << "drawbend: unknown command '" << cmd << "' (expected: run, loop, synth)\n";
    return 2;
  }
  if (argc < 3) {
    std::cerr << "drawbend run: missing CASE.toml\n";
    return 2;
  }
  const std::string deck_path = argv[2];
  io::RunOptions ro;
  bool quiet = false;
  Options opt("drawbend run CASE.toml", "Run one case deck.");
  opt.add(ro.out_dir, "out", "output directory");
  opt.add(ro.threads, "threads", "OpenMP threads (0: deck or default)");
  opt.add_flag(quiet, "quiet", "no progress line");
  try {
    if (!opt.parse(argc - 2, argv + 2)) return 0;
    ro.quiet = quiet;
    io::Deck deck = io::read_deck(deck_path);
    io::run_case(deck, ro, std::cout);
    return 0;
  } catch (const InputError& e) {
    std::cerr << "input error: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "input error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 3;
  }
}
