// drawbend run CASE.toml [--out DIR] [--threads N] [--quiet] [--progress-every S]
//              [--checkpoint-every N|Ts] [--restart CHECKPOINT]
// Runs one case deck, printing progress and an end summary (energy balance,
// hourglass and kinetic energy ratios, added mass).  Exit codes: 0 ok,
// 2 bad input (every problem of the deck, each with file:line: key), 3 a
// numerical fault (a guard of fe/guards.hpp, naming element or node and time).
#include <cmath>
#include <csignal>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/threads.hpp"
#include "core/csv.hpp"
#include "core/options.hpp"
#include "io/deck.hpp"
#include "cli/option_bounds.hpp"
#include "core/file_gate.hpp"
#include "io/run_case.hpp"
#include "io/run_result.hpp"

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

namespace drawbend::cli {

int run_main(int argc, char** argv) {
  // `drawbend run --help` prints the options below without a deck.
  const bool help = argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h");
  if (argc < 2) {
    std::cerr << "drawbend run: missing CASE.toml (drawbend run --help lists the options)\n";
    return 2;
  }
  const std::string deck_path = argv[1];
  if (!help && deck_path.rfind("--", 0) == 0) {  // `drawbend run --out DIR deck.toml`: the deck comes first
    std::cerr << "input error: drawbend run: expected CASE.toml first, found the option '" << clip_for_message(deck_path)
              << "' (drawbend run CASE.toml --out DIR; --help lists the options)\n";
    return 2;
  }
  io::RunOptions ro;
  bool quiet = false;
  std::string every;
  int halt = 0;
  Options opt("drawbend run CASE.toml",
              "Run one case deck. Writes result.toml (the answer: for a draw-bend deck F_X, F_Y, F_B, mu by Eq. (2.3)), history.csv, summary.csv, contact maps and ParaView frames (open fields.pvd: the sheet and the tools; docs/paraview.md) to "
              "--out; the sheet's points are the deformed positions (do not warp them by the displacement again).");
  opt.add(ro.out_dir, "out", "output directory");
  opt.add(ro.threads, "threads", "OpenMP threads (0: deck or default)");
  opt.add_flag(quiet, "quiet", "no progress line");
  opt.add(ro.progress_every_s, "progress-every", "wall-clock seconds between progress lines (> 0)");
  opt.add(every, "checkpoint-every",
          "write <out>/checkpoint.bin every N cycles (e.g. 500) or T simulated seconds (e.g. 2e-3s)");
  opt.add(ro.restart, "restart", "continue from this checkpoint (same deck; use the same --out)");
  opt.example("drawbend run data/cases/block_slide.toml --out my-block --quiet");
  opt.example("drawbend drawbend-deck --pin-diameter 12.7 --element-length 1.5 --through 2 --draw-length 12 --friction '{ law = \"coulomb\", mu = 0.1 }' > my.toml");
  opt.example("drawbend run my.toml --out my-run --threads 2    # my-run/result.toml: F_X, F_Y, F_B, mu");
  opt.add(halt, "halt-after-cycles", "stop after the first checkpoint at or beyond this cycle (tests restarts)");
  opt.range("progress-every", 0, 1e6, "s", true).range("halt-after-cycles", 0, 2e9);
  opt.add(ro.result.basis, "basis", "draw-bend decks: basis of --bending-force and the printed forces, full or half");
  opt.add(ro.result.bending_force, "bending-force",
          "draw-bend decks: F_B [N] on --basis for mu by Eq. (2.3) (0: this run if frictionless, else Swift's Eq. (2.1))");
  opt.add(ro.result.yield_stress, "yield-stress", "draw-bend decks: yield stress [MPa] of Swift's F_B (0: Table 5.1, RD)");
  opt.range("bending-force", 0, bounds::kForceN, "N").range("yield-stress", 0, 1e4, "MPa");
  return with_exit_codes([&] {
    if (!opt.parse(argc - (help ? 0 : 1), argv + (help ? 0 : 1))) return 0;
    check_threads(ro.threads);
    ro.quiet = quiet;
    if (!(ro.progress_every_s > 0) || !std::isfinite(ro.progress_every_s))
      throw std::invalid_argument("--progress-every must be a positive number of seconds");
    ro.halt_after_cycles = halt;
    if (ro.result.basis != "full" && ro.result.basis != "half")
      throw std::invalid_argument("--basis: expected full or half, found '" + ro.result.basis + "'");
    if (!(ro.result.bending_force >= 0) || !std::isfinite(ro.result.bending_force))
      throw std::invalid_argument("--bending-force: expected a force >= 0 N (0: estimated)");
    if (!(ro.result.yield_stress >= 0) || !std::isfinite(ro.result.yield_stress))
      throw std::invalid_argument("--yield-stress: expected a stress >= 0 MPa (0: Table 5.1, RD)");
    if (!every.empty()) io::parse_checkpoint_every(every, ro);
    name_input(ro.restart, "--restart");  // the file gate names the option (core/file_gate.hpp)
    if (halt > 0 && every.empty()) throw std::invalid_argument("--halt-after-cycles needs --checkpoint-every");
    ensure_writable_dir(ro.out_dir, "--out");  // before any work
    watch_stop_signals();
    ro.stop = &g_stop;
    io::Deck deck = io::read_deck(deck_path);
    // The draw-bend answer's options on another deck were ignored with exit 0 before 2026-12-04.
    opt.only_when(io::is_drawbend_deck(deck), {"basis", "bending-force", "yield-stress"},
                  "with a draw-bend deck (history signals outlet_force_N and back_tension_N, a step 'draw')");
    const io::RunSummary r = io::run_case(deck, ro, std::cout);
    return r.interrupted ? 128 + r.interrupted : 0;
  });
}

}  // namespace drawbend::cli
