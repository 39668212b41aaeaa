#pragma once
// The one-point hexahedron: Flanagan-Belytschko uniform gradient plus
// physically derived, corotational hourglass stabilisation.
//
// Why this element.  The sheet is 1.04 mm thick with 4 elements through the
// thickness, bent over pins of radius 6.35-21 mm, plastically.
//  - One-point integration is cheap and free of volumetric and shear locking.
//  - The uniform gradient B_a = (1/V) dV/dx_a (exact volume derivative of the
//    trilinear hexahedron) makes the element pass the patch test on distorted
//    meshes: the nodal forces of a constant stress balance exactly.
//  - Hourglass stabilisation in the spirit of Belytschko-Bindeman (1993): in the
//    element's corotational frame, the mode h_alpha of displacement component i
//    gets the stiffness of its physical strain field on a rectangular element:
//      modes containing the coordinate of i (bending, warping):  only the normal
//        strain, K = E V / (3 h_i^2)  (warping xi*eta*zeta: E V / (9 h_i^2));
//      the mode not containing it (pure shear):  K = mu V (1/h_j^2 + 1/h_k^2) / 3,
//    with h the element half-lengths.  The parasitic shear of the bending modes
//    is left out, which is what makes a coarse layer bend correctly: a layer in
//    pure bending carries exactly its beam energy.  Without stabilisation 4
//    layers would miss 1/16 of the bending energy.
//  - In plastic bending each layer's internal strain gradient must see the
//    hardening tangent, not E: the stabilisation modulus is scaled by the
//    material's current tangent ratio (Material::tangent_ratio), otherwise a
//    plastically bent strip would be twice too stiff.
//  - Objective stress rate: Jaumann, sigma += dt (W sigma - sigma W).
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
/// Flanagan & Belytschko (1981) as written in LULESH.
void volume_derivatives(const double x[8], const double y[8], const double z[8], double dvdx[8], double dvdy[8],
                        double dvdz[8]);

/// Element geometry at the current configuration.
struct HexGeometry {
  double B[3][8];   ///< uniform gradient dN_a/dx_i averaged over the element [1/mm]
  double volume;    ///< exact volume [mm^3]
  double R[3][3];   ///< corotational frame: columns are the local axes e_xi, e_eta, e_zeta
  double h[3];      ///< half-lengths along the local axes [mm]
};

/// Compute B, V, the corotational frame and half-lengths; returns false if the
/// volume is not positive (inverted element).
bool hex_geometry(const double x[8], const double y[8], const double z[8], HexGeometry& g);

/// Smallest element dimension for the critical time step: V / (largest face area).
double hex_characteristic_length(const double x[8], const double y[8], const double z[8], double volume);

}  // namespace drawbend::fe
