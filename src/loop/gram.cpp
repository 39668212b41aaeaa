// J^T J with the zero products skipped, bit for bit as Eigen's (gram.hpp).
#include "loop/gram.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace drawbend::loop {

namespace {

using GramTraits = Eigen::internal::gebp_traits<double, double>;

// The kernel whose order of sums is replicated (see gram.hpp).
#if EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4 && defined(EIGEN_VECTORIZE_SSE2) && \
    !defined(EIGEN_VECTORIZE_AVX) && !defined(EIGEN_VECTORIZE_FMA) && !defined(EIGEN_USE_BLAS)
constexpr bool kKnownKernel = GramTraits::mr == 4 && GramTraits::nr == 4 && GramTraits::LhsProgress == 2;
#else
constexpr bool kKnownKernel = false;
#endif

}  // namespace

bool gram_sparse(const Eigen::MatrixXd& J, Eigen::MatrixXd& A, bool force, const std::vector<std::vector<int>>* nz) {
  const Eigen::Index n = J.rows(), p = J.cols();
  // Eigen's GEMM path only (p = 1 is a matrix-vector product, tiny sizes a
  // coefficient-wise one).
  if (!kKnownKernel || p < 2 || n < 32) return false;
  const double* d = J.data();
  std::vector<Eigen::Index> start(static_cast<size_t>(n) + 1, 0);
  if (nz) {  // the rows of each column that may be nonzero: the others are not read
    if (static_cast<Eigen::Index>(nz->size()) != p) return false;
    for (const auto& rows : *nz)
      for (int k : rows) ++start[k + 1];
  } else {
    if (!J.allFinite()) return false;  // NaN or infinity: 0 x it is not 0
    for (Eigen::Index j = 0; j < p; ++j) {
      const double* c = d + j * n;
      for (Eigen::Index k = 0; k < n; ++k) start[k + 1] += c[k] != 0;
    }
  }
  double pairs = 0;
  for (Eigen::Index k = 0; k < n; ++k) pairs += static_cast<double>(start[k + 1]) * static_cast<double>(start[k + 1]);
  if (!force && 8 * pairs > static_cast<double>(n) * static_cast<double>(p) * static_cast<double>(p)) return false;
  for (Eigen::Index k = 0; k < n; ++k) start[k + 1] += start[k];
  // Per row, its nonzero columns (ascending) and values.
  std::vector<int> col(static_cast<size_t>(start[n]));
  std::vector<double> val(col.size());
  {
    std::vector<Eigen::Index> pos(start.begin(), start.end() - 1);
    for (Eigen::Index j = 0; j < p; ++j) {
      const double* c = d + j * n;
      if (nz)
        for (int k : (*nz)[j]) col[pos[k]] = static_cast<int>(j), val[pos[k]++] = c[k];
      else
        for (Eigen::Index k = 0; k < n; ++k)
          if (c[k] != 0) col[pos[k]] = static_cast<int>(j), val[pos[k]++] = c[k];
    }
  }
  if (nz)
    for (double v : val)
      if (!(std::abs(v) <= std::numeric_limits<double>::max())) return false;
  // Eigen's blocking (general_matrix_matrix_product::run).
  Eigen::Index kc = n, mc = p, nc = p;
  Eigen::internal::computeProductBlockingSizes<double, double, 1, Eigen::Index>(kc, mc, nc, Eigen::Index(1));
  mc = std::min(p, mc), nc = std::min(p, nc);
  if (kc < 1 || mc < 1 || nc < 1) return false;
  // Element e = i + j p: summed with even and odd rows apart (gebp's one-packet
  // row panel in a 4-column panel), odd[e] = p^2 (the D half of CD), else 0.
  const Eigen::Index pp = p * p;
  std::vector<Eigen::Index> odd(static_cast<size_t>(pp), 0);
  for (Eigen::Index j = 0; j < p; ++j) {
    const Eigen::Index j2 = j / nc * nc, anc = std::min(j2 + nc, p) - j2;
    if (j - j2 >= anc / 4 * 4) continue;  // a remaining column: one at a time
    for (Eigen::Index i = 0; i < p; ++i) {
      const Eigen::Index i2 = i / mc * mc, amc = std::min(i2 + mc, p) - i2, il = i - i2;
      const Eigen::Index pm2 = amc / 4 * 4, pm1 = pm2 + (amc - pm2) / 2 * 2;
      if (il >= pm2 && il < pm1) odd[static_cast<size_t>(i + j * p)] = pp;
    }
  }
  std::vector<double> R(static_cast<size_t>(pp), 0.0), CD(static_cast<size_t>(2 * pp), 0.0);
  auto rows = [&](Eigen::Index k0, Eigen::Index k1, bool alternate) {  // alternate: odd rows (from k0) to D where odd[e]
    for (Eigen::Index k = k0; k < k1; ++k) {
      const int* cb = col.data() + start[k];
      const double* vb = val.data() + start[k];
      const Eigen::Index m = start[k + 1] - start[k];
      if (!alternate || ((k - k0) & 1) == 0) {
        for (Eigen::Index b = 0; b < m; ++b) {
          double* t = CD.data() + static_cast<Eigen::Index>(cb[b]) * p;
          const double vj = vb[b];
          for (Eigen::Index a = 0; a < m; ++a) t[cb[a]] += vb[a] * vj;
        }
      } else {
        for (Eigen::Index b = 0; b < m; ++b) {
          const Eigen::Index o = static_cast<Eigen::Index>(cb[b]) * p;
          const double vj = vb[b];
          for (Eigen::Index a = 0; a < m; ++a) {
            const Eigen::Index e = o + cb[a];
            CD[e + odd[e]] += vb[a] * vj;
          }
        }
      }
    }
  };
  for (Eigen::Index k0 = 0; k0 < n; k0 += kc) {
    const Eigen::Index k1 = std::min(n, k0 + kc), peeled = k0 + ((k1 - k0) & ~Eigen::Index(7));
    rows(k0, peeled, true);  // the peeled rows: even and odd apart where odd[e]
    for (Eigen::Index e = 0; e < pp; ++e)
      if (odd[e]) CD[e] = CD[e] + CD[e + pp], CD[e + pp] = 0.0;
    rows(peeled, k1, false);  // the rest in order
    for (Eigen::Index e = 0; e < pp; ++e) R[e] = R[e] + CD[e], CD[e] = 0.0;
  }
  A.resize(p, p);
  std::copy(R.begin(), R.end(), A.data());
  return true;
}

Eigen::MatrixXd gram(const Eigen::MatrixXd& J, const std::vector<std::vector<int>>* nz) {
  Eigen::MatrixXd A;
  if (gram_sparse(J, A, false, nz)) return A;
  return J.transpose() * J;
}

}  // namespace drawbend::loop
