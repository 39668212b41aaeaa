#pragma once
// The one 3-vector of drawbend: positions, velocities, forces and directions
// [mm, mm/s, N, -].  fe::, contact:: and friction:: name it by a
// using-declaration, so that fe::Vec3 and contact::Vec3 are this type.
#include <array>

namespace drawbend {

using Vec3 = std::array<double, 3>;

}  // namespace drawbend
