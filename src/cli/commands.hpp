#pragma once
// The commands of `drawbend`, in one table: the usage text, the dispatch and
// the "unknown command" message all come from it (cli/main.cpp).  A new
// command is one row in commands.cpp and its *_cmd.cpp.
#include <vector>

namespace drawbend::cli {

struct Command {
  const char* name;      ///< as typed after `drawbend`
  const char* synopsis;  ///< its arguments in the usage line ("" for none)
  const char* what;      ///< one line for the usage text
  int (*main)(int argc, char** argv);  ///< argv[0] = name; returns the exit code (cli/exit_codes.hpp)
};

/// Every command, in the order of the usage text.
const std::vector<Command>& commands();

/// `drawbend run` (run_cmd.cpp); argv[0] = "run".
int run_main(int argc, char** argv);

}  // namespace drawbend::cli
