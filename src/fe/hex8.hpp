#pragma once
// The hexahedron's geometry: Flanagan-Belytschko uniform gradient, the
// corotational frame and half-lengths, hourglass base vectors.
//
// The element built on it (element_forces.cpp) is chosen for a 1.04 mm sheet
// with 4 elements through the thickness, bent plastically over pins:
//  - The uniform gradient B_a = (1/V) dV/dx_a (exact volume derivative of the
//    trilinear hexahedron) makes the element pass the patch test on distorted
//    meshes: the nodal forces of a constant stress balance exactly.
//  - Two integration points through the thickness (assumed strain from the two
//    hourglass modes linear in zeta): each half of an element yields on its
//    own, so an element crossed by the neutral axis of a plastically bent strip
//    is right; no transverse shear locking; the zeta-linear thickness strain is
//    assumed (plane stress elastic, isochoric plastic) to avoid volumetric
//    locking.  A one-point version of this element overestimated the fully
//    plastic moment of a 4-layer strip by 59 %; this one is within 1 %.
//  - The remaining hourglass modes (xi*eta, xi*eta*zeta) get the stiffness of
//    their physical strain fields on a rectangular element (Belytschko-Bindeman
//    spirit), in the corotational frame, with the elastic moduli: a stiffness
//    that followed yielding pumped energy into them as material streamed
//    through a bend.
//  - Objective stress rate: Jaumann, with strain increments on the
//    mid-interval geometry (exact for rigid rotation).
#include <algorithm>
#include <cmath>

namespace drawbend::fe {

/// Hourglass base vectors h_alpha (eta*zeta, zeta*xi, xi*eta, xi*eta*zeta) at the 8 nodes.
inline constexpr double kHg[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                                     {1, -1, -1, 1, -1, 1, 1, -1},
                                     {1, -1, 1, -1, 1, -1, 1, -1},
                                     {-1, 1, -1, 1, 1, -1, 1, -1}};
/// Natural coordinates of the nodes.
inline constexpr double kXiN[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
inline constexpr double kEtaN[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
inline constexpr double kZetaN[8] = {-1, -1, -1, -1, 1, 1, 1, 1};

/// dV/dx_a, dV/dy_a, dV/dz_a of the trilinear hexahedron (exact), following
/// Flanagan & Belytschko (1981), in the Walsh form of fe/hex8_geometry.hpp.
void volume_derivatives(const double x[8], const double y[8], const double z[8], double dvdx[8], double dvdy[8],
                        double dvdz[8]);

/// Element geometry at the current configuration; T = double for one element,
/// a vector of doubles for several side by side (core/lanes.hpp).
template <class T>
struct HexGeometryT {
  T B[3][8];   ///< uniform gradient dN_a/dx_i averaged over the element [1/mm]
  T volume;    ///< exact volume [mm^3]
  T R[3][3];   ///< corotational frame: columns are the local axes e_xi, e_eta, e_zeta
  T h[3];      ///< half-lengths along the local axes [mm]
};
using HexGeometry = HexGeometryT<double>;

/// Compute B, V, the corotational frame and half-lengths; returns false if the
/// volume is not positive (inverted element).
bool hex_geometry(const double x[8], const double y[8], const double z[8], HexGeometry& g);

/// Element size for the critical time step: 2 min(h), twice the smallest
/// half-length (equal to V / largest face area for a parallelepiped).  The
/// one definition used by the mass scaling and by every cycle's time step.
inline double hex_stable_length(double h0, double h1, double h2) { return 2.0 * std::min({h0, h1, h2}); }
inline double hex_stable_length(const HexGeometry& g) { return hex_stable_length(g.h[0], g.h[1], g.h[2]); }

}  // namespace drawbend::fe
