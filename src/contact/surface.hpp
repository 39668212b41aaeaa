#pragma once
// Rigid analytic surfaces for tools (thesis: pins, flat dies, punch and die
// radii).  Units: mm.  Each surface answers one question for a point x: how
// far inside the tool is it (penetration > 0) and along which outward normal.
//
//   plane     points on the side of +normal are free; optional annulus bounds
//             r_min <= |x - origin|_perp(axis=normal) <= r_max (die face with a
//             hole, punch face);
//   cylinder  axis through origin along `axis`, radius R; material outside
//             (pin) or inside (die wall); optional axial bounds z_min..z_max;
//   torus     axis through origin along `axis`, tube of radius r around the
//             circle of radius R in the plane z = 0; material outside the tube;
//             optional bounds on the tube angle (die and punch corner radii).
#include <array>
#include <string>

#include "core/vec3.hpp"

namespace drawbend::contact {

using drawbend::Vec3;

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct Surface {
  enum class Kind { plane, cylinder, torus };
  Kind kind = Kind::plane;
  Vec3 origin{0, 0, 0};
  Vec3 axis{0, 0, 1};  ///< plane normal (towards the free side) or cylinder/torus axis (unit)
  double R = 0.0;      ///< cylinder radius or torus major radius
  double r = 0.0;      ///< torus minor (tube) radius
  bool inside = false; ///< cylinder: the free side is inside the cylinder
  double r_min = 0.0, r_max = 1e30;   ///< plane: radial bounds about `origin` in the plane
  double z_min = -1e30, z_max = 1e30; ///< cylinder: axial bounds
  double a_min = -4.0, a_max = 4.0;   ///< torus: tube angle bounds [rad], measured from the +radial direction towards +axis

  void validate(const std::string& where) const;
};

/// Penetration of point x into the surface displaced by `offset`; returns false
/// when x is outside the surface's bounds or farther than `search` from it.
/// On true, depth > 0 means penetration, n is the outward unit normal and
/// foot is the closest surface point.
bool penetration(const Surface& s, const Vec3& offset, const Vec3& x, double search, double& depth, Vec3& n, Vec3& foot);

}  // namespace drawbend::contact
