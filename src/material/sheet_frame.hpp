#pragma once
// The sheet frame: one rolling direction for the whole model, stated once in
// the deck ([sheet] rolling_direction), from which both the friction texture
// (contact/texture.hpp, per contact face) and the material axes (per
// integration point) are built.
//
// At a point of the sheet with unit normal n (an element's third natural axis
// zeta, normal to the sheet in the generated meshes, or a contact face's
// normal), the axes are
//   RD = (rd - (rd . n) n) / |rd - (rd . n) n|,  ND = n,  TD = ND x RD,
// so a rolling direction that is not quite in the sheet's plane (a curved
// blank, a tilted deck) is projected into it.  From then on the axes turn with
// the material (material/objectivity.hpp).
#include <array>

#include "material/material.hpp"

namespace drawbend::material {

/// The sheet axes at a point with normal `normal` (need not be unit) for the
/// global rolling direction `rd`.  Throws std::invalid_argument when rd is
/// (within 1e-6 rad) normal to the sheet there.
SheetAxes sheet_axes(const std::array<double, 3>& rd, const std::array<double, 3>& normal);

/// A Voigt tensor (tensor shears) between global and sheet axes; the rows of Q
/// are RD, TD, ND: local = Q A Q^T (to_local), global = Q^T A Q.  (The lanes of
/// material/lanes/hill48_lanes.hpp repeat its arithmetic in the same order.)
void sheet_transform(const double Q[3][3], const double v[6], double out[6], bool to_local);
/// c = a x b.
void cross3(const double a[3], const double b[3], double c[3]);
/// Re-orthonormalise stored RD and ND (state of an anisotropic model) after a first-order rotation.
void orthonormalise_axes(double* rd, double* nd);

}  // namespace drawbend::material
