#pragma once
// The rigid tools as surfaces for ParaView: each analytic surface of a tool
// (contact/surface.hpp) cut into quadrilaterals at the tool's current
// position, one .vtp file per tool and frame (io/run_case.cpp).  mm.
//
//   cylinder  64 facets round the axis; along the axis its bounds z_min..z_max,
//             or where unbounded the extent of the sheet's box along the axis
//             and a margin (the larger of 2 R and a tenth of the box's diagonal);
//   torus     64 x 16 facets (round the axis x along the tube) over its tube
//             angle bounds (a full tube where they span 2 pi or more);
//   plane     an annulus about its origin, 64 x 8 facets, from r_min to r_max,
//             or where unbounded to the farthest corner of the sheet's box in
//             the plane plus the margin.
// Corners lie on the exact surface (a facet's chord is inside a convex face:
// 0.12 % of the radius at 64 facets).  Each quadrilateral carries the index of
// its surface in the tool (CellData "surface").
#include <string>
#include <vector>

#include "fe/model.hpp"

namespace drawbend::io {

struct ToolMesh {
  std::vector<double> x, y, z;  ///< corners [mm]
  std::vector<int> quads;       ///< 4 corner indices per facet, counterclockwise seen from the free side
  std::vector<double> surface;  ///< per facet: the index of its surface in the tool
};

/// The tool's surfaces displaced by `offset`, bounded where they are unbounded by the
/// box lo..hi (the sheet's current extent) [mm].
ToolMesh tool_mesh(const fe::Tool& tool, const Vec3& offset, const Vec3& lo, const Vec3& hi);

}  // namespace drawbend::io
