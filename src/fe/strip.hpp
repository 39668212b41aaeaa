#pragma once
// A strip wrapped round a pin: the draw-bend geometry.  Units: mm.
//
// The pin axis is the y axis through the origin, radius R.  The strip's inner
// (contact) surface starts on the inlet leg, a straight run along +x at
// z = R that ends at the top of the pin (x = 0); wraps round the pin by
// `wrap` radians; and leaves along the tangent as the outlet leg.  The strip is
// generated as a structured block in (s, y, zeta) -- s along the mid-surface,
// y across the width (0..width), zeta through the thickness (0 = contact side)
// -- and mapped onto that shape, so its node and face sets keep their block
// names: xmin = inlet end, xmax = outlet end, ymin/ymax = the width edges,
// zmin = contact face (normals point into the pin), zmax = free face.
#include <vector>

#include "fe/mesh.hpp"

namespace drawbend::fe {

struct StripSpec {
  double pin_radius = 6.35;    ///< R [mm]
  double wrap = 1.5707963267948966;  ///< wrap angle [rad]
  double thickness = 1.04;     ///< [mm]
  double width = 12.7;         ///< modelled width [mm] (half the strip on a symmetry model)
  double inlet_length = 25.0;  ///< straight inlet leg [mm]
  double outlet_length = 10.0; ///< straight outlet leg [mm]
  double element_length = 0.5; ///< along the strip [mm]
  int across = 4;              ///< elements across the modelled width
  int through = 4;             ///< elements through the thickness
};

/// The wrapped strip mesh (stress-free in the wrapped shape).
Mesh wrapped_strip(const StripSpec& s);

/// Mid-surface length of the wrap, (R + t/2) * wrap [mm].
double wrap_length(const StripSpec& s);

}  // namespace drawbend::fe
