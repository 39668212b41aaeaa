#pragma once
// Where a deck-writing command (block-deck, strip-deck) puts its deck: the file
// --out (written atomically, its folder made if missing, the tables it reads copied
// beside it) or standard output (absolute paths).
#include <filesystem>
#include <iostream>
#include <string>

#include "core/csv.hpp"
#include "core/file_gate.hpp"
#include "io/deck.hpp"
#include "io/portable_paths.hpp"

namespace drawbend::cli {

/// A builder's deck passes the checks `drawbend run` applies (io::parse_deck:
/// every key, the material and the friction law, the files they name, the
/// cost limits) before it is printed or written: a builder never writes a
/// deck that `run` then refuses (issue 53: drawbend-deck wrote r0 = -1).
inline const std::string& checked_deck(const std::string& text, const std::string& command) {
  try {
    // Its warnings (e.g. one element through the thickness) are said now, without the
    // generated deck's line numbers, which the user never sees.
    for (const auto& w : io::parse_deck(text, command + ".toml").warnings) {
      const std::string gen = command + ".toml:";
      std::string say = w;
      if (const std::size_t at = say.find(": ", gen.size()); say.rfind(gen, 0) == 0 && at != std::string::npos)
        say = say.substr(at + 2);
      std::cerr << "warning: " << command << " (the deck it writes): " << say << "\n";
    }
  } catch (const InputError& e) {
    throw InputError(std::string(e.what()) + "\n(" + command + " refuses to write a deck that `drawbend run` would refuse)");
  }
  return text;
}

inline int write_deck_out(const std::string& text, const std::string& out, const std::string& command) {
  checked_deck(text, command);
  if (out.empty()) {
    std::cout << text;
    return 0;
  }
  const std::filesystem::path p(out);
  if (p.has_parent_path()) ensure_writable_dir(p.parent_path().string(), "--out");
  // The tables the deck reads are copied beside it and named by file name (io/portable_paths.hpp).
  const std::string dir = p.has_parent_path() ? p.parent_path().string() : std::string(".");
  name_input(out, "--out");
  write_output(out, io::portable_deck(text, dir));  // never replaces a folder, FIFO or device (core/file_gate.hpp)
  std::cout << command << ": wrote " << out << " (run it with: drawbend run " << out << " --out DIR)\n";
  return 0;
}

}  // namespace drawbend::cli
