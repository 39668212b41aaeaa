// drawbend: the command-line front end.  The commands are one table
// (cli/commands.hpp): the usage text, the dispatch and the message for an
// unknown command come from it.
#include <algorithm>
#include <iostream>
#include <string>

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
  usage += "  --version                    print the version and commit\n"
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
  std::string names;
  for (const cli::Command& c : commands) {
    if (cmd == c.name) return c.main(argc - 1, argv + 1);
    names += (names.empty() ? "" : ", ") + std::string(c.name);
  }
  std::cerr << "drawbend: unknown command '" << cmd << "' (expected: " << names << "; see drawbend --help)\n";
  return 2;
}
