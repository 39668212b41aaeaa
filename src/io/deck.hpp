#pragma once
// Case decks: TOML files that describe a complete explicit analysis, so that a
// case changes without recompiling.  The format is documented in
// data/cases/README.md; every key is checked (a typo is an error, not
// silently ignored) and every message names the file, the line and the key.
#include <cstdint>
#include <string>
#include <vector>

#include "fe/model.hpp"

namespace drawbend::io {

/// What to record while a case runs.
struct HistorySignal {
  std::string name;     ///< column name
  std::string kind;     ///< "reaction", "applied" (node set) or "tool_force", "tool_offset" (tool)
  std::string target;   ///< node set or tool name
  int component = 0;    ///< 0, 1, 2 = x, y, z
  /// kind "strain": the element whose reference centroid is nearest `point`
  /// [mm]; component 0 = logarithmic strain along the element's reference x
  /// edges, 1 = equivalent plastic strain.
  fe::Vec3 point{0, 0, 0};
};

struct OutputSpec {
  double history_interval = 0;  ///< [s]; 0: 200 samples per step
  int fields_per_step = 1;      ///< VTU snapshots per step (>= 1: at least the end of each step)
  std::vector<HistorySignal> history;
};

struct Deck {
  std::string path;
  std::uint64_t hash = 0;  ///< FNV-1a of the deck's text (checkpoints must match it)
  fe::Model model;
  OutputSpec output;
  int threads = 0;  ///< 0: OpenMP default
};

/// Read and validate a deck; throws drawbend::InputError with file:line: key: message.
Deck read_deck(const std::string& path);
/// The same from a string (path used in messages and for relative file names).
Deck parse_deck(const std::string& text, const std::string& path);

}  // namespace drawbend::io
