#pragma once
// Every run has a finite, predicted cost before it starts.  A deck is refused
// (input error, exit 2, file:line: key) when its predicted cycles, memory or
// mass-scaling factor exceed the limits of [limits], which the deck may raise;
// doubtful but valid values (moduli or densities outside the range of real
// materials, heavy mass scaling) become warnings.  Limits and their reasons:
// data/cases/README.md, section "Limits".
#include <toml++/toml.h>

#include "core/run_output.hpp"
#include "io/deck.hpp"
#include "io/deck_context.hpp"

namespace drawbend::io {

/// [limits] max_cycles, max_memory_mb, max_mass_factor (read before the mesh,
/// so that a mesh too large for memory is refused before it is built).
void read_limits(const DeckContext& c, const toml::table& root, RunLimits& lim);

/// Predicted memory of a run [MB]: mesh, solver state and the per-step scratch
/// arrays (bytes per node and per element measured, see deck_limits.cpp).
double estimate_memory_mb(double nodes, double elements);

/// Refuses (records a problem at `where`, returns false) a mesh whose memory
/// estimate exceeds lim.max_memory_mb.
bool check_memory(const DeckContext& c, const toml::node& where, const std::string& key, double nodes,
                  double elements, const RunLimits& lim);

/// After the deck is read: the stable step with mass scaling, the predicted
/// cycles and memory, the mass factor (into d.cost); problems above the limits,
/// warnings below.  A zero or non-finite stable step is left to the solver,
/// which reports it as a numerical fault naming the element.
void check_cost(const DeckContext& c, const toml::table& root, Deck& d);

/// One element through the thickness in a bending case (issue 53), a warning
/// in d.warnings at the [mesh] line: the mesh is one layer thick (every
/// element has two opposite faces on the mesh's surface, whatever the mesh
/// kind) and a tool has a curved surface (a cylinder or a torus: a pin, a die
/// or punch radius) that the sheet bends over.  Meshes above 2e6 elements are
/// not examined (the face count needs 48 bytes per element).
void mesh_warnings(const DeckContext& c, const toml::table& root, Deck& d);

/// The first contact pair on a tool with a cylinder surface (the pin); -1 if none.
int pin_pair(const fe::Model& m);
/// Whether the deck records the history signal s (core/run_output.hpp).
bool has_signal(const Deck& d, run_output::Signal s);
/// A deck that records outlet_force_N and back_tension_N over a pin but has
/// no step named "draw" gets no [drawbend] answer (F_X, F_Y, mu; run_result.hpp):
/// a warning at its [[step]] line naming its steps (a renamed draw step had
/// dropped the answer without a word).
void drawbend_step_warning(const DeckContext& c, const toml::table& root, Deck& d);

}  // namespace drawbend::io
