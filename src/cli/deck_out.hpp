#pragma once
// Where a deck-writing command (block-deck, strip-deck) puts its deck: the file
// --out (written atomically, its folder made if missing, the tables it reads copied
// beside it) or standard output (absolute paths).
#include <cctype>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "core/file_gate.hpp"
#include "io/deck.hpp"
#include "io/portable_paths.hpp"

namespace drawbend::cli {

/// The options of a builder that set a key of the deck it writes (the first
/// entry whose key starts the message's key wins), for its messages.
struct KeyOptions {
  std::string key, options;
};

/// A message of the deck a builder writes in the user's words: each
/// "NAME:LINE: key: " of that deck (`generated`, a name the user never sees)
/// becomes "OPTIONS (key of the deck COMMAND writes): ", or without a known
/// option "COMMAND (the deck it writes): key: "; "N problems in NAME:" names the
/// command (before 2026-12-04 `drawbend-deck --speed 0.001` said
/// "drawbend-deck.toml:26: numerics.mass_scaling").
inline std::string user_words(std::string msg, const std::string& generated, const std::string& command,
                              const std::vector<KeyOptions>& keys) {
  const std::string tag = generated + ":";
  for (std::size_t at = msg.find(tag); at != std::string::npos; at = msg.find(tag, at + 1)) {
    std::size_t p = at + tag.size();
    while (p < msg.size() && std::isdigit(static_cast<unsigned char>(msg[p]))) ++p;
    if (p == at + tag.size() || msg.compare(p, 2, ": ") != 0) {  // "problems in NAME:" (no line)
      if (at >= 12 && msg.compare(at - 12, 12, "problems in ") == 0)
        msg.replace(at, tag.size(), "the deck " + command + " writes:");
      continue;
    }
    const std::size_t key_end = msg.find(": ", p + 2);
    const std::string key = key_end == std::string::npos ? "" : msg.substr(p + 2, key_end - p - 2);
    std::string words = command + " (the deck it writes): " + key + ": ";
    for (const KeyOptions& k : keys)
      if (!key.empty() && key.rfind(k.key, 0) == 0) {
        words = k.options + " (" + key + " of the deck " + command + " writes): ";
        break;
      }
    if (key_end == std::string::npos) words = command + " (the deck it writes): ";
    msg.replace(at, (key_end == std::string::npos ? p + 2 : key_end + 2) - at, words);
  }
  return msg;
}

/// A builder's deck passes the checks `drawbend run` applies (io::parse_deck:
/// every key, the material and the friction law, the files they name, the
/// cost limits) before it is printed or written: a builder never writes a
/// deck that `run` then refuses (issue 53: drawbend-deck wrote r0 = -1).
/// Its messages and warnings name the options (user_words), not the lines of
/// a deck the user has not seen.  `warn` false: the warnings are left to the
/// run that follows (drawbend-deck --run), which says them once.
inline const std::string& checked_deck(const std::string& text, const std::string& command,
                                       const std::vector<KeyOptions>& keys = {}, bool warn = true) {
  try {
    for (const auto& w : io::parse_deck(text, command + ".toml").warnings)
      if (warn) std::cerr << "warning: " << user_words(w, command + ".toml", command, keys) << "\n";
  } catch (const InputError& e) {
    throw InputError(user_words(e.what(), command + ".toml", command, keys) + "\n(" + command +
                     " refuses to write a deck that `drawbend run` would refuse)");
  }
  return text;
}

inline int write_deck_out(const std::string& text, const std::string& out, const std::string& command,
                          const std::vector<KeyOptions>& keys = {}) {
  checked_deck(text, command, keys);
  if (out.empty()) {
    std::cout << text;
    return 0;
  }
  // "dir/" names a folder: refused before the folder is made and the tables copied into it.
  if (out.back() == '/') throw InputError("--out '" + out + "': expected a file name, found a folder's (it ends in '/')");
  const std::filesystem::path p(out);
  if (p.has_parent_path()) ensure_writable_dir(p.parent_path().string(), "--out");
  // The tables the deck reads are copied beside it and named by file name (io/portable_paths.hpp).
  const std::string dir = p.has_parent_path() ? p.parent_path().string() : std::string(".");
  name_input(out, "--out");
  refuse_input_as_output(out);  // --out naming --hardening or another table read replaced it
  write_output(out, io::portable_deck(text, dir));  // never replaces a folder, FIFO or device (core/file_gate.hpp)
  std::cout << command << ": wrote " << out << " (run it with: drawbend run " << out << " --out DIR)\n";
  return 0;
}

}  // namespace drawbend::cli
