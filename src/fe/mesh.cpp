#include "fe/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/hash.hpp"

namespace drawbend::fe {

namespace {
constexpr int kXi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
constexpr int kEta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
constexpr int kZeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
}  // namespace

const std::vector<int>& Mesh::node_set(const std::string& name) const {
  const auto it = node_sets.find(name);
  if (it == node_sets.end()) throw std::invalid_argument("mesh has no node set '" + name + "'");
  return it->second;
}

const std::vector<Quad>& Mesh::face_set(const std::string& name) const {
  const auto it = face_sets.find(name);
  if (it == face_sets.end()) throw std::invalid_argument("mesh has no face set '" + name + "'");
  return it->second;
}

double quad_area(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                 const Quad& f) {
  const double d1[3] = {x[f[2]] - x[f[0]], y[f[2]] - y[f[0]], z[f[2]] - z[f[0]]};
  const double d2[3] = {x[f[3]] - x[f[1]], y[f[3]] - y[f[1]], z[f[3]] - z[f[1]]};
  const double n[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

double hex_volume(const double x[8], const double y[8], const double z[8]) {
  const double g = 1.0 / std::sqrt(3.0);
  double v = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double xi = kXi[q] * g, eta = kEta[q] * g, zeta = kZeta[q] * g;
    double J[3][3] = {{0}};
    for (int a = 0; a < 8; ++a) {
      const double d[3] = {0.125 * kXi[a] * (1 + kEta[a] * eta) * (1 + kZeta[a] * zeta),
                           0.125 * kEta[a] * (1 + kXi[a] * xi) * (1 + kZeta[a] * zeta),
                           0.125 * kZeta[a] * (1 + kXi[a] * xi) * (1 + kEta[a] * eta)};
      for (int k = 0; k < 3; ++k) {
        J[0][k] += x[a] * d[k];
        J[1][k] += y[a] * d[k];
        J[2][k] += z[a] * d[k];
      }
    }
    v += J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  }
  return v;
}

void Mesh::validate() const {
  const int n = num_nodes();
  if (static_cast<int>(y.size()) != n || static_cast<int>(z.size()) != n)
    throw std::invalid_argument("mesh: coordinate arrays differ in length");
  for (int e = 0; e < num_elements(); ++e) {
    double ex[8], ey[8], ez[8];
    for (int a = 0; a < 8; ++a) {
      const int i = hex[e][a];
      if (i < 0 || i >= n)
        throw std::invalid_argument("mesh: element " + std::to_string(e) + " refers to node " + std::to_string(i) +
                                    " (nodes 0.." + std::to_string(n - 1) + ")");
      ex[a] = x[i];
      ey[a] = y[i];
      ez[a] = z[i];
    }
    if (!(hex_volume(ex, ey, ez) > 0.0))
      throw std::invalid_argument("mesh: element " + std::to_string(e) + " has a non-positive volume (inverted?)");
  }
}

std::uint64_t mesh_fingerprint(const Mesh& m) {
  std::uint64_t h = fnv1a64({});
  auto bytes = [&h](const void* p, std::size_t n) { h = fnv1a64({static_cast<const char*>(p), n}, h); };
  const std::int64_t counts[2] = {m.num_nodes(), m.num_elements()};
  bytes(counts, sizeof counts);
  bytes(m.hex.data(), m.hex.size() * sizeof(m.hex[0]));
  for (const auto* v : {&m.x, &m.y, &m.z}) bytes(v->data(), v->size() * sizeof(double));
  return h;
}

int nearest_element(const Mesh& m, double px, double py, double pz, double* dist, double* size) {
  int best = -1;
  double bd = INFINITY;
  for (int e = 0; e < m.num_elements(); ++e) {
    double c[3] = {0, 0, 0};
    for (int a : m.hex[e]) c[0] += m.x[a] / 8, c[1] += m.y[a] / 8, c[2] += m.z[a] / 8;
    const double d = (c[0] - px) * (c[0] - px) + (c[1] - py) * (c[1] - py) + (c[2] - pz) * (c[2] - pz);
    if (d < bd) bd = d, best = e;
  }
  if (dist) *dist = best < 0 ? INFINITY : std::sqrt(bd);
  if (size && best >= 0) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int a : m.hex[best]) {
      const double q[3] = {m.x[a], m.y[a], m.z[a]};
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
    }
    *size = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
  }
  return best;
}

NodeCorners NodeCorners::build(const Mesh& m) {
  NodeCorners nc;
  nc.start.assign(m.num_nodes() + 1, 0);
  for (const auto& h : m.hex)
    for (int a = 0; a < 8; ++a) ++nc.start[h[a] + 1];
  for (int i = 0; i < m.num_nodes(); ++i) nc.start[i + 1] += nc.start[i];
  nc.corner.assign(nc.start.back(), 0);
  std::vector<int> fill(nc.start.begin(), nc.start.end() - 1);
  for (int e = 0; e < m.num_elements(); ++e)
    for (int a = 0; a < 8; ++a) nc.corner[fill[m.hex[e][a]]++] = 8 * e + a;  // ascending (e, a) by construction
  return nc;
}

std::vector<double> uniform_lines(double a, double b, int n) {
  if (n < 1 || !(b > a)) throw std::invalid_argument("uniform_lines: need n >= 1 and b > a");
  std::vector<double> v(n + 1);
  for (int i = 0; i <= n; ++i) v[i] = a + (b - a) * i / n;
  return v;
}

