// The permutation test's bounded pass (issue 50 item 6): an upper bound on a
// permutation's statistic from one pass over the rows, so that the probes'
// exact sums are made only for a permutation that may reach the observed T.
//
// What the test writes is decided by comparisons alone: a permutation counts
// when its statistic (the family's largest probe_z) is >= T' = T - 1e-12
// max(1, |T|).  A significant row-level candidate's 3,100 permutations all lie
// far below T, and each cost a pass per probe over every row.  Here, for a
// row-level candidate permuted within tests (every test a run of rows, every
// probe's stratum constant within a test), one pass per permutation sums per
// key (the tests alike in every probe's stratum) and level the raw residual r0
// (and x r0, and the scaled probe's sums), from which every levels probe (fixed
// counts), slopes probe and the scaled slope follow with O(keys x levels) work
// per probe (a pooled levels probe, its residual
// centred per block first, with the block means' sum per cell taken out: the
// same under every permutation).  These sums differ from the exact
// ones only by rounding, and each is given a bound on that difference:
//   - a probe's centred residual is ur = fl(r0 - M) (M: its stratum's mean,
//     ProbeDef::mean), so ur = r0 - M + eta with |eta| <= u |r0 - M|;
//   - any floating-point sum of m terms, in any order or tree, is within
//     gamma_m = m u / (1 - m u) of the sum of its terms' absolute values
//     (Higham, Accuracy and Stability, 2nd ed., eq. 4.4 and Sec. 4.2).
// So a cell sum s1 of the exact code and its bounded-pass value differ by at
// most (4 n + 8) u R, R = sum over the stratum of |r0| + |M|, n its rows;
// the bounds below take 4 times that.  Each probe's ESS is then bounded above
// by the sum of (|s1| + e)^2 / count over its cells (slopes: (|s3| + e)^2 /
// a_lo), times a factor for the rounding of both sums of terms.  probe_z is
// increasing in the ESS; a permutation whose bounded statistic lies below T'
// by 1e-8 max(1, |T'|) (far more than probe_z's rounding) cannot count.
// Every other permutation is evaluated by the exact passes and counted by the
// same comparison as before, so the counts, p-values, permutation numbers and
// decisions are those of the exact test, bit for bit.  The pilot calibration
// and the observed statistic keep the exact passes (their values are written).
#include <algorithm>
#include <cmath>
#include <map>

#include "loop/screen_candidate.hpp"

