#pragma once
// The command-line options every draw-bend chapter shares, and the one
// definition of the `quick` mesh tier (the default of `make` and `make test`,
// of `drawbend drawbend-deck` and of `drawbend model-loop`): 1 mm elements
// along the strip in the bend zone, 2 across the half width, 4 through the
// thickness, mass scaling 1e4 at 100 mm/s, scaled by (100/v)^2 at speed v.
// The `full` tier is the same options with finer values (chapters/CMakeLists.txt,
// FULL_ARGS).
#include "core/options.hpp"
#include "sim/drawbend_case.hpp"

namespace drawbend::sim {

/// The quick tier's mass scaling at the reference speed of 100 mm/s.
inline constexpr double kQuickMassScaling = 1e4;

/// Mass scaling at speed v [mm/s] with the inertia (rho v^2) that `at_100`
/// gives at 100 mm/s: at_100 (100/v)^2.  The one copy of this rule.
double mass_scaling_for_speed(double at_100, double v);

/// The quick tier's mesh on `s`: element_length 1 mm, 2 across, 4 through,
/// mass scaling kQuickMassScaling (the value at 100 mm/s; callers that run at
/// another speed pass it through mass_scaling_for_speed).
void set_quick_mesh(DrawBendSpec& s);

/// The deck `drawbend drawbend-deck` starts from, and the one `make bench`
/// times: the quick mesh, its mass scaling at the spec's default speed
/// (mass_scaling_for_speed), the RD hardening curve of data/materials.
DrawBendSpec quick_deck_spec();

/// Set the quick-tier mesh on `base` and register --fe, --reuse-runs,
/// --fe-element-length, --fe-across, --fe-through, --fe-mass-scaling and
/// --fe-bend-inlet-slides (--fe, --reuse-runs and --fe-bend-inlet-slides take
/// true or false; --fe-bend-inlet-slides false reproduces the clamped bend
/// step of the decks before issue 51).
void add_fe_options(Options& o, DrawBendSpec& base, bool& run_fe, bool& reuse_runs);

}  // namespace drawbend::sim
