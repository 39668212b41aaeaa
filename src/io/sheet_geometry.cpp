// Sheet thickness through all layers and element strains; see sheet_geometry.hpp.
#include "io/sheet_geometry.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>


namespace drawbend::io {
namespace {

/// Local face f = 2 d + side: the pair of opposite faces d, side 0 or 1.
constexpr int kFace[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 2, 6, 5}};

std::array<int, 4> face_nodes(const fe::Mesh& m, int e, int f) {
  return {m.hex[e][kFace[f][0]], m.hex[e][kFace[f][1]], m.hex[e][kFace[f][2]], m.hex[e][kFace[f][3]]};
}

/// Distance between the centroids of element e's faces 2d and 2d+1 (reference).
double height(const fe::Mesh& m, const double* x, const double* y, const double* z, int e, int d) {
  double c[2][3] = {{0, 0, 0}, {0, 0, 0}};
  for (int s = 0; s < 2; ++s)
    for (int a : kFace[2 * d + s]) {
      const int n = m.hex[e][a];
      c[s][0] += x[n] / 4, c[s][1] += y[n] / 4, c[s][2] += z[n] / 4;
    }
  return std::hypot(c[1][0] - c[0][0], c[1][1] - c[0][1], c[1][2] - c[0][2]);
}

}  // namespace

SheetColumns sheet_columns(const fe::Mesh& m) {
  const int ne = m.num_elements();
  // Faces matched by their sorted node numbers: neighbour[6e + f] = 6e' + f' (-1: a free face).
  struct Rec {
    std::array<int, 4> key;
    int slot;
  };
  std::vector<Rec> recs;
  recs.reserve(6 * static_cast<std::size_t>(ne));
  for (int e = 0; e < ne; ++e)
    for (int f = 0; f < 6; ++f) {
      auto k = face_nodes(m, e, f);
      std::sort(k.begin(), k.end());
      recs.push_back({k, 6 * e + f});
    }
  std::sort(recs.begin(), recs.end(), [](const Rec& a, const Rec& b) { return a.key != b.key ? a.key < b.key : a.slot < b.slot; });
  std::vector<int> neighbour(6 * static_cast<std::size_t>(ne), -1);
  for (std::size_t i = 0; i < recs.size();) {
    std::size_t j = i;
    while (j < recs.size() && recs[j].key == recs[i].key) ++j;
    if (j - i == 2) neighbour[recs[i].slot] = recs[i + 1].slot, neighbour[recs[i + 1].slot] = recs[i].slot;
    i = j;
  }
  // Chains: each (element, direction) on exactly one, walked both ways from
  // its first element to the free faces (or round a ring); their reference lengths.
  std::vector<int> chain_of(3 * static_cast<std::size_t>(ne), -1);
  std::vector<double> chain_len;
  for (int e0 = 0; e0 < ne; ++e0)
    for (int d0 = 0; d0 < 3; ++d0) {
      if (chain_of[3 * e0 + d0] >= 0) continue;
      const int id = static_cast<int>(chain_len.size());
      double len = height(m, m.x.data(), m.y.data(), m.z.data(), e0, d0);
      chain_of[3 * e0 + d0] = id;
      for (int side = 0; side < 2; ++side) {
        int e = e0, f = 2 * d0 + side;
        for (;;) {
          const int nb = neighbour[6 * e + f];
          if (nb < 0) break;
          const int e2 = nb / 6, f2 = nb % 6, d2 = f2 / 2;
          if (chain_of[3 * e2 + d2] == id) break;  // round a ring
          chain_of[3 * e2 + d2] = id;
          len += height(m, m.x.data(), m.y.data(), m.z.data(), e2, d2);
          e = e2;
          f = f2 ^ 1;  // the opposite face
        }
      }
      chain_len.push_back(len);
    }
  // Each element's column direction: that of its shortest chain (the lowest direction on a tie).
  std::vector<int> dir(ne, 0);
  for (int e = 0; e < ne; ++e)
    for (int d = 1; d < 3; ++d)
      if (chain_len[chain_of[3 * e + d]] < chain_len[chain_of[3 * e + dir[e]]]) dir[e] = d;
  // Through-thickness edges (face 2d corner i to face 2d+1 corner i), then
  // each node's path along them: its two end nodes.
  const int nn = m.num_nodes();
  std::vector<std::vector<int>> up(nn);
  for (int e = 0; e < ne; ++e)
    for (int i = 0; i < 4; ++i) {
      const int a = m.hex[e][kFace[2 * dir[e]][i]], b = m.hex[e][kFace[2 * dir[e] + 1][i]];
      if (std::find(up[a].begin(), up[a].end(), b) == up[a].end()) up[a].push_back(b), up[b].push_back(a);
    }
  SheetColumns c;
  c.ends.assign(nn, {-1, -1});
  for (int n0 = 0; n0 < nn; ++n0) {
    if (c.ends[n0][0] >= 0 || up[n0].size() > 1) continue;  // start from an end (or a lone node)
    std::vector<int> path{n0};
    int prev = -1, cur = n0;
    bool ok = true;
    for (;;) {
      int next = -1;
      for (int q : up[cur])
        if (q != prev) next = q;
      if (up[cur].size() > 2) ok = false;  // a branching node: not a column of a sheet
      if (next < 0 || !ok || path.size() > static_cast<std::size_t>(nn)) break;
      path.push_back(next);
      prev = cur, cur = next;
    }
    for (int q : path) c.ends[q] = ok ? std::array<int, 2>{n0, cur} : std::array<int, 2>{q, q};
  }
  for (int n = 0; n < nn; ++n)
    if (c.ends[n][0] < 0) c.ends[n] = {n, n};  // on a ring: no surface to measure to
  return c;
}

std::vector<double> node_thickness(const SheetColumns& c, const double* x, const double* y, const double* z) {
  std::vector<double> h(c.ends.size());
  for (std::size_t n = 0; n < c.ends.size(); ++n) {
    const int a = c.ends[n][0], b = c.ends[n][1];
    h[n] = std::hypot(x[b] - x[a], y[b] - y[a], z[b] - z[a]);
  }
  return h;
}

void log_strain(const fe::Mesh& m, const double* x, const double* y, const double* z, int e, double eps[6]) {
  // Natural coordinates of the VTK hexahedron's corners.
  static const int s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero(), J0 = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 8; ++a) {
    const int n = m.hex[e][a];
    const double cur[3] = {x[n], y[n], z[n]}, ref[3] = {m.x[n], m.y[n], m.z[n]};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) J(i, j) += cur[i] * s[a][j] / 8.0, J0(i, j) += ref[i] * s[a][j] / 8.0;
  }
  const Eigen::Matrix3d F = J * J0.inverse();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(F * F.transpose());
  Eigen::Vector3d l = es.eigenvalues();
  for (int i = 0; i < 3; ++i) l(i) = l(i) > 0 ? 0.5 * std::log(l(i)) : 0.0;
  const Eigen::Matrix3d E = es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose();
  eps[0] = E(0, 0), eps[1] = E(1, 1), eps[2] = E(2, 2), eps[3] = E(0, 1), eps[4] = E(1, 2), eps[5] = E(0, 2);
}

}  // namespace drawbend::io
