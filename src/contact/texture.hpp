#pragma once
// Texture axes that rotate with the sheet ("corotational", thesis Sec. 6.4:
// "this algorithm needs improvements for the general sheet forming cases by
// defining corotational local axes").
//
// Each contact node is tied to one face of its contact face set (the first
// face of the set that contains it, a fixed choice).  At the start the rolling
// direction RD (a global vector) is projected into that face and written in
// the face's own orthonormal frame (g1 along the face's mid-edge vector a,
// g3 = a x b / |a x b|, g2 = g3 x g1, with a and b the two mid-edge vectors
// joining opposite edge midpoints): RD0 = c1 g1 + c2 g2.  Now, the face's
// in-plane deformation gradient in the two frames is F = A A0^-1, with
// A = [[a.g1, b.g1], [a.g2, b.g2]] (upper triangular: a.g2 = 0), and its polar
// rotation angle is omega = atan2(F21 - F12, F11 + F22).  The current RD is the
// initial components rotated by omega in the current frame:
//   e1 = (c1 cos w - c2 sin w) g1 + (c1 sin w + c2 cos w) g2.
// So e1 follows the material's rigid rotation exactly (a rigidly rotated face
// has F = I and a rotated frame), the face's bending over a tool (g3 turns
// with the face) and, under in-plane shear, the polar rotation rather than the
// first edge.  The contact code projects e1 onto the tool's tangent plane.
// Units: mm.
#include <array>
#include <string>
#include <vector>

#include "core/vec3.hpp"


namespace drawbend::contact {

using drawbend::Vec3;

struct TextureRef {
  std::array<int, 4> face{};  ///< the face the node's texture follows
  double inv[2][2]{};         ///< A0^-1 (initial in-plane frame of the face)
  double c1 = 1, c2 = 0;      ///< initial RD in the face's initial frame (unit)
};

/// One reference per node of `nodes` (sorted node ids of the face set
/// `faces`, named `name` in messages), from the reference coordinates X, Y, Z
/// and the rolling direction `rd`.  Throws std::invalid_argument when `rd` is
/// normal to a face.
std::vector<TextureRef> texture_refs(const std::vector<std::array<int, 4>>& faces, const double* X, const double* Y,
                                     const double* Z, const std::vector<int>& nodes, const Vec3& rd,
                                     const std::string& name);

/// Current unit RD of one node from current nodal coordinates.
Vec3 texture_axis(const TextureRef& r, const double* x, const double* y, const double* z);

}  // namespace drawbend::contact
