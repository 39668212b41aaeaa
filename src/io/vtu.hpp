#pragma once
// VTK XML output of hexahedral meshes for ParaView: one .vtu file per output
// step and a .pvd collection that lists the steps with their times.
//
// Format written (VTK XML, version 1.0), in one of three encodings (VtkFormat):
//  ascii   every value as text, in its shortest round-trip form;
//  raw     the arrays in an <AppendedData encoding="raw"> block, each a UInt64
//          byte count and the values in the machine's byte order (written as
//          byte_order); what ParaView calls "appended, raw";
//  zlib    the same, each array cut in blocks of 64 KiB and compressed with
//          zlib (compressor="vtkZLibDataCompressor", VTK's own header of block
//          count, block size, last block size and the compressed sizes).
//          Without zlib at build time (DRAWBEND_HAVE_ZLIB unset) zlib writes raw.
//  - Points: Float64, 3 components, current coordinates (mm).
//  - Cells: connectivity (Int64, nodes_per_cell per cell: 8 for
//    VTK_HEXAHEDRON, 4 for VTK_QUAD), offsets (Int64), types (UInt8).
//  - PointData / CellData: one Float64 DataArray per field, with
//    NumberOfComponents = 1, 3 or 6, values interleaved per point/cell exactly
//    as passed in.  6-component arrays also carry ComponentName0..5 =
//    XX, YY, ZZ, XY, YZ, XZ, so ParaView labels the components.
//  - FieldData: one Float64 array "TimeValue" holding the step time (s), which
//    ParaView shows as the time of a single file.
// Every double reads back bit-identical in every encoding (ascii: std::to_chars's
// shortest round-trip form), and the bytes written depend only on the values.
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

/// A mesh of one cell type as structure-of-arrays views (nothing is copied or owned).
struct VtuMesh {
  std::size_t num_points = 0;
  const double* x = nullptr;  ///< current coordinates (mm), num_points each
  const double* y = nullptr;
  const double* z = nullptr;
  std::size_t num_cells = 0;
  const int* hex = nullptr;  ///< nodes_per_cell * num_cells node indices, in VTK's ordering of cell_type
  int nodes_per_cell = 8;    ///< 8 (hexahedra) or 4 (quadrilaterals)
  int cell_type = 12;        ///< VTK_HEXAHEDRON = 12, VTK_QUAD = 9
};

enum class VtkFormat { ascii, raw, zlib };

/// Write an unstructured-grid VTK XML file (.vtu) with point and cell
/// fields, atomically (temporary file, then rename).  `time` is written as
/// FieldData "TimeValue".
///
/// Throws std::invalid_argument if: a pointer is null while its count is
/// nonzero; a node index is outside [0, num_points); a field has components
/// other than 1, 3 or 6, an empty or duplicate name, or null data with a
/// nonzero count; or a coordinate, field value or `time` is not finite.
/// (VTK's ASCII reader cannot parse "nan"/"inf".)
void write_vtu(const std::string& path, const VtuMesh& mesh, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields, double time = 0.0, VtkFormat format = VtkFormat::ascii);

/// One DataArray of a .vtu this module wrote (any encoding), as doubles:
/// "Points", "connectivity", "offsets", "types", "TimeValue" or a field's name.
/// Throws drawbend::InputError naming the file if the array is missing or its
/// data cannot be decoded.  (For our own files only: one Piece, UInt64 headers.)
std::vector<double> read_vtu_array(const std::string& path, const std::string& text, const std::string& name);

/// A multiblock collection (.vtm) of the files given as (block name, file),
/// in that order; ParaView opens it as one dataset with a block per file.
/// Names are resolved against the .vtm's directory.  Throws std::invalid_argument
/// on an empty name or file.
void write_vtm(const std::string& path, const std::vector<std::pair<std::string, std::string>>& blocks);

/// The same as a PolyData file (.vtp) of quadrilaterals (mesh.nodes_per_cell 4,
/// cell_type 9), for surfaces such as the rigid tools (io/tool_mesh.hpp).
void write_vtp(const std::string& path, const VtuMesh& mesh, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields, double time = 0.0, VtkFormat format = VtkFormat::ascii);

/// One file of a collection: its time [s], its part (0, 1, ...: ParaView shows
/// the parts of a time as the blocks of one dataset) and the part's name.
struct PvdEntry {
  double time = 0;
  int part = 0;
  std::string name;  ///< "" : none written
  std::string file;
};
/// The collection of `steps`, part 0 each, no names (the form before parts).
void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& steps);

/// Write a ParaView collection (.pvd) that lists (time, file) pairs, in the
/// order given, so ParaView can play the series.  File names are written as
/// given (XML-escaped).  ParaView resolves relative names against the directory
/// of the .pvd file.  Throws std::invalid_argument on an empty file name or a
/// time that is not finite.
void write_pvd(const std::string& path, const std::vector<PvdEntry>& steps);

}  // namespace drawbend::io
