#pragma once
// The solver's nodal state as plain pointers into its structure-of-arrays
// storage: what the cycle's phases (fe/step_phases.hpp), the contact module
// and the element loop (fe/element_view.hpp) read and write.  No
// dependencies, so the element kernel's per-ISA builds include it cheaply.
// Units: mm, mm/s, N, t.

namespace drawbend::fe {

/// Nodal state, n of each, as plain pointers (Solver::node_view()).
struct NodeView {
  int n = 0;
  double *x = nullptr, *y = nullptr, *z = nullptr;     ///< current positions [mm]
  double *vx = nullptr, *vy = nullptr, *vz = nullptr;  ///< velocities [mm/s]
  const double* mass = nullptr;                        ///< lumped masses [t]
  const double* inv_mass = nullptr;                    ///< 1.0 / mass, once (the same bits as dividing each cycle)
  const double *X = nullptr, *Y = nullptr, *Z = nullptr;     ///< reference positions [mm]
};

/// A per-node vector field (external forces, reactions, old velocities).
struct NodeField {
  double *x = nullptr, *y = nullptr, *z = nullptr;
};

}  // namespace drawbend::fe
