#pragma once
// A quarter disk of solid hexahedra: the cup-drawing blank on a symmetry model
// (thesis Sec. 6.6.2, Fig. 6.18).  Units: mm.
//
// Plan view: an O-grid ("butterfly") mesh, so no element degenerates at the
// centre.  A square core [0, a]^2 (a = core_fraction x radius) of n x n
// elements, and a ring of 2n x m elements joining the core's outer edges to
// the quarter circle: ring line k (k = 0..2n) runs straight from the k-th core
// boundary point (from (a, 0) up to (a, a), then to (0, a)) to the arc point at
// angle k/(2n) x 90 deg, in m equal steps.  The plan is extruded through the
// thickness, z = 0 (bottom) to z = thickness, in `through` layers.
//
// Polar outer ring (polar_radius > 0): the ring's rows are then circles from
// that radius out (rounded down to a row of the 0-degree line) and the ring
// lines radial at equal angles; inside it each ring line runs straight from
// its core point to its point on the circle.  A tool edge of revolution (a
// punch nose, a die shoulder) then crosses the elements square, not at the
// angle of the O-grid's square-ish rows, and the mesh is polar-symmetric
// wherever the sheet is drawn.
//
// Sets: node sets all, xmin (the x = 0 symmetry plane), ymin (y = 0), zmin
// (bottom), zmax (top), rim (r = radius); face sets zmin and zmax (outward
// normals -z, +z).  The rolling direction of the study is x.
#include "fe/mesh.hpp"

namespace drawbend::fe {

struct QuarterDiskSpec {
  double radius = 55.625;      ///< blank radius [mm] (111.25 mm disk)
  double thickness = 1.05;     ///< [mm]
  double core_fraction = 0.5;  ///< core square side / radius
  int core = 8;                ///< n: elements along each core side (the arc has 2n)
  int ring = 12;               ///< m: elements from the core to the rim
  int through = 2;             ///< elements through the thickness
  double polar_radius = 0;     ///< rows are circles from this radius out [mm]; 0: straight ring lines
};

Mesh quarter_disk(const QuarterDiskSpec& s);

}  // namespace drawbend::fe
