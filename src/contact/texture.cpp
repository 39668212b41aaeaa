#include "contact/texture.hpp"

#include "contact/surface.hpp"  // Vec3 helpers (dot)

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace drawbend::contact {

namespace {
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The face's mid-edge vectors a, b and orthonormal frame g1, g2 (g3 = normal);
// the 2 x 2 in-plane matrix [[a.g1, b.g1], [0, b.g2]].
struct Frame {
  Vec3 g1, g2;
  double A[2][2];
};

Frame frame(const std::array<int, 4>& f, const double* x, const double* y, const double* z) {
  Vec3 p[4];
  for (int q = 0; q < 4; ++q) p[q] = {x[f[q]], y[f[q]], z[f[q]]};
  Vec3 a, b;
  for (int j = 0; j < 3; ++j) {
    a[j] = 0.5 * (p[1][j] + p[2][j] - p[0][j] - p[3][j]);
    b[j] = 0.5 * (p[2][j] + p[3][j] - p[0][j] - p[1][j]);
  }
  Frame F;
  const double la = std::sqrt(dot(a, a));
  for (int j = 0; j < 3; ++j) F.g1[j] = a[j] / la;
  Vec3 g3 = cross(a, b);
  const double l3 = std::sqrt(dot(g3, g3));
  for (double& v : g3) v /= l3;
  F.g2 = cross(g3, F.g1);
  F.A[0][0] = la;
  F.A[0][1] = dot(b, F.g1);
  F.A[1][0] = 0.0;
  F.A[1][1] = dot(b, F.g2);
  return F;
}
}  // namespace

std::vector<TextureRef> texture_refs(const std::vector<std::array<int, 4>>& faces, const double* X, const double* Y,
                                     const double* Z, const std::vector<int>& nodes, const Vec3& rd,
                                     const std::string& name) {
  std::vector<TextureRef> refs(nodes.size());
  std::vector<bool> done(nodes.size(), false);
  for (const auto& f : faces) {
    const Frame F = frame(f, X, Y, Z);
    for (int q = 0; q < 4; ++q) {
      const auto it = std::lower_bound(nodes.begin(), nodes.end(), f[q]);
      if (it == nodes.end() || *it != f[q]) continue;
      const auto k = static_cast<std::size_t>(it - nodes.begin());
      if (done[k]) continue;
      done[k] = true;
      TextureRef& r = refs[k];
      r.face = f;
      const double det = F.A[0][0] * F.A[1][1] - F.A[0][1] * F.A[1][0];
      r.inv[0][0] = F.A[1][1] / det;
      r.inv[0][1] = -F.A[0][1] / det;
      r.inv[1][0] = -F.A[1][0] / det;
      r.inv[1][1] = F.A[0][0] / det;
      const double c1 = dot(rd, F.g1), c2 = dot(rd, F.g2), l = std::hypot(c1, c2);
      if (!(l > 1e-9)) throw std::invalid_argument("texture: the rolling direction is normal to a face of '" + name + "'");
      r.c1 = c1 / l;
      r.c2 = c2 / l;
    }
  }
  return refs;
}

Vec3 texture_axis(const TextureRef& r, const double* x, const double* y, const double* z) {
  const Frame F = frame(r.face, x, y, z);
  // In-plane deformation gradient F = A A0^-1 and its polar rotation.
  double G[2][2];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) G[i][j] = F.A[i][0] * r.inv[0][j] + F.A[i][1] * r.inv[1][j];
  const double cw = G[0][0] + G[1][1], sw = G[1][0] - G[0][1], l = std::sqrt(cw * cw + sw * sw);
  const double c = cw / l, s = sw / l;
  const double e1 = r.c1 * c - r.c2 * s, e2 = r.c1 * s + r.c2 * c;
  return {e1 * F.g1[0] + e2 * F.g2[0], e1 * F.g1[1] + e2 * F.g2[1], e1 * F.g1[2] + e2 * F.g2[2]};
}

}  // namespace drawbend::contact
