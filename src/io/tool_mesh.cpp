// Tessellation of a tool's analytic surfaces; see tool_mesh.hpp.
#include "io/tool_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace drawbend::io {
namespace {

constexpr int kRound = 64, kTube = 16, kRings = 8;

Vec3 unit(const Vec3& a) {
  const double n = std::sqrt(contact::dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// A grid of (nu + 1) x (nv + 1) corners p(i / nu, j / nv) joined into nu x nv quads.
template <class P>
void grid(ToolMesh& t, int nu, int nv, int surface, P p) {
  const int base = static_cast<int>(t.x.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const Vec3 q = p(static_cast<double>(i) / nu, static_cast<double>(j) / nv);
      t.x.push_back(q[0]), t.y.push_back(q[1]), t.z.push_back(q[2]);
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = base + j * (nu + 1) + i;
      t.quads.insert(t.quads.end(), {a, a + 1, a + nu + 2, a + nu + 1});
      t.surface.push_back(surface);
    }
}

}  // namespace

ToolMesh tool_mesh(const fe::Tool& tool, const Vec3& offset, const Vec3& lo, const Vec3& hi) {
  ToolMesh t;
  const double diag = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  for (std::size_t k = 0; k < tool.surfaces.size(); ++k) {
    const contact::Surface& s = tool.surfaces[k];
    const Vec3 a = unit(s.axis);
    const Vec3 o{s.origin[0] + offset[0], s.origin[1] + offset[1], s.origin[2] + offset[2]};
    // Two unit directions perpendicular to the axis (as io::write_contact_maps).
    const Vec3 r1 = unit(std::abs(a[2]) < 0.9 ? Vec3{-a[1], a[0], 0} : Vec3{0, -a[2], a[1]});
    const Vec3 r2 = cross(a, r1);
    // The sheet's box corners relative to o: their range along the axis and radius about it.
    double amin = INFINITY, amax = -INFINITY, rmax = 0;
    for (int c = 0; c < 8; ++c) {
      const Vec3 q{(c & 1 ? hi : lo)[0] - o[0], (c & 2 ? hi : lo)[1] - o[1], (c & 4 ? hi : lo)[2] - o[2]};
      const double along = contact::dot(q, a);
      amin = std::min(amin, along), amax = std::max(amax, along);
      rmax = std::max(rmax, std::sqrt(std::max(0.0, contact::dot(q, q) - along * along)));
    }
    const double margin = std::max(2.0 * s.R, 0.1 * diag);
    auto at = [&](double ra, double rb, double ax) {
      return Vec3{o[0] + ra * r1[0] + rb * r2[0] + ax * a[0], o[1] + ra * r1[1] + rb * r2[1] + ax * a[1],
                  o[2] + ra * r1[2] + rb * r2[2] + ax * a[2]};
    };
    const int id = static_cast<int>(k);
    if (s.kind == contact::Surface::Kind::cylinder) {
      const double z0 = std::max(s.z_min, amin - margin), z1 = std::min(s.z_max, amax + margin);
      grid(t, kRound, 1, id, [&](double u, double v) {
        const double th = 2 * M_PI * u;
        return at(s.R * std::cos(th), s.R * std::sin(th), z0 + (z1 - z0) * v);
      });
    } else if (s.kind == contact::Surface::Kind::torus) {
      const double a0 = s.a_max - s.a_min >= 2 * M_PI ? -M_PI : s.a_min;
      const double a1 = s.a_max - s.a_min >= 2 * M_PI ? M_PI : s.a_max;
      grid(t, kRound, kTube, id, [&](double u, double v) {
        const double th = 2 * M_PI * u, ph = a0 + (a1 - a0) * v, rho = s.R + s.r * std::cos(ph);
        return at(rho * std::cos(th), rho * std::sin(th), s.r * std::sin(ph));
      });
    } else {  // plane: an annulus about the origin
      const double rin = s.r_min, rout = std::min(s.r_max, rmax + margin);
      grid(t, kRound, kRings, id, [&](double u, double v) {
        const double th = 2 * M_PI * u, r = rin + (rout - rin) * v;
        return at(r * std::cos(th), r * std::sin(th), 0.0);
      });
    }
  }
  return t;
}

}  // namespace drawbend::io
