#include "fe/disk.hpp"

#include <cmath>
#include <stdexcept>

namespace drawbend::fe {

Mesh quarter_disk(const QuarterDiskSpec& s) {
  if (!(s.radius > 0) || !(s.thickness > 0)) throw std::invalid_argument("quarter_disk: radius and thickness must be > 0");
  if (!(s.core_fraction > 0.2 && s.core_fraction < 0.7))
    throw std::invalid_argument("quarter_disk: core_fraction must lie in (0.2, 0.7)");
  if (s.core < 1 || s.ring < 1 || s.through < 1) throw std::invalid_argument("quarter_disk: element counts must be >= 1");
  const int n = s.core, m = s.ring;
  const double a = s.core_fraction * s.radius;
  // Plan-view nodes: core (i, j), then ring (k, r) for r = 1..m.
  std::vector<double> px, py;
  auto core_id = [&](int i, int j) { return i + (n + 1) * j; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      px.push_back(a * i / n);
      py.push_back(a * j / n);
    }
  auto boundary = [&](int k) { return k <= n ? core_id(n, k) : core_id(2 * n - k, n); };
  auto ring_id = [&](int k, int r) { return r == 0 ? boundary(k) : (n + 1) * (n + 1) + k * m + (r - 1); };
  // Polar part: rows mp..m are circles, row mp at radius rp (row mp of the 0-degree line).
  int mp = m;
  double rp = s.radius;
  if (s.polar_radius > 0) {
    mp = static_cast<int>(std::floor(m * (s.polar_radius - a) / (s.radius - a)));
    rp = a + (s.radius - a) * mp / m;
    if (!(rp > a * std::sqrt(2.0) && s.polar_radius < s.radius))
      throw std::invalid_argument("quarter_disk: polar_radius must lie between the core's corner and the rim by at "
                                  "least one row");
  }
  for (int k = 0; k <= 2 * n; ++k) {
    const double th = 0.5 * M_PI * k / (2.0 * n);
    const double c = k == 2 * n ? 0.0 : std::cos(th), sn = k == 0 ? 0.0 : std::sin(th);
    const double bx = px[boundary(k)], by = py[boundary(k)];
    const double cx = rp * c, cy = rp * sn;  // end of the straight part (the rim without a polar part)
    for (int r = 1; r <= m; ++r) {
      if (r <= mp) {
        px.push_back(bx + (cx - bx) * r / mp);
        py.push_back(by + (cy - by) * r / mp);
      } else {
        const double rr = rp + (s.radius - rp) * (r - mp) / (m - mp);
        px.push_back(rr * c);
        py.push_back(rr * sn);
      }
    }
  }
  // Plan-view quads, counter-clockwise seen from +z.
  std::vector<Quad> quads;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) quads.push_back({core_id(i, j), core_id(i + 1, j), core_id(i + 1, j + 1), core_id(i, j + 1)});
  for (int k = 0; k < 2 * n; ++k)
    for (int r = 0; r < m; ++r) quads.push_back({ring_id(k, r), ring_id(k, r + 1), ring_id(k + 1, r + 1), ring_id(k + 1, r)});
  // Extrude.
  const int np = static_cast<int>(px.size()), nl = s.through + 1;
  Mesh msh;
  for (int l = 0; l < nl; ++l)
    for (int q = 0; q < np; ++q) {
      msh.x.push_back(px[q]);
      msh.y.push_back(py[q]);
      msh.z.push_back(s.thickness * l / s.through);
    }
  for (int l = 0; l < s.through; ++l)
    for (const auto& q : quads) {
      std::array<int, 8> h;
      for (int c = 0; c < 4; ++c) {
        h[c] = q[c] + l * np;
        h[c + 4] = q[c] + (l + 1) * np;
      }
      msh.hex.push_back(h);
    }
  msh.element_block.assign(msh.hex.size(), 0);
  for (int i = 0; i < msh.num_nodes(); ++i) {
    const int q = i % np, l = i / np;
    msh.node_sets["all"].push_back(i);
    if (px[q] == 0.0) msh.node_sets["xmin"].push_back(i);
    if (py[q] == 0.0) msh.node_sets["ymin"].push_back(i);
    if (l == 0) msh.node_sets["zmin"].push_back(i);
    if (l == nl - 1) msh.node_sets["zmax"].push_back(i);
    if (q >= (n + 1) * (n + 1) && (q - (n + 1) * (n + 1)) % m == m - 1) msh.node_sets["rim"].push_back(i);
  }
  const int top = (nl - 1) * np;
  for (const auto& q : quads) {
    msh.face_sets["zmin"].push_back({q[0], q[3], q[2], q[1]});
    msh.face_sets["zmax"].push_back({q[0] + top, q[1] + top, q[2] + top, q[3] + top});
  }
  msh.validate();
  return msh;
}

}  // namespace drawbend::fe
