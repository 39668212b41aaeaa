#pragma once
// What a forming engineer reads off a deformed sheet, from the mesh alone:
// its thickness through all element layers, and each element's strain.
// Used by the ParaView frames (io/run_case.cpp, write_fields).  mm.
//
// Sheet thickness.  The elements of a sheet stack in columns through the
// thickness.  A "chain" is a row of elements joined face to opposite face
// (hexahedron faces 0-1-2-3 / 4-5-6-7, 0-1-5-4 / 3-2-6-7 or 0-3-7-4 / 1-2-6-5);
// each element lies on three chains, one per pair of opposite faces.  Its
// thickness direction is that of the shortest of the three in the reference
// mesh (the sum of its elements' heights between the centroids of opposite
// faces): through a sheet that is the sheet's thickness, whatever the element
// sizes (1.04 mm over 4 layers against 10 mm or more across a strip).  The
// element edges along it join the nodes into paths from one surface of the
// sheet to the other; a node's sheet thickness is the current distance
// between the two end nodes of its path (the node pairs through the whole
// thickness).  This is the thickness a section would show where the path
// stays normal to the sheet; a through-thickness shear gamma lengthens it by
// 1 / cos(gamma) (0.4 % at 5 degrees).  A node on a ring or a branching path
// (not a sheet) reads 0.
//
// Strain.  The logarithmic (Hencky) strain of the deformation gradient at
// the element's centre, F = (dx/dxi)(dX/dxi)^-1: eps = ln V = 1/2 ln(F F^T),
// global axes, tensor shears, symmetric (XX, YY, ZZ, XY, YZ, XZ).  Its trace
// is ln(J); for a uniaxial stretch lambda it is diag(ln lambda, 0, 0).
#include <array>
#include <vector>

#include "fe/mesh.hpp"

namespace drawbend::io {

/// The through-thickness node paths of a mesh (from its reference geometry).
struct SheetColumns {
  std::vector<std::array<int, 2>> ends;  ///< per node: the two end nodes of its path (n, n: none)
};
SheetColumns sheet_columns(const fe::Mesh& m);

/// Each node's sheet thickness in the configuration (x, y, z) [mm].
std::vector<double> node_thickness(const SheetColumns& c, const double* x, const double* y, const double* z);

/// The logarithmic strain of element e at its centre, reference m, current (x, y, z).
void log_strain(const fe::Mesh& m, const double* x, const double* y, const double* z, int e, double eps[6]);

}  // namespace drawbend::io
