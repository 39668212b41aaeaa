#pragma once
// Where a deck-writing command (block-deck, strip-deck) puts its deck: the file
// --out (written atomically, its folder made if missing, the tables it reads copied
// beside it) or standard output (absolute paths).
#include <filesystem>
#include <iostream>
#include <string>

#include "core/csv.hpp"
#include "io/portable_paths.hpp"

namespace drawbend::cli {

inline int write_deck_out(const std::string& text, const std::string& out, const std::string& command) {
  if (out.empty()) {
    std::cout << text;
    return 0;
  }
  const std::filesystem::path p(out);
  if (p.has_parent_path()) ensure_writable_dir(p.parent_path().string(), "--out");
  // The tables the deck reads are copied beside it and named by file name (io/portable_paths.hpp).
  const std::string dir = p.has_parent_path() ? p.parent_path().string() : std::string(".");
  write_file_atomic(out, io::portable_deck(text, dir));
  std::cout << command << ": wrote " << out << " (run it with: drawbend run " << out << " --out DIR)\n";
  return 0;
}

}  // namespace drawbend::cli
