#pragma once
// Hexahedral meshes in structure-of-arrays form (LULESH style).  Units: mm.
//
// Node numbering inside an element follows VTK_HEXAHEDRON: nodes 0-3 the
// bottom face counter-clockwise seen from +zeta, nodes 4-7 the top face.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace drawbend::fe {

using Quad = std::array<int, 4>;  ///< a boundary face, outward normal by the right-hand rule

struct Mesh {
  std::vector<double> x, y, z;           ///< reference coordinates [mm]
  std::vector<std::array<int, 8>> hex;   ///< element connectivity
  std::map<std::string, std::vector<int>> node_sets;
  std::map<std::string, std::vector<Quad>> face_sets;
  std::vector<int> element_block;        ///< block id per element (0 for generated meshes)

  int num_nodes() const { return static_cast<int>(x.size()); }
  int num_elements() const { return static_cast<int>(hex.size()); }
  const std::vector<int>& node_set(const std::string& name) const;
  const std::vector<Quad>& face_set(const std::string& name) const;
  void validate() const;  ///< indices in range, positive volumes; throws std::invalid_argument
};

/// A 64-bit fingerprint (FNV-1a, core/hash.hpp) of the mesh's numbering and geometry: the
/// node and element counts, every element's 8 node numbers and every node's
/// reference coordinates, byte for byte.  Two meshes with the same counts
/// but another numbering (fe::block_order) or another coordinate differ in
/// it (but for the 2^-64 chance of a collision).  A checkpoint stores it,
/// so that a state is never restored onto another numbering (fe/checkpoint.cpp).
std::uint64_t mesh_fingerprint(const Mesh& m);

/// The element whose reference centroid is nearest (px, py, pz) (lowest index on
/// ties; -1 for a mesh without elements), and in `dist` that centroid's distance
/// and in `size` the element's size (the diagonal of its nodes' bounding box) [mm].
int nearest_element(const Mesh& m, double px, double py, double pz, double* dist = nullptr, double* size = nullptr);

/// Node-to-element-corner adjacency in CSR form, sorted by (element, corner),
/// so that nodal sums run in a fixed order whatever the thread count.
struct NodeCorners {
  std::vector<int> start;   ///< size num_nodes + 1
  std::vector<int> corner;  ///< 8 * element + corner
  static NodeCorners build(const Mesh& m);
};

/// The numbering of a structured block: axis[0] runs fastest, axis[2]
/// slowest (0 = x, 1 = y, 2 = z).
struct BlockOrder {
  int axis[3];
};

/// Elements that a row on the fastest axis must hold before block_order puts
/// that axis first: the AVX-512 kernel's lane count.  A row of 8 or 16 (any
/// multiple of 8: the blocks start at multiples of 8) puts each block of
/// eight elements on one row of consecutive nodes, which loads as vectors
/// (fe/element_kernel.hpp: nodes_run_on); another row of at least 8 has a
/// block across the end of a row now and then, which takes the per-lane
/// gather (a row of 12: one block in three).  Fixed, not the running
/// kernel's width: the numbering, and so every result's bits, must not
/// depend on the instruction set.
inline constexpr int kMinRow = 8;

/// The numbering of a block of ex x ey x ez elements.  As built (x fastest,
/// then y, then z), unless the axis with the most elements is not z and the
/// longer of the other two has at least kMinRow elements: then that one runs
/// fastest, the remaining one next, and the longest slowest.  Why: with the
/// longest axis slowest, the contiguous halves that the threads take of the
/// elements and of the nodes meet on the block's smallest cross-section (bar
/// of 100 x 16 x 5 elements: 102 nodes instead of about 1,800), so less data
/// passes between the cores every cycle (docs/performance-log.md, the slow
/// stretches); it is also the classic numbering across the short side for
/// a narrow bandwidth.  Ties keep the tied axes in their as-built order: of
/// two axes tied for the most elements the later runs slowest (x = y > z
/// still reorders, to x, z, y), of two tied for the fastest the earlier
/// runs fastest.
BlockOrder block_order(int ex, int ey, int ez);

/// A structured block on the coordinate lines xs x ys x zs (each strictly
/// increasing), numbered by block_order (nodes and elements alike).  Node
/// sets (ascending): xmin, xmax, ymin, ymax, zmin, zmax, all.  Face sets with
/// outward normals: xmin, xmax, ymin, ymax, zmin, zmax.
Mesh structured_block(const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<double>& zs);

/// Coordinate lines: n equal intervals from a to b.
std::vector<double> uniform_lines(double a, double b, int n);
/// Coordinate lines with refined zones: the segment [a, b] is split at the
/// given breakpoints, each piece with its own count of equal intervals.
std::vector<double> piecewise_lines(const std::vector<double>& breakpoints, const std::vector<int>& counts);

/// Coordinates of one element's 8 nodes from structure-of-arrays positions.
inline void gather(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                   const std::array<int, 8>& h, double ex[8], double ey[8], double ez[8]) {
  for (int a = 0; a < 8; ++a) {
    ex[a] = x[h[a]];
    ey[a] = y[h[a]];
    ez[a] = z[h[a]];
  }
}

/// Area of a (possibly warped) quadrilateral face: half the cross product of its diagonals.
double quad_area(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                 const Quad& f);

/// Exact volume of a trilinear hexahedron (2 x 2 x 2 Gauss is exact).
double hex_volume(const double x[8], const double y[8], const double z[8]);

}  // namespace drawbend::fe
