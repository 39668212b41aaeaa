// One probe of the screen (screen_probe.hpp): its explained sums of squares
// under permutation (eval), its held-out gain (probe_cv) and the pooled
// probes' block-centred residual (centred_by).
#include <cstddef>
#include <vector>

#include "loop/screen_probe.hpp"

namespace drawbend::loop::detail {

double probe_cv(const ProbeDef& p, const std::vector<int>& rows, const std::vector<double>& z,
                const std::vector<int>& l, const std::vector<double>& w, const std::vector<double>& r,
                const Folds& f, int cell) {
  // pooled index of stratum s: itself, or 0 for the strata of the cell (-1: outside it)
  auto pool = [&](int s) { return cell < 0 ? s : s % p.ngroups == cell ? 0 : -1; };
  double sse0 = 0, sse1 = 0;
  const int S = p.nstrata, L = p.nlev;
  for (int k = 0; k < f.k; ++k) {
    std::vector<double> sm(S, 0), sn(S, 0), sx(S, 0), sxx(S, 0), sxr(S, 0), lm(static_cast<size_t>(S) * L, 0),
        ln(static_cast<size_t>(S) * L, 0);
    double q11 = 0, q12 = 0, q22 = 0, b1 = 0, b2 = 0;
    for (int i : rows)
      if (f.fold[i] != k) sm[p.row_stratum[i]] += r[i], sn[p.row_stratum[i]] += 1;
    for (int s = 0; s < S; ++s) sm[s] = sn[s] > 0 ? sm[s] / sn[s] : 0;
    // The stratum means of z (slopes, quad) and z^2 (quad): read by those
    // shapes only, so the other shapes skip their pass (two divisions a row).
    std::vector<double> mz(S, 0), mz2(S, 0);
    if (p.shape == Shape::quad) {
      for (int i : rows)
        if (f.fold[i] != k) mz[p.row_stratum[i]] += z[i] / sn[p.row_stratum[i]], mz2[p.row_stratum[i]] += z[i] * z[i] / sn[p.row_stratum[i]];
    } else if (p.shape == Shape::slopes) {
      for (int i : rows)
        if (f.fold[i] != k) mz[p.row_stratum[i]] += z[i] / sn[p.row_stratum[i]];
    }
    for (int i : rows) {
      if (f.fold[i] == k) continue;
      const int s = p.row_stratum[i], ps = pool(s);
      if (ps < 0) continue;
      const double rc = r[i] - sm[s];
      const size_t li = static_cast<size_t>(ps) * L + l[i];
      switch (p.shape) {
        case Shape::levels: lm[li] += rc, ln[li] += 1; break;
        case Shape::wlevels: lm[li] += w[i] * rc, ln[li] += w[i] * w[i]; break;
        case Shape::slopes: sx[ps] += (z[i] - mz[s]) * (z[i] - mz[s]), sxr[ps] += (z[i] - mz[s]) * rc; break;
        case Shape::wslope: q11 += z[i] * z[i] * w[i] * w[i], b1 += z[i] * w[i] * rc; break;
        case Shape::quad: {
          const double f1 = z[i] - mz[s], f2 = z[i] * z[i] - mz2[s];
          q11 += f1 * f1, q12 += f1 * f2, q22 += f2 * f2, b1 += f1 * rc, b2 += f2 * rc;
          break;
        }
      }
    }
    double c1 = 0, c2 = 0;
    if (p.shape == Shape::quad) {
      const double det = q11 * q22 - q12 * q12;
      if (p.dof[0] == 2 && det > 1e-12 * std::max(1.0, q11 * q22)) c1 = (q22 * b1 - q12 * b2) / det, c2 = (q11 * b2 - q12 * b1) / det;
      else if (q11 > 1e-12) c1 = b1 / q11;
    }
    if (p.shape == Shape::wslope && q11 > 1e-12) c1 = b1 / q11;
    // Per cell, the quotient each held-out row of the cell adds (the same
    // operands as per row, so the same bits), when there are fewer cells than
    // rows: a division per cell instead of per row.
    const bool per_cell = p.shape == Shape::levels && lm.size() <= rows.size();
    if (per_cell)
      for (size_t q = 0; q < lm.size(); ++q) lm[q] = ln[q] > 0 ? lm[q] / ln[q] : 0;
    if (p.shape == Shape::slopes)
      for (int q = 0; q < S; ++q) sxr[q] = sxr[q] / sx[q];
    for (int i : rows) {
      if (f.fold[i] != k) continue;
      const int s = p.row_stratum[i], ps = pool(s);
      if (sn[s] <= 0) continue;
      double pr = sm[s];
      const size_t li = static_cast<size_t>(std::max(ps, 0)) * L + l[i];
      if (ps >= 0) switch (p.shape) {
        case Shape::levels: pr += per_cell ? lm[li] : ln[li] > 0 ? lm[li] / ln[li] : 0; break;
        case Shape::wlevels: pr += ln[li] > 0 ? w[i] * lm[li] / ln[li] : 0; break;
        case Shape::slopes: pr += sx[ps] > 1e-12 ? sxr[ps] * (z[i] - mz[s]) : 0; break;  // sxr: the slope
        case Shape::wslope: pr += c1 * z[i] * w[i]; break;
        case Shape::quad: pr += c1 * (z[i] - mz[s]) + c2 * (z[i] * z[i] - mz2[s]); break;
      }
      sse0 += (r[i] - sm[s]) * (r[i] - sm[s]);
      sse1 += (r[i] - pr) * (r[i] - pr);
    }
  }
  return sse0 > 0 ? 1 - sse1 / sse0 : 0.0;
}

std::vector<double> centred_by(const std::vector<int>& group, int ngroups, const std::vector<int>& rows,
                               const std::vector<double>& r) {
  std::vector<double> s(ngroups, 0.0), m(ngroups, 0.0), out = r;
  for (int i : rows) s[group[i]] += r[i], m[group[i]] += 1;
  for (int i : rows) out[i] = r[i] - s[group[i]] / m[group[i]];
  return out;
}

// The levels and wlevels probes, step 1: the sums per (stratum, level) cell
// and lane, s1 (residual, or weight x residual) and s2 (rows, or squared
// weights), zeroed (every cell, or the reachable ones) and summed over the units.
template <int L>
inline void ProbeDef::level_sums(const int* xl) const {
  const size_t U = ur.size();
  const bool w = shape == Shape::wlevels;
  const size_t K = static_cast<size_t>(nstrata) * nlev;
  const bool sparse = !reach.empty();
  if (!sparse || s1.size() != K * L) {  // every cell; or (sparse) the reachable ones, the rest still empty
    s1.assign(K * L, 0.0);
    s2.assign(K * L, 0.0);
  } else {
    for (int k : reach)
      for (int j = 0; j < L; ++j) s1[static_cast<size_t>(k) * L + j] = 0.0, s2[static_cast<size_t>(k) * L + j] = 0.0;
  }
  const double* a = w ? urw.data() : ur.data();
  const double* b = w ? uw2.data() : un.data();
  if (!w && !fixed_counts.empty()) {  // the counts are those of every permutation
    for (size_t u = 0; u < U; ++u) {
      const size_t k0 = static_cast<size_t>(stratum[u]) * nlev;
      for (int j = 0; j < L; ++j) s1[(k0 + static_cast<size_t>(xl[u * L + j])) * L + j] += a[u];
    }
    if (sparse)
      for (int k : reach)
        for (int j = 0; j < L; ++j) s2[static_cast<size_t>(k) * L + j] = fixed_counts[k];
    else
      for (size_t k = 0; k < K; ++k)
        for (int j = 0; j < L; ++j) s2[k * L + j] = fixed_counts[k];
  } else {
    for (size_t u = 0; u < U; ++u) {
      const size_t k0 = static_cast<size_t>(stratum[u]) * nlev;
      for (int j = 0; j < L; ++j) {
        const size_t k = (k0 + static_cast<size_t>(xl[u * L + j])) * L + j;
        s1[k] += a[u], s2[k] += b[u];
      }
    }
  }
}

// The levels and wlevels probes, step 2: each lane's ESS from the cell sums,
// and (cells) each group's sub-probe.
template <int L>
inline void ProbeDef::level_ess(double* out) const {
  const int G = ngroups;
  const size_t K = static_cast<size_t>(nstrata) * nlev;
  const bool sparse = !reach.empty();
  // An empty cell adds no term (and +0 to the per-group sums below, which
  // are never -0), so summing the reachable cells alone, in order, is exact.
  auto each_cell = [&](auto&& fn) {
    if (sparse)
      for (int k : reach) fn(static_cast<size_t>(k));
    else
      for (size_t k = 0; k < K; ++k) fn(k);
  };
  for (int j = 0; j < L; ++j) {
    double e = 0;
    each_cell([&](size_t k) {
      if (s2[k * L + j] > 0) e += s1[k * L + j] * s1[k * L + j] / s2[k * L + j];
    });
    out[j] = e;
  }
  if (cells) {
    c1.assign(static_cast<size_t>(G) * nlev * L, 0.0), c2.assign(c1.size(), 0.0);
    each_cell([&](size_t k) {
      const size_t q = static_cast<size_t>((k / nlev) % G) * nlev + k % nlev;
      for (int j = 0; j < L; ++j) c1[q * L + j] += s1[k * L + j], c2[q * L + j] += s2[k * L + j];
    });
    for (int g = 0; g < G; ++g)
      for (int j = 0; j < L; ++j) {
        double eg = 0;
        for (int l = 0; l < nlev; ++l) {
          const size_t q = (static_cast<size_t>(g) * nlev + l) * L + j;
          if (c2[q] > 0) eg += c1[q] * c1[q] / c2[q];
        }
        out[(1 + g) * L + j] = eg;
      }
  }
}

// The slopes probe: one centred slope per stratum.
template <int L>
inline void ProbeDef::slopes_ess(const double* xz, double* out) const {
  const size_t U = ur.size();
  const int G = ngroups;
  s1.assign(static_cast<size_t>(nstrata) * L, 0.0), s2.assign(s1.size(), 0.0), s3.assign(s1.size(), 0.0);
  count_per_stratum();  // s4: rows per stratum, the same under every permutation
  for (size_t u = 0; u < U;) {  // a run of units in one stratum: its sums held in registers
    const int s = stratum[u];
    const size_t o = static_cast<size_t>(s) * L;
    double a1[L], a2[L], a3[L];
    for (int j = 0; j < L; ++j) a1[j] = s1[o + j], a2[j] = s2[o + j], a3[j] = s3[o + j];
    for (; u < U && stratum[u] == s; ++u)
      for (int j = 0; j < L; ++j) {
        const double x = xz[u * L + j];
        a1[j] += un[u] * x, a2[j] += un[u] * x * x, a3[j] += x * ur[u];
      }
    for (int j = 0; j < L; ++j) s1[o + j] = a1[j], s2[o + j] = a2[j], s3[o + j] = a3[j];
  }
  for (int j = 0; j < L; ++j) {
    double e = 0;
    if (cells) c1.assign(G, 0.0), c2.assign(G, 0.0);
    for (int s = 0; s < nstrata; ++s) {
      const size_t h = static_cast<size_t>(s) * L + j;
      const double a = s4[s] > 0 ? s2[h] - s1[h] * s1[h] / s4[s] : 0;
      if (a > 1e-12) e += s3[h] * s3[h] / a;
      if (cells && a > 1e-12) c1[s % G] += s3[h], c2[s % G] += a;
    }
    out[j] = e;
    if (cells)
      for (int g = 0; g < G; ++g) out[(1 + g) * L + j] = c2[g] > 1e-12 ? c1[g] * c1[g] / c2[g] : 0.0;
  }
}

// The wslope probe: one slope on z w (multiplicative: the effect scales with dF/dmu).
template <int L>
inline void ProbeDef::wslope_ess(const double* xz, double* out) const {
  const size_t U = ur.size();
  double b[L] = {}, a[L] = {};
  for (size_t u = 0; u < U; ++u)
    for (int j = 0; j < L; ++j) {
      const double x = xz[u * L + j];
      b[j] += x * urw[u], a[j] += x * x * uw2[u];
    }
  for (int j = 0; j < L; ++j) out[j] = a[j] > 1e-12 ? b[j] * b[j] / a[j] : 0.0;
}

// The quad probe: z and z^2, centred per stratum.
template <int L>
inline void ProbeDef::quad_ess(const double* xz, double* out) const {
  const size_t U = ur.size();
  s1.assign(static_cast<size_t>(nstrata) * L, 0.0), s2.assign(s1.size(), 0.0);
  count_per_stratum();
  double q11[L] = {}, q12[L] = {}, q22[L] = {}, b1[L] = {}, b2[L] = {};
  for (size_t u = 0; u < U;) {  // runs of one stratum, as in slopes
    const int s = stratum[u];
    const size_t o = static_cast<size_t>(s) * L;
    double a1[L], a2[L];
    for (int j = 0; j < L; ++j) a1[j] = s1[o + j], a2[j] = s2[o + j];
    for (; u < U && stratum[u] == s; ++u)
      for (int j = 0; j < L; ++j) {
        const double x = xz[u * L + j], x2 = x * x, n = un[u];
        q11[j] += n * x2, q12[j] += n * x2 * x, q22[j] += n * x2 * x2;
        a1[j] += n * x, a2[j] += n * x2;
        b1[j] += x * ur[u], b2[j] += x2 * ur[u];
      }
    for (int j = 0; j < L; ++j) s1[o + j] = a1[j], s2[o + j] = a2[j];
  }
  for (int j = 0; j < L; ++j) {
    for (int k = 0; k < nstrata; ++k) {
      const size_t h = static_cast<size_t>(k) * L + j;
      if (s4[k] > 0)
        q11[j] -= s1[h] * s1[h] / s4[k], q12[j] -= s1[h] * s2[h] / s4[k], q22[j] -= s2[h] * s2[h] / s4[k];
    }
    const double lin = q11[j] > 1e-12 ? b1[j] * b1[j] / q11[j] : 0.0;
    if (dof[0] == 1) { out[j] = lin; continue; }
    const double det = q11[j] * q22[j] - q12[j] * q12[j];
    if (det <= 1e-12 * std::max(1.0, q11[j] * q22[j])) { out[j] = lin; continue; }
    const double c1q = (q22[j] * b1[j] - q12[j] * b2[j]) / det, c2q = (q11[j] * b2[j] - q12[j] * b1[j]) / det;
    out[j] = c1q * b1[j] + c2q * b2[j];
  }
}

// Lane j: the one-permutation pass's operations in the same order on its own
// sums ([k L + j]), so its ESS is bit for bit that of the permutation alone,
// and the lanes' chains of additions overlap instead of waiting in turn.
template <int L>
void ProbeDef::eval(const double* xz, const int* xl, double* out) const {
  switch (shape) {
    case Shape::levels:
    case Shape::wlevels:
      level_sums<L>(xl);
      level_ess<L>(out);
      return;
    case Shape::slopes:
      slopes_ess<L>(xz, out);
      return;
    case Shape::wslope:
      wslope_ess<L>(xz, out);
      return;
    case Shape::quad:
      quad_ess<L>(xz, out);
      return;
  }
}

template void ProbeDef::eval<1>(const double*, const int*, double*) const;
template void ProbeDef::eval<kLanes>(const double*, const int*, double*) const;

}  // namespace drawbend::loop::detail
