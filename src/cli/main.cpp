// drawbend: the command-line front end.  The commands are one table
// (cli/commands.hpp): the usage text, the dispatch and the message for an
// unknown command come from it; `help [COMMAND]` and `version` are this file's.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"

int main(int argc, char** argv) {
  using namespace drawbend;
  const auto& commands = cli::commands();
  std::string usage = "usage: drawbend COMMAND [options]    (drawbend COMMAND --help: that command's options)\n";
  for (const cli::Command& c : commands) {
    std::string left = std::string(c.name) + (*c.synopsis ? " " : "") + c.synopsis;
    left += std::string(std::max<std::size_t>(2, 29 - std::min<std::size_t>(29, left.size())), ' ');
    usage += "  " + left + c.what + "\n";
  }
  usage += "  help [COMMAND]               this list, or that command's options and examples (= COMMAND --help)\n"
           "  version, --version           print the version and commit\n"
           "Units: mm, N, MPa, s.  Exit codes: 0 done, 2 input error, 3 numerical fault.\n"
           "Examples (from the source folder after make or make test; drawbend is build/src/drawbend):\n"
           "  drawbend drawbend-deck --pin-diameter 12.7 --element-length 1.5 --through 2 --draw-length 12 --run my-free\n"
           "  drawbend loop data/measured/thesis_drawbend.csv --out my-loop\n"
           "  drawbend help run\n";
  // `drawbend help CMD` is `drawbend CMD --help`; `help`, `version` and
  // `--help` take nothing more (a stray word is an input error, not exit 0).
  const std::string first = argc >= 2 ? argv[1] : "";
  const bool bare = first == "version" || first == "--version" || first == "--help" || first == "-h" ||
                    (first == "help" && argc >= 3 && (std::string(argv[2]) == "help" || std::string(argv[2]) == "version"));
  // `drawbend version --help` (and `help version`) as every command's --help: its usage, exit 0 (exit 2
  // before 2026-12-05; `help version` printed the version).
  if ((first == "version" && argc == 3 && (std::string(argv[2]) == "--help" || std::string(argv[2]) == "-h")) ||
      (first == "help" && argc == 3 && std::string(argv[2]) == "version")) {
    std::cout << "Usage: drawbend version\nPrint the version and the commit it was built from (also drawbend --version); "
                 "takes no options.\n";
    return 0;
  }
  if (bare && argc > (first == "help" ? 3 : 2)) {
    std::cerr << "input error: drawbend " << first << (first == "help" ? std::string(" ") + argv[2] : "")
              << ": unexpected argument '" << argv[first == "help" ? 3 : 2] << "' (it takes none; see drawbend --help)\n";
    return 2;
  }
  if (first == "help" && argc > 3) {  // help CMD takes nothing more
    std::cerr << "input error: drawbend help " << argv[2] << ": unexpected argument '" << argv[3]
              << "' (help takes one command name; see drawbend --help)\n";
    return 2;
  }
  if (first == "help" && argc == 3 && std::string(argv[2]) == "help") argc = 2;  // help help: the list
  std::vector<char*> args(argv, argv + argc);
  static char help_flag[] = "--help";
  if (argc >= 3 && std::string(argv[1]) == "help") {
    args.erase(args.begin() + 1);  // drawbend CMD ...
    args.insert(args.begin() + 2, help_flag);
    argc = static_cast<int>(args.size());
    argv = args.data();
  } else if (argc == 2 && std::string(argv[1]) == "help") {
    std::cout << usage;
    return 0;
  }
  if (argc >= 2 && (std::string(argv[1]) == "--version" || std::string(argv[1]) == "version")) {
    std::cout << "drawbend " << DRAWBEND_VERSION << " (" << DRAWBEND_GIT_DESCRIBE << ")\n";
    return 0;
  }
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    (argc < 2 ? std::cerr : std::cout) << usage;
    return argc < 2 ? 2 : 0;
  }
  const std::string cmd = argv[1];
  std::string names;
  for (const cli::Command& c : commands) {
    if (cmd == c.name) return c.main(argc - 1, argv + 1);
    names += (names.empty() ? "" : ", ") + std::string(c.name);
  }
  std::cerr << "drawbend: unknown command '" << cmd << "' (expected: " << names
            << ", help, version; see drawbend --help)\n";
  return 2;
}