namespace drawbend::loop::detail {

namespace {

constexpr double kU = 0x1p-53;  // unit roundoff of double
constexpr int kMaxLevels = 64;  // a levels probe with more levels keeps the exact pass

// The quad probe's setup: Q = [q11 q12; q12 q22] (z and z^2 centred per
// stratum: the same multiset under every permutation) and which branch the
// exact pass takes (mode 0: no term, 1: the line b1^2 / q11, 2: b' Q^-1 b);
// false when a branch is too close to call.  Every entry of Q is within
// 2 gamma_(n+2) of a sum of |x|^2, |x|^3 or |x|^4 (the stratum products by
// Cauchy-Schwarz and Chebyshev's sum inequality), exact pass and here alike.
bool quad_setup(const ProbeDef& p, const std::vector<double>& n, const std::vector<double>& xz, BoundProbe& b) {
  const int S = p.nstrata;
  std::vector<double> s1(S, 0.0), s2(S, 0.0);
  double q11 = 0, q12 = 0, q22 = 0, m2 = 0, m3 = 0, m4 = 0;
  for (size_t u = 0; u < xz.size(); ++u) {
    const double x = xz[u], x2 = x * x;
    s1[p.stratum[u]] += x, s2[p.stratum[u]] += x2;
    q11 += x2, q12 += x2 * x, q22 += x2 * x2, m2 += x2, m3 += x2 * std::abs(x), m4 += x2 * x2;
  }
  for (int s = 0; s < S; ++s)
    if (n[s] > 0) q11 -= s1[s] * s1[s] / n[s], q12 -= s1[s] * s2[s] / n[s], q22 -= s2[s] * s2[s] / n[s];
  const double U = static_cast<double>(xz.size()), eq = 32 * (U + S + 8) * kU * (m2 + m3 + m4);
  b.q11 = q11, b.q12 = q12, b.q22 = q22, b.eq = eq;
  if (q11 + eq <= 1e-12 && p.dof[0] == 1) return b.mode = 0, true;  // (two dof: left to the exact pass)
  if (q11 - eq <= 1e-12) return false;
  if (p.dof[0] == 1) return b.mode = 1, true;
  // the exact pass's det test: det <= 1e-12 max(1, q11 q22)
  const double det = q11 * q22 - q12 * q12, thr = 1e-12 * std::max(1.0, q11 * q22);
  const double ed = 4 * eq * (std::abs(q11) + std::abs(q22) + std::abs(q12) + eq) + 8 * kU * (std::abs(q11 * q22) + q12 * q12);
  if (std::abs(det - thr) <= 2 * ed + 1e-11 * std::max(1.0, std::abs(q11 * q22))) return false;
  if (det <= thr) return b.mode = 1, true;
  // smallest eigenvalue of Q, and Q_exact >= Q - eps I (eps = 2 eq >= the 2-norm of the difference)
  const double tr = q11 + q22, rad = std::sqrt((q11 - q22) * (q11 - q22) + 4 * q12 * q12);
  const double lam = (tr - rad) / 2 - 1e-9 * tr, eps = 2 * eq;
  if (!(lam > 4 * eps)) return false;
  b.lam = lam, b.cond = (tr + rad) / 2 / lam;
  return b.mode = 2, true;
}

}  // namespace

void CandidateScreen::setup_bounds() {
  bounded = false;
  bprobes.clear();
  bws = -1;
  bfast.assign(probes.size(), 0);
  // Units are the rows (in order), the groups the tests as consecutive runs
  // covering the units in order; the values a permutation of them.
  if (two_level || c.test_level || U != rows.size() || U == 0 || nlev > kMaxLevels) return;
  for (size_t u = 0; u < U; ++u)
    if (unit_of[rows[u]] != static_cast<int>(u)) return;
  size_t next = 0;
  for (size_t gi = 0; gi < groups.size(); ++gi) {
    if (!run[gi] || static_cast<size_t>(gfirst[gi]) != next) return;
    next += static_cast<size_t>(gsize[gi]);
  }
  if (next != U) return;
  quad = false;
  bwl = -1;
  r0.resize(U);
  for (size_t u = 0; u < U; ++u) r0[u] = resid[rows[u]];
  // A pooled probe's residual is centred per block first (centred_by): the
  // block means per unit, computed as there (the same sums in the same order).
  std::vector<double> bmu;
  auto block_means = [&]() {
    if (!bmu.empty()) return;
    std::vector<double> s(static_cast<size_t>(nblocks), 0.0), m(s.size(), 0.0);
    for (int i : rows) s[f.block[i]] += resid[i], m[f.block[i]] += 1;
    bmu.resize(U);
    for (size_t u = 0; u < U; ++u) bmu[u] = s[f.block[rows[u]]] / m[f.block[rows[u]]];
  };
  for (size_t j = 0; j < probes.size(); ++j) {
    const ProbeDef& p = probes[j];
    const bool pooled = !p.rpre.empty();
    if ((pooled && (p.shape != Shape::levels || p.fixed_counts.empty())) || p.cells || p.nsub() != 1 || p.dof[0] <= 0)
      continue;
    if (pooled) block_means();
    bool constant = true;  // the probe's stratum constant within every test
    for (size_t gi = 0; gi < groups.size() && constant; ++gi)
      for (int k = 1; k < gsize[gi]; ++k) constant = constant && p.stratum[gfirst[gi] + k] == p.stratum[gfirst[gi]];
    if (!constant) continue;
    const int S = p.nstrata;
    std::vector<double> n(S, 0.0), R(S, 0.0), xmax(S, 0.0), sx(S, 0.0), sxx(S, 0.0);
    double sum_urw = 0, xall = 0;
    for (size_t u = 0; u < U; ++u) {
      const int s = p.stratum[u];
      n[s] += 1, R[s] += std::abs(r0[u]) + std::abs(p.mean[s]) + (pooled ? std::abs(bmu[u]) : 0.0);
      xmax[s] = std::max(xmax[s], std::abs(xz[u])), sx[s] += xz[u], sxx[s] += xz[u] * xz[u];
      sum_urw += std::abs(p.urw[u]), xall = std::max(xall, std::abs(xz[u]));
    }
    BoundProbe b;
    b.j = static_cast<int>(j);
    b.gstratum.resize(groups.size());
    for (size_t gi = 0; gi < groups.size(); ++gi) b.gstratum[gi] = p.stratum[gfirst[gi]];
    if (p.shape == Shape::levels && !p.fixed_counts.empty()) {
      b.e.resize(S);
      for (int s = 0; s < S; ++s) b.e[s] = 16 * ((pooled ? 2 : 1) * n[s] + 8) * kU * R[s];
      if (pooled) {  // per cell: the sum of the block means over its rows (the same under every permutation)
        b.bsum.assign(static_cast<size_t>(S) * nlev, 0.0);
        for (size_t u = 0; u < U; ++u) b.bsum[static_cast<size_t>(p.stratum[u]) * nlev + xl[u]] += bmu[u];
      }
      b.acc.assign(static_cast<size_t>(S) * nlev * kLanes, 0.0);
      b.factor = 1 + 16 * (static_cast<double>(S) * nlev + 16) * kU;
    } else if (p.shape == Shape::slopes) {
      b.e.assign(S, 0.0), b.alo.assign(S, 0.0), b.sx = sx;
      bool clear = true;
      for (int s = 0; s < S && clear; ++s) {
        if (n[s] == 0) continue;
        // a = sum x^2 - (sum x)^2 / n over the stratum: the same multiset
        // under every permutation; exact and here within (8 n + 16) u sum x^2.
        const double a = sxx[s] - sx[s] * sx[s] / n[s], ea = (16 * n[s] + 32) * kU * sxx[s];
        if (a + ea <= 1e-12) continue;  // the exact pass adds no term (a <= 1e-12)
        if (a - ea <= 1e-12) clear = false;  // too close to call: the exact passes decide
        b.alo[s] = a - ea;
        b.e[s] = 16 * (n[s] + 8) * kU * xmax[s] * R[s];
      }
      if (!clear) continue;
      b.acc.assign(static_cast<size_t>(S) * kLanes, 0.0);
      b.factor = 1 + 16 * (static_cast<double>(S) + 16) * kU;
    } else if (p.shape == Shape::quad) {
      if (!quad_setup(p, n, xz, b)) continue;
      double Rall = 0;
      for (int s = 0; s < S; ++s) Rall += R[s];
      b.sx = sx, b.sxx = sxx;
      b.eb = 16 * (static_cast<double>(U) + S + 8) * kU * xall * Rall;
      b.eb2 = b.eb * xall;
      b.factor = 1 + 64 * kU;
      b.acc.assign(static_cast<size_t>(S) * 2 * kLanes, 0.0);
      quad = true;
    } else if (p.shape == Shape::wlevels && weighted) {
      // One probe: its own urw and uw2 summed per cell, the exact pass's
      // inputs in another order: s1 within 2 gamma of the sum of |urw|, s2
      // (>= 0 terms) within 2 gamma relative, and zero exactly when zero there.
      if (bwl >= 0) continue;
      std::vector<double> Rw(S, 0.0);
      for (size_t u = 0; u < U; ++u) Rw[p.stratum[u]] += std::abs(p.urw[u]);
      b.e.resize(S), b.alo.resize(S);
      for (int s = 0; s < S; ++s) b.e[s] = 16 * (n[s] + 8) * kU * Rw[s], b.alo[s] = 1 - 16 * (n[s] + 8) * kU;
      b.acc.assign(static_cast<size_t>(S) * nlev * 2 * kLanes, 0.0);
      b.factor = 1 + 16 * (static_cast<double>(S) * nlev + 16) * kU;
      bwl = static_cast<int>(bprobes.size());
    } else if (p.shape == Shape::wslope) {
      if (bws >= 0) continue;
      b.eb = 16 * (static_cast<double>(U) + 8) * kU * xall * sum_urw;
      b.arel = 16 * (static_cast<double>(U) + 8) * kU;
      b.factor = 1 + 64 * kU;
      bws = static_cast<int>(bprobes.size());
    } else {
      continue;
    }
    bfast[j] = 1;
    bprobes.push_back(std::move(b));
  }
  bounded = !bprobes.empty();
  // The keys: tests alike in every bounded probe's stratum, in order of first appearance.
  const size_t nb = bprobes.size();
  gkey.assign(groups.size(), 0), kstratum.clear(), nkeys = 0;
  std::map<std::vector<int>, int> keys;
  std::vector<int> key(nb);
  for (size_t gi = 0; gi < groups.size() && bounded; ++gi) {
    for (size_t i = 0; i < nb; ++i) key[i] = bprobes[i].gstratum[gi];
    const auto [it, added] = keys.emplace(key, nkeys);
    if (added) kstratum.insert(kstratum.end(), key.begin(), key.end()), ++nkeys;
    gkey[gi] = it->second;
  }
  ka.assign(static_cast<size_t>(nkeys) * nlev * kLanes, 0.0);
  kaw.assign(bwl >= 0 ? static_cast<size_t>(nkeys) * nlev * 2 * kLanes : 0, 0.0);
  kx.assign(static_cast<size_t>(nkeys) * 2 * kLanes, 0.0);
  xlo.resize(U);
  for (size_t u = 0; u < U; ++u) xlo[u] = static_cast<long>(xl[u]) * kLanes;
}

// The quad probe's ESS bound in lane j: b1 = sum x ur, b2 = sum x^2 ur (the
// stratum means taken out of the test sums), each within eb (eb2) of the
// exact pass's.  Branch 2: with Q_exact >= Q - eps I >= (1 - eps / lam) Q,
// b' Q_exact^-1 b <= b' Q^-1 b / (1 - eps / lam), and the Q^-1-norm of the
// change in b is at most |d| / sqrt(lam); each computed b' Q^-1 b is within
// 64 u (1 + cond) |b|^2 / lam of its value (Cramer's rule on a 2 x 2).
double CandidateScreen::quad_bound(const ProbeDef& p, const BoundProbe& b, int j) const {
  constexpr int L = kLanes;
  double b1 = 0, b2 = 0;
  for (int s = 0; s < p.nstrata; ++s)
    b1 += b.acc[static_cast<size_t>(s) * 2 * L + j] - p.mean[s] * b.sx[s],
        b2 += b.acc[(static_cast<size_t>(s) * 2 + 1) * L + j] - p.mean[s] * b.sxx[s];
  if (b.mode == 0) return 0.0;
  if (b.mode == 1) {
    const double t = std::abs(b1) + b.eb;
    return t * t / (b.q11 - b.eq);
  }
  const double det = b.q11 * b.q22 - b.q12 * b.q12;
  const double c1 = (b.q22 * b1 - b.q12 * b2) / det, c2 = (b.q11 * b2 - b.q12 * b1) / det;
  const double eps = 2 * b.eq, bb = (std::abs(b1) + b.eb) * (std::abs(b1) + b.eb) + (std::abs(b2) + b.eb2) * (std::abs(b2) + b.eb2);
  const double slack = 64 * kU * (1 + b.cond) * bb / b.lam;
  const double t = std::sqrt(std::max(0.0, c1 * b1 + c2 * b2) + slack) + std::sqrt((b.eb * b.eb + b.eb2 * b.eb2) / b.lam);
  return t * t / (1 - eps / b.lam) + slack;
}

// The largest upper bound of the bounded probes' statistics in each lane
// (+infinity when a bound cannot be given: the exact passes decide), zmax[j]
// for the kLanes lanes side by side, lane j's permutation lp[j] (unit u takes
// unit lp[j][u]'s value; lanes past the last permutation repeat lane 0).  Its sums may be made in any order: only their bounds matter.
void CandidateScreen::bounded_max(const std::vector<int>* lp, double* zmax) {
  constexpr int L = kLanes;
  const int* p0 = lp[0].data();
  const int* p1 = lp[1].data();
  const int* p2 = lp[2].data();
  const int* p3 = lp[3].data();
  static_assert(L == 4, "bounded_max reads four lanes' permutations");
  std::fill(ka.begin(), ka.end(), 0.0), std::fill(kaw.begin(), kaw.end(), 0.0), std::fill(kx.begin(), kx.end(), 0.0);
  const double* urw = bws >= 0 ? probes[bprobes[bws].j].urw.data() : nullptr;
  const double* uw2 = bws >= 0 ? probes[bprobes[bws].j].uw2.data() : nullptr;
  const double* wl1 = bwl >= 0 ? probes[bprobes[bwl].j].urw.data() : nullptr;
  const double* wl2 = bwl >= 0 ? probes[bprobes[bwl].j].uw2.data() : nullptr;
  // Two lanes to a vector (GCC's vector extension: the same operations on
  // each lane as in scalar code; SSE2 keeps these sums in registers).
  typedef double v2 __attribute__((vector_size(16)));
  typedef double v2u __attribute__((vector_size(16), aligned(8)));  // (at any double's address)
  v2 wb[2] = {}, wa[2] = {};
  // The rows' terms summed per key (tests alike in every probe's stratum),
  // then the keys' sums per probe and stratum.
  for (size_t gi = 0; gi < groups.size(); ++gi) {
    const size_t u0 = static_cast<size_t>(gfirst[gi]), u1 = u0 + static_cast<size_t>(gsize[gi]);
    const size_t k = static_cast<size_t>(gkey[gi]);
    double* A = ka.data() + k * nlev * L;
    // the wlevels probe's per-level sums of urw and uw2, side by side: (level, lane) pairs
    double* AW = wl2 ? kaw.data() + k * nlev * 2 * L : nullptr;
    v2 x1[2] = {}, x2[2] = {};
    for (size_t u = u0; u < u1; ++u) {
      const double r = r0[u];
      // lane j's value of unit u: the unit its permutation puts there
      const int v[L] = {p0[u], p1[u], p2[u], p3[u]};
      const v2 x[2] = {{xz[v[0]], xz[v[1]]}, {xz[v[2]], xz[v[3]]}};
      // lane j's sums of level l at (l L + j): o[j] = l L, in 64 bits (an address mode, no widening)
      const long o[L] = {xlo[v[0]], xlo[v[1]], xlo[v[2]], xlo[v[3]]};
      for (int j = 0; j < L; ++j) A[o[j] + j] += r;
      const v2 rr = {r, r};
      for (int h = 0; h < 2; ++h) x1[h] += x[h] * rr;
      if (quad)
        for (int h = 0; h < 2; ++h) x2[h] += x[h] * x[h] * rr;
      if (wl2) {
        const v2 w = {wl1[u], wl2[u]};
        for (int j = 0; j < L; ++j) {
          v2u* a = reinterpret_cast<v2u*>(AW + (o[j] + j) * 2);
          *a += w;
        }
      }
      if (urw) {
        const v2 w1 = {urw[u], urw[u]}, w2 = {uw2[u], uw2[u]};
        for (int h = 0; h < 2; ++h) wb[h] += x[h] * w1, wa[h] += x[h] * x[h] * w2;
      }
    }
    for (int j = 0; j < L; ++j) kx[k * 2 * L + j] += x1[j / 2][j % 2], kx[(k * 2 + 1) * L + j] += x2[j / 2][j % 2];
  }
  const size_t nb = bprobes.size();
  for (size_t i = 0; i < nb; ++i) {
    BoundProbe& b = bprobes[i];
    const ProbeDef& p = probes[b.j];
    std::fill(b.acc.begin(), b.acc.end(), 0.0);
    for (size_t k = 0; k < static_cast<size_t>(nkeys); ++k) {
      const size_t s = static_cast<size_t>(kstratum[k * nb + i]);
      if (p.shape == Shape::levels) {
        double* d = b.acc.data() + s * nlev * L;
        const double* A = ka.data() + k * nlev * L;
        for (int q = 0; q < nlev * L; ++q) d[q] += A[q];
      } else if (p.shape == Shape::slopes) {
        for (int j = 0; j < L; ++j) b.acc[s * L + j] += kx[k * 2 * L + j];
      } else if (p.shape == Shape::quad) {
        for (int j = 0; j < L; ++j)
          b.acc[s * 2 * L + j] += kx[k * 2 * L + j], b.acc[(s * 2 + 1) * L + j] += kx[(k * 2 + 1) * L + j];
      } else if (p.shape == Shape::wlevels) {
        double* d = b.acc.data() + s * nlev * 2 * L;
        const double* AW = kaw.data() + k * nlev * 2 * L;
        for (int l = 0; l < nlev; ++l)
          for (int j = 0; j < L; ++j)
            d[l * 2 * L + j] += AW[(l * L + j) * 2], d[l * 2 * L + L + j] += AW[(l * L + j) * 2 + 1];
      }
    }
  }
  for (int j = 0; j < L; ++j) zmax[j] = -INFINITY;
  for (const auto& b : bprobes) {
    const ProbeDef& p = probes[b.j];
    double ess[L] = {};
    if (p.shape == Shape::levels) {
      for (int s = 0; s < p.nstrata; ++s)
        for (int l = 0; l < nlev; ++l) {
          const size_t k = static_cast<size_t>(s) * nlev + l;
          const double N = p.fixed_counts[k], B = b.bsum.empty() ? 0.0 : b.bsum[k];
          if (N > 0)
            for (int j = 0; j < L; ++j) {
              const double t = std::abs(b.acc[k * L + j] - B - p.mean[s] * N) + b.e[s];
              ess[j] += t * t / N;
            }
        }
    } else if (p.shape == Shape::slopes) {
      for (int s = 0; s < p.nstrata; ++s)
        if (b.alo[s] > 0)
          for (int j = 0; j < L; ++j) {
            const double t = std::abs(b.acc[static_cast<size_t>(s) * L + j] - p.mean[s] * b.sx[s]) + b.e[s];
            ess[j] += t * t / b.alo[s];
          }
    } else if (p.shape == Shape::quad) {
      for (int j = 0; j < L; ++j) ess[j] = quad_bound(p, b, j);
    } else if (p.shape == Shape::wlevels) {
      for (int s = 0; s < p.nstrata; ++s)
        for (int l = 0; l < nlev; ++l) {
          const double* a = b.acc.data() + (static_cast<size_t>(s) * nlev + l) * 2 * L;
          for (int j = 0; j < L; ++j)
            if (a[L + j] > 0) {
              const double t = std::abs(a[j]) + b.e[s];
              ess[j] += t * t / (a[L + j] * b.alo[s]);
            }
        }
    } else {  // wslope: b^2 / a when a > 1e-12
      for (int j = 0; j < L; ++j) {
        const double wa_j = wa[j / 2][j % 2], alo = wa_j * (1 - b.arel), ahi = wa_j * (1 + b.arel),
                     t = std::abs(wb[j / 2][j % 2]) + b.eb;
        ess[j] = ahi <= 1e-12 ? 0.0 : alo <= 1e-12 ? INFINITY : t * t / alo;
      }
    }
    for (int j = 0; j < L; ++j) zmax[j] = std::max(zmax[j], probe_z(p, 0, ess[j] * b.factor));
  }
}

}  // namespace drawbend::loop::detail
