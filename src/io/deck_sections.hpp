#pragma once
// Deck sections with repeated entries ([[tool]], [[contact]], [[step]]) and
// the [guards] thresholds.  Each entry is read on its own (InputProblems::attempt),
// so one bad entry does not hide the problems of the others.
#include <string>

#include <toml++/toml.h>

#include "fe/model.hpp"
#include "io/deck_context.hpp"

namespace drawbend::io {

/// [guards]: each key is a limit (number) or { limit = x, action = "error" | "warn" }.
void read_guards(const DeckContext& c, const toml::table& t, fe::Guards& g);
void read_tools(const DeckContext& c, const toml::table& root, fe::Model& m);
/// `mesh_ok`: the mesh was read, so face sets can be checked.
/// [[contact]] pairs.  `texture_axis` is the older spelling of [sheet] rolling_direction: allowed
/// when the deck has no [sheet] rolling direction, and then the same on every pair.
void read_contacts(const DeckContext& c, const toml::table& root, fe::Model& m, const std::string& dir, bool mesh_ok,
                   bool sheet_rd);
void read_steps(const DeckContext& c, const toml::table& root, fe::Model& m, bool mesh_ok);

}  // namespace drawbend::io
