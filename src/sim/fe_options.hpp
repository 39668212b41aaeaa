#pragma once
// The command-line options every draw-bend chapter shares, and the one
// definition of the `quick` mesh tier (the default of `make` and `make test`):
// 1 mm elements along the strip in the bend zone, 2 across the half width, 4
// through the thickness, mass scaling 1e4 at 100 mm/s.  The `full` tier is
// the same options with finer values (chapters/CMakeLists.txt, FULL_ARGS).
#include "core/options.hpp"
#include "sim/drawbend_case.hpp"

namespace drawbend::sim {

/// Set the quick-tier mesh on `base` and register --fe, --reuse-runs,
/// --fe-element-length, --fe-across, --fe-through and --fe-mass-scaling
/// (--fe and --reuse-runs take true or false).
void add_fe_options(Options& o, DrawBendSpec& base, bool& run_fe, bool& reuse_runs);

}  // namespace drawbend::sim
