#pragma once
// What the materials' lane twins (material/lanes/) read and write of the
// element loop's state: plain pointers into the solver's structure-of-arrays
// records (core/lane_records.hpp) and the bound material's constants.  The
// element kernel's view (fe/element_view.hpp, fe::ElementView) is one of
// these with the element's geometry, nodes and forces added; a lane twin sees
// only this part.
#include "material/combined_plasticity.hpp"
#include "material/j2_isotropic.hpp"

namespace drawbend::material::lanes {

struct PointsView {
  double* sig = nullptr;         ///< 12 per element: the two integration points' stresses [MPa]
  double* state = nullptr;       ///< 2 * ns per element: the points' material states
  double* ie_inc = nullptr;      ///< 1 per element: internal energy increment [mJ]
  int ns = 0;                    ///< material state size per point
  bool spin = false;             ///< the material rotates its own state (Material::uses_spin)
  bool j2_lanes = false;         ///< J2 isotropic: its update runs on the lanes (j2_lanes.hpp)
  J2Isotropic::LaneParams j2{};  ///< its constants, when j2_lanes
  bool combined_lanes = false;   ///< CombinedPlasticity (von Mises or Hill'48): on the lanes too (combined_lanes.hpp)
  CombinedPlasticity::LaneParams combined{};  ///< its constants, when combined_lanes
  double dtp = 0;                ///< length of the interval the velocities act over [s]
};

}  // namespace drawbend::material::lanes