std::vector<double> piecewise_lines(const std::vector<double>& bp, const std::vector<int>& counts) {
  if (bp.size() != counts.size() + 1 || counts.empty())
    throw std::invalid_argument("piecewise_lines: need one count per segment");
  std::vector<double> v{bp.front()};
  for (std::size_t s = 0; s < counts.size(); ++s) {
    const auto seg = uniform_lines(bp[s], bp[s + 1], counts[s]);
    v.insert(v.end(), seg.begin() + 1, seg.end());
  }
  return v;
}

BlockOrder block_order(int ex, int ey, int ez) {
  const int e[3] = {ex, ey, ez};
  // The slowest axis: the most elements; a tie keeps the later axis (z, then y).
  int slow = 2;
  for (int a : {1, 0})
    if (e[a] > e[slow]) slow = a;
  const int p = slow == 0 ? 1 : 0, q = slow == 2 ? 1 : 2;  // the other two, in x, y, z order
  const int fast = e[q] > e[p] ? q : p;                     // the longer of them (a tie: the earlier)
  if (e[fast] < kMinRow || slow == 2) return {{0, 1, 2}};
  return {{fast, fast == p ? q : p, slow}};
}

Mesh structured_block(const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<double>& zs) {
  for (const auto* l : {&xs, &ys, &zs}) {
    if (l->size() < 2) throw std::invalid_argument("structured_block: each direction needs >= 2 lines");
    for (std::size_t i = 1; i < l->size(); ++i)
      if (!((*l)[i] > (*l)[i - 1])) throw std::invalid_argument("structured_block: lines must increase strictly");
  }
  const int nx = static_cast<int>(xs.size()), ny = static_cast<int>(ys.size()), nz = static_cast<int>(zs.size());
  const BlockOrder order = block_order(nx - 1, ny - 1, nz - 1);
  const int lines[3] = {nx, ny, nz};
  int stride[3];
  stride[order.axis[0]] = 1;
  stride[order.axis[1]] = lines[order.axis[0]];
  stride[order.axis[2]] = lines[order.axis[0]] * lines[order.axis[1]];
  auto id = [&](int i, int j, int k) { return i * stride[0] + j * stride[1] + k * stride[2]; };
  Mesh m;
  m.x.resize(nx * ny * nz);
  m.y.resize(m.x.size());
  m.z.resize(m.x.size());
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        m.x[id(i, j, k)] = xs[i];
        m.y[id(i, j, k)] = ys[j];
        m.z[id(i, j, k)] = zs[k];
      }
  // Elements in the nodes' order: the fastest axis innermost.
  int c[3];
  int& a0 = c[order.axis[0]];
  int& a1 = c[order.axis[1]];
  int& a2 = c[order.axis[2]];
  for (a2 = 0; a2 + 1 < lines[order.axis[2]]; ++a2)
    for (a1 = 0; a1 + 1 < lines[order.axis[1]]; ++a1)
      for (a0 = 0; a0 + 1 < lines[order.axis[0]]; ++a0) {
        const int i = c[0], j = c[1], k = c[2];
        m.hex.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                         id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
      }
  m.element_block.assign(m.hex.size(), 0);
  auto& all = m.node_sets["all"];
  for (int n = 0; n < m.num_nodes(); ++n) all.push_back(n);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int n = id(i, j, k);
        if (i == 0) m.node_sets["xmin"].push_back(n);
        if (i == nx - 1) m.node_sets["xmax"].push_back(n);
        if (j == 0) m.node_sets["ymin"].push_back(n);
        if (j == ny - 1) m.node_sets["ymax"].push_back(n);
        if (k == 0) m.node_sets["zmin"].push_back(n);
        if (k == nz - 1) m.node_sets["zmax"].push_back(n);
      }
  for (auto& [name, set] : m.node_sets) std::sort(set.begin(), set.end());  // ascending, whatever the order
  // Boundary faces with outward normals.
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j) {
      m.face_sets["xmin"].push_back({id(0, j, k), id(0, j, k + 1), id(0, j + 1, k + 1), id(0, j + 1, k)});
      m.face_sets["xmax"].push_back(
          {id(nx - 1, j, k), id(nx - 1, j + 1, k), id(nx - 1, j + 1, k + 1), id(nx - 1, j, k + 1)});
    }
  for (int k = 0; k + 1 < nz; ++k)
    for (int i = 0; i + 1 < nx; ++i) {
      m.face_sets["ymin"].push_back({id(i, 0, k), id(i + 1, 0, k), id(i + 1, 0, k + 1), id(i, 0, k + 1)});
      m.face_sets["ymax"].push_back(
          {id(i, ny - 1, k), id(i, ny - 1, k + 1), id(i + 1, ny - 1, k + 1), id(i + 1, ny - 1, k)});
    }
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      m.face_sets["zmin"].push_back({id(i, j, 0), id(i, j + 1, 0), id(i + 1, j + 1, 0), id(i + 1, j, 0)});
      m.face_sets["zmax"].push_back(
          {id(i, j, nz - 1), id(i + 1, j, nz - 1), id(i + 1, j + 1, nz - 1), id(i, j + 1, nz - 1)});
    }
  return m;
}

}  // namespace drawbend::fe
