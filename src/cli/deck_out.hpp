#pragma once
// Where a deck-writing command (block-deck, strip-deck) puts its deck: the file
// --out (written atomically, its folder made if missing) or standard output.
#include <filesystem>
#include <iostream>
#include <string>

#include "core/csv.hpp"

namespace drawbend::cli {

inline int write_deck_out(const std::string& text, const std::string& out, const std::string& command) {
  if (out.empty()) {
    std::cout << text;
    return 0;
  }
  const std::filesystem::path p(out);
  if (p.has_parent_path()) ensure_writable_dir(p.parent_path().string(), "--out");
  write_file_atomic(out, text);
  std::cout << command << ": wrote " << out << " (run it with: drawbend run " << out << " --out DIR)\n";
  return 0;
}

}  // namespace drawbend::cli
