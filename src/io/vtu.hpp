#pragma once
// VTK XML output of hexahedral meshes for ParaView: one .vtu file per output
// step and a .pvd collection that lists the steps with their times.
//
// Format written (VTK XML, version 1.0, ASCII):
//  - Points: Float64, 3 components, current coordinates (mm).
//  - Cells: connectivity (Int64, 8 per cell, VTK_HEXAHEDRON node ordering),
//    offsets (Int64, 8, 16, ...), types (UInt8, all 12 = VTK_HEXAHEDRON).
//  - PointData / CellData: one Float64 DataArray per field, with
//    NumberOfComponents = 1, 3 or 6, values interleaved per point/cell exactly
//    as passed in.  6-component arrays also carry ComponentName0..5 =
//    XX, YY, ZZ, XY, YZ, XZ, so ParaView labels the components.
//  - FieldData: one Float64 array "TimeValue" holding the step time (s), which
//    ParaView shows as the time of a single file.
// Every double is written in its shortest round-trip form (std::to_chars), so
// reading the file back gives bit-identical values.
//
// Symmetric tensors (components = 6) are written in the order the caller passes,
// which must be XX, YY, ZZ, XY, YZ, XZ.  That is the order ParaView expects for
// a 6-component symmetric tensor.  It is also the Voigt order
// xx, yy, zz, xy, yz, zx, because zx = xz.  Store tensor (not engineering)
// shear components: for strains, pass eps_xy, not gamma_xy = 2 eps_xy.
//
// All inputs are validated before anything is written, so a bad call leaves no
// file behind.  Validation errors throw std::invalid_argument.  Failing to write
// the file throws drawbend::InputError (from write_file_atomic).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace drawbend::io {

/// One named field on the points or on the cells of a mesh.
struct VtuField {
  std::string name;              ///< non-empty, unique within its PointData/CellData section
  int components = 1;            ///< 1 (scalar), 3 (vector) or 6 (symmetric tensor XX,YY,ZZ,XY,YZ,XZ)
  const double* data = nullptr;  ///< components * count values, interleaved per point/cell; finite
};

/// A hexahedral mesh as structure-of-arrays views (nothing is copied or owned).
struct VtuMesh {
  std::size_t num_points = 0;
  const double* x = nullptr;  ///< current coordinates (mm), num_points each
  const double* y = nullptr;
  const double* z = nullptr;
  std::size_t num_cells = 0;
  const int* hex = nullptr;  ///< 8 * num_cells node indices, VTK_HEXAHEDRON ordering
};

/// Write an unstructured-grid VTK XML file (.vtu, ASCII) with point and cell
/// fields, atomically (temporary file, then rename).  `time` is written as
/// FieldData "TimeValue".
///
/// Throws std::invalid_argument if: a pointer is null while its count is
/// nonzero; a node index is outside [0, num_points); a field has components
/// other than 1, 3 or 6, an empty or duplicate name, or null data with a
/// nonzero count; or a coordinate, field value or `time` is not finite.
/// (VTK's ASCII reader cannot parse "nan"/"inf".)
void write_vtu(const std::string& path, const VtuMesh& mesh, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields, double time = 0.0);

/// Write a ParaView collection (.pvd) that lists (time, file) pairs, in the
/// order given, so ParaView can play the series.  File names are written as
/// given (XML-escaped).  ParaView resolves relative names against the directory
/// of the .pvd file.  Throws std::invalid_argument on an empty file name or a
/// time that is not finite.
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& steps);

}  // namespace drawbend::io
