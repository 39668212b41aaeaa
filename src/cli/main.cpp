// drawbend: the command-line front end.
//   drawbend run CASE.toml [--out DIR] [--threads N] [--quiet]
//                [--checkpoint-every N|Ts] [--restart CHECKPOINT]
// Runs one case deck, printing progress and an end summary (energy balance,
// hourglass and kinetic energy ratios, added mass).  Exit codes: 0 ok,
// 2 bad input (every problem of the deck, each with file:line: key), 3 a
// numerical fault (a guard of fe/guards.hpp, naming element or node and time).
#include <iostream>
#include <string>

#include "cli/loop_cmd.hpp"
#include "core/csv.hpp"
#include "core/options.hpp"
#include "fe/guards.hpp"
#include "io/deck.hpp"
#include "io/run_case.hpp"
#include "cli/exit_codes.hpp"

namespace drawbend::cli {
int drawbend_deck_command(int argc, char** argv);
int model_loop_command(int argc, char** argv);  // model_loop_cmd.cpp
}

int main(int argc, char** argv) {
  using namespace drawbend;
  const char* usage =
      "usage: drawbend run CASE.toml [--out DIR] [--threads N] [--quiet] [--checkpoint-every N|Ts] "
      "[--restart CHECKPOINT]\n"
      "  Runs an explicit finite-element case deck (format: data/cases/README.md).\n"
      "  Exit codes: 0 done, 2 input error, 3 numerical fault.\n"
      "       drawbend drawbend-deck [--pin-diameter D ...] [--run DIR]\n"
      "  Writes (or runs) the draw-bend deck of the chapters' builder; --help lists its options.\n"
      "       drawbend model-loop DATA.csv --out DIR [options]  (FE candidates; see drawbend model-loop --help)\n"
      "       drawbend loop DATA.csv --out DIR [options]  (see drawbend loop --help)\n"
      "       drawbend synth --effect E | --from-thesis --out DIR  (see drawbend synth --help)\n";
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << usage;
    return argc < 2 ? 2 : 0;
  }
  const std::string cmd = argv[1];
  if (cmd == "drawbend-deck") return cli::with_exit_codes([&] { return cli::drawbend_deck_command(argc - 1, argv + 1); });
  if (cmd == "model-loop") return cli::with_exit_codes([&] { return cli::model_loop_command(argc - 1, argv + 1); });
  if (cmd == "loop") return cli::loop_main(argc - 1, argv + 1);    // loop_cmd.cpp
  if (cmd == "synth") return cli::synth_main(argc - 1, argv + 1);  // loop_cmd.cpp
  if (cmd != "run") {
    std::cerr << "drawbend: unknown command '" << cmd << "' (expected: run, drawbend-deck, model-loop, loop, synth)\n";
    return 2;
  }
  if (argc < 3) {
    std::cerr << "drawbend run: missing CASE.toml\n";
    return 2;
  }
  const std::string deck_path = argv[2];
  io::RunOptions ro;
  bool quiet = false;
  std::string every;
  int halt = 0;
  Options opt("drawbend run CASE.toml", "Run one case deck.");
  opt.add(ro.out_dir, "out", "output directory");
  opt.add(ro.threads, "threads", "OpenMP threads (0: deck or default)");
  opt.add_flag(quiet, "quiet", "no progress line");
  opt.add(every, "checkpoint-every",
          "write <out>/checkpoint.bin every N cycles (e.g. 500) or T simulated seconds (e.g. 2e-3s)");
  opt.add(ro.restart, "restart", "continue from this checkpoint (same deck; use the same --out)");
  opt.add(halt, "halt-after-cycles", "stop after the first checkpoint at or beyond this cycle (tests restarts)");
  return cli::with_exit_codes([&] {
    if (!opt.parse(argc - 2, argv + 2)) return 0;
    ro.quiet = quiet;
    ro.halt_after_cycles = halt;
    if (!every.empty()) io::parse_checkpoint_every(every, ro);
    if (halt > 0 && every.empty()) throw std::invalid_argument("--halt-after-cycles needs --checkpoint-every");
    io::Deck deck = io::read_deck(deck_path);
    io::run_case(deck, ro, std::cout);
    return 0;
  });
}
