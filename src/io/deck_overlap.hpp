#pragma once
// A sheet that starts inside a rigid tool (a pin, punch, die or holder placed
// over the initial mesh) is refused before the run, at the tool's line of the
// deck: the penalty contact pushes a node out with a pressure that grows with
// its depth, and does not see it at all beyond twice its element size, so a
// deep overlap either explodes in the first cycles or runs on as if the tool
// were not there (exit 0, a nonsense answer).  The tolerance and its reason:
// deck_overlap.cpp.
#include <toml++/toml.h>

#include "fe/model.hpp"
#include "io/deck_context.hpp"

namespace drawbend::io {

/// Records a problem at each [[tool]] that a contact pair's face-set nodes
/// start inside by more than the tolerance (the deepest node named, in mm).
void check_initial_overlap(const DeckContext& c, const toml::table& root, const fe::Model& m);

}  // namespace drawbend::io
