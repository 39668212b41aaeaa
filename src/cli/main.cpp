// drawbend: the command-line front end.
//   drawbend run CASE.toml [--out DIR] [--threads N] [--quiet] [--progress-every S]
//                [--checkpoint-every N|Ts] [--restart CHECKPOINT]
// Runs one case deck, printing progress and an end summary (energy balance,
// hourglass and kinetic energy ratios, added mass).  Exit codes: 0 ok,
// 2 bad input (every problem of the deck, each with file:line: key), 3 a
// numerical fault (a guard of fe/guards.hpp, naming element or node and time).
#include <cmath>
#include <csignal>
#include <iostream>
#include <string>

#include "cli/loop_cmd.hpp"
#include "core/csv.hpp"
#include "core/file_gate.hpp"
#include "core/options.hpp"
#include "fe/guards.hpp"
#include "io/deck.hpp"
#include "io/run_case.hpp"
#include "cli/exit_codes.hpp"
#include "cli/threads.hpp"

namespace drawbend::cli {
int drawbend_deck_command(int argc, char** argv);
int block_deck_command(int argc, char** argv);
int strip_deck_command(int argc, char** argv);
int cup_deck_command(int argc, char** argv);
}

namespace {
// SIGINT/SIGTERM during `drawbend run`: the run checkpoints at the next cycle
// boundary, prints how to continue and exits 128 + the signal (130, 143).  A
// second signal ends the program at once (the handler resets itself).
volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_stop_signal(int sig) { g_stop = sig; }
void watch_stop_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sa.sa_flags = SA_RESETHAND;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}
}  // namespace

int main(int argc, char** argv) {
  using namespace drawbend;
  const char* usage =
      "usage: drawbend COMMAND [options]    (drawbend COMMAND --help: that command's options)\n"
      "  run CASE.toml --out DIR      run one finite-element case deck (format: data/cases/README.md)\n"
      "  drawbend-deck [--run DIR]    write or run a draw-bend deck (full-strip forces; --basis half)\n"
      "  block-deck [--out FILE]      write a block-sliding deck (Chapter 6, mu(p, v) surface)\n"
      "  strip-deck [--out FILE]      write a strip-draw deck (Chapter 3, Stribeck law)\n"
      "  cup-deck                     write a cup-drawing deck (thesis Sec. 6.6; radii, material, friction)\n"
      "  loop DATA.csv --out DIR      close the loop on measured draw-bend data (writes loop.md)\n"
      "  model-loop DATA.csv --out DIR  re-run the draw-bend FE model with candidate effects\n"
      "  synth --out DIR              synthetic draw-bend data with a hidden law, or the thesis data\n"
      "  export MODEL.toml --to X     a friction_model.toml for LS-DYNA, OpenRadioss or Abaqus\n"
      "  --version                    print the version and commit\n"
      "Units: mm, N, MPa, s.  Exit codes: 0 done, 2 input error, 3 numerical fault.\n";
  if (argc >= 2 && std::string(argv[1]) == "--version") {
    std::cout << "drawbend " << DRAWBEND_VERSION << " (" << DRAWBEND_GIT_DESCRIBE << ")\n";
    return 0;
  }
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    (argc < 2 ? std::cerr : std::cout) << usage;
    return argc < 2 ? 2 : 0;
  }
  const std::string cmd = argv[1];
  if (cmd == "drawbend-deck") return cli::with_exit_codes([&] { return cli::drawbend_deck_command(argc - 1, argv + 1); });
  if (cmd == "block-deck") return cli::with_exit_codes([&] { return cli::block_deck_command(argc - 1, argv + 1); });
  if (cmd == "strip-deck") return cli::with_exit_codes([&] { return cli::strip_deck_command(argc - 1, argv + 1); });
  if (cmd == "cup-deck") return cli::with_exit_codes([&] { return cli::cup_deck_command(argc - 1, argv + 1); });
  if (cmd == "model-loop") return cli::with_exit_codes([&] { return cli::model_loop_command(argc - 1, argv + 1); });
  if (cmd == "loop") return cli::loop_main(argc - 1, argv + 1);    // loop_cmd.cpp
  if (cmd == "synth") return cli::synth_main(argc - 1, argv + 1);  // loop_cmd.cpp
  if (cmd == "export") return cli::export_main(argc - 1, argv + 1);  // export_cmd.cpp
  if (cmd != "run") {
    std::cerr << "drawbend: unknown command '" << cmd << "' (expected: run, drawbend-deck, block-deck, strip-deck, cup-deck, model-loop, loop, synth, export; see drawbend --help)\n";
    return 2;
  }
  // `drawbend run --help` prints the options below without a deck.
  const bool help = argc >= 3 && (std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h");
  if (argc < 3) {
    std::cerr << "drawbend run: missing CASE.toml (drawbend run --help lists the options)\n";
    return 2;
  }
  const std::string deck_path = argv[2];
  io::RunOptions ro;
  bool quiet = false;
  std::string every;
  int halt = 0;
  Options opt("drawbend run CASE.toml",
              "Run one case deck. Writes history.csv, summary.csv, contact maps and ParaView .vtu/.pvd frames to "
              "--out; the .vtu points are the deformed positions (do not warp them by the displacement again).");
  opt.add(ro.out_dir, "out", "output directory");
  opt.add(ro.threads, "threads", "OpenMP threads (0: deck or default)");
  opt.add_flag(quiet, "quiet", "no progress line");
  opt.add(ro.progress_every_s, "progress-every", "wall-clock seconds between progress lines (> 0)");
  opt.add(every, "checkpoint-every",
          "write <out>/checkpoint.bin every N cycles (e.g. 500) or T simulated seconds (e.g. 2e-3s)");
  opt.add(ro.restart, "restart", "continue from this checkpoint (same deck; use the same --out)");
  opt.add(halt, "halt-after-cycles", "stop after the first checkpoint at or beyond this cycle (tests restarts)");
  opt.range("progress-every", 0, 1e6, "s", true).range("halt-after-cycles", 0, 2e9);
  return cli::with_exit_codes([&] {
    if (!opt.parse(argc - (help ? 1 : 2), argv + (help ? 1 : 2))) return 0;
    cli::check_threads(ro.threads);
    ro.quiet = quiet;
    if (!(ro.progress_every_s > 0) || !std::isfinite(ro.progress_every_s))
      throw std::invalid_argument("--progress-every must be a positive number of seconds");
    ro.halt_after_cycles = halt;
    if (!every.empty()) io::parse_checkpoint_every(every, ro);
    name_input(ro.restart, "--restart");  // the file gate names the option (core/file_gate.hpp)
    if (halt > 0 && every.empty()) throw std::invalid_argument("--halt-after-cycles needs --checkpoint-every");
    ensure_writable_dir(ro.out_dir, "--out");  // before any work
    watch_stop_signals();
    ro.stop = &g_stop;
    io::Deck deck = io::read_deck(deck_path);
    const io::RunSummary r = io::run_case(deck, ro, std::cout);
    return r.interrupted ? 128 + r.interrupted : 0;
  });
}
