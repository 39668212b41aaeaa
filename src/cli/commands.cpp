#include "cli/commands.hpp"

#include "cli/exit_codes.hpp"
#include "cli/loop_cmd.hpp"

namespace drawbend::cli {
int drawbend_deck_command(int argc, char** argv);
int block_deck_command(int argc, char** argv);
int strip_deck_command(int argc, char** argv);
int cup_deck_command(int argc, char** argv);
int plan_command(int argc, char** argv);
int calibrate_command(int argc, char** argv);

namespace {
// The deck builders and the model loop throw; these give them their exit codes.
template <int (*F)(int, char**)>
int with_codes(int argc, char** argv) {
  return with_exit_codes([&] { return F(argc, argv); });
}
int model_loop(int argc, char** argv) { return model_loop_command(argc, argv); }
}  // namespace

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"run", "CASE.toml --out DIR", "run one finite-element case deck (format: data/cases/README.md)", run_main},
      {"drawbend-deck", "[--run DIR]", "write or run a draw-bend deck (full-strip forces; --basis half)",
       with_codes<drawbend_deck_command>},
      {"block-deck", "[--out FILE]", "write a block-sliding deck (Chapter 6, mu(p, v) surface)",
       with_codes<block_deck_command>},
      {"strip-deck", "[--out FILE]", "write a strip-draw deck (Chapter 3, Stribeck law)", with_codes<strip_deck_command>},
      {"cup-deck", "", "write a cup-drawing deck (thesis Sec. 6.6; radii, material, friction)",
       with_codes<cup_deck_command>},
      {"loop", "DATA.csv --out DIR", "close the loop on measured draw-bend data (writes loop.md)", loop_main},
      {"model-loop", "DATA.csv --out DIR", "re-run the draw-bend FE model with candidate effects",
       with_codes<model_loop>},
      {"synth", "--out DIR", "synthetic draw-bend data with a hidden law, or the thesis data", synth_main},
      {"export", "MODEL.toml --to X", "a friction_model.toml for LS-DYNA, OpenRadioss or Abaqus", export_main},
      {"calibrate", "TESTS.csv --out DIR", "fit Yld2004-18p to a sheet's material tests (material TOML, table)",
       with_codes<calibrate_command>},
      {"plan", "DECK_OR_FOLDER...", "predicted CPU time, memory and makespan of decks (docs/cluster.md)",
       with_codes<plan_command>},
  };
  return table;
}

}  // namespace drawbend::cli
