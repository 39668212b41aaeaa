// One probe of the screen (screen_probe.hpp): its explained sums of squares
// under permutation (eval), its held-out gain (probe_cv) and the pooled
// probes' block-centred residual (centred_by).
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

#include "loop/screen_probe.hpp"

namespace drawbend::loop::detail {

namespace {

// L lanes as L / 2 SSE2 vectors of two (GCC's vector extension, as in
// bounded_max; L = 1: the scalar): each lane the same operations in the same
// order as the scalar code, two lanes to an instruction.
template <int L>
struct Pack {
  typedef double v2 __attribute__((vector_size(16)));
  static constexpr int W = L % 2 == 0 ? 2 : 1, N = L / W;
  using T = std::conditional_t<W == 2, v2, double>;
  static T load(const double* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  static void store(double* p, const T& v) { std::memcpy(p, &v, sizeof v); }
  static T splat(double x) {
    if constexpr (W == 2) return T{x, x};
    else return x;
  }
};

}  // namespace

double probe_cv(const ProbeDef& p, const std::vector<int>& rows, const std::vector<double>& z,
                const std::vector<int>& l, const std::vector<double>& w, const std::vector<double>& r,
                const Folds& f, int cell) {
  // pooled index of stratum s: itself, or 0 for the strata of the cell (-1: outside it)
  auto pool = [&](int s) { return cell < 0 ? s : s % p.ngroups == cell ? 0 : -1; };
  double sse0 = 0, sse1 = 0;
  const int S = p.nstrata, L = p.nlev, K = f.k;
  // Each fold's training sums per stratum, of every fold in one pass over the
  // rows (each fold's sums in row order, as a pass per fold made them), and
  // each fold's held-out rows, in order (a fold outside 0..K-1 holds none).
  std::vector<double> SM(static_cast<size_t>(K) * S, 0.0), SN(SM.size(), 0.0);
  std::vector<std::vector<int>> held(static_cast<size_t>(std::max(K, 0)));
  for (int i : rows) {
    const int s = p.row_stratum[i], fi = f.fold[i];
    const double ri = r[i];
    for (int k = 0; k < K; ++k)
      if (k != fi) SM[static_cast<size_t>(k) * S + s] += ri, SN[static_cast<size_t>(k) * S + s] += 1;
    if (fi >= 0 && fi < K) held[fi].push_back(i);
  }
  for (int k = 0; k < K; ++k) {
    std::vector<double> sm(SM.begin() + static_cast<size_t>(k) * S, SM.begin() + static_cast<size_t>(k + 1) * S),
        sn(SN.begin() + static_cast<size_t>(k) * S, SN.begin() + static_cast<size_t>(k + 1) * S), sx(S, 0), sxx(S, 0),
        sxr(S, 0), lm(static_cast<size_t>(S) * L, 0), ln(static_cast<size_t>(S) * L, 0);
    double q11 = 0, q12 = 0, q22 = 0, b1 = 0, b2 = 0;
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
    for (int i : held[k]) {
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
  // s12: cell k's lane j at (k L + j) 2, its s1 and s2 side by side (one
  // two-lane addition of (a, b) where the sums are made per unit).
  if (!sparse || s12.size() != 2 * K * L) {  // every cell; or (sparse) the reachable ones, the rest still empty
    s12.assign(2 * K * L, 0.0);
  } else {
    for (int k : reach)
      for (int j = 0; j < 2 * L; ++j) s12[static_cast<size_t>(k) * 2 * L + j] = 0.0;
  }
  const double* a = w ? urw.data() : ur.data();
  const double* b = w ? uw2.data() : un.data();
  double* c = s12.data();
  if (!w && !fixed_counts.empty()) {  // the counts are those of every permutation
    for (size_t u = 0; u < U; ++u) {
      const size_t k0 = static_cast<size_t>(stratum[u]) * nlev;
      for (int j = 0; j < L; ++j) c[((k0 + static_cast<size_t>(xl[u * L + j])) * L + j) * 2] += a[u];
    }
    auto counts = [&](size_t k) {
      for (int j = 0; j < L; ++j) c[(k * L + j) * 2 + 1] = fixed_counts[k];
    };
    if (sparse)
      for (int k : reach) counts(static_cast<size_t>(k));
    else
      for (size_t k = 0; k < K; ++k) counts(k);
  } else {
    using V = Pack<2>;
    for (size_t u = 0; u < U; ++u) {
      const size_t k0 = static_cast<size_t>(stratum[u]) * nlev;
      const V::T ab = {a[u], b[u]};
      for (int j = 0; j < L; ++j) {
        double* q = c + ((k0 + static_cast<size_t>(xl[u * L + j])) * L + j) * 2;
        V::store(q, V::load(q) + ab);  // s1 += a[u], s2 += b[u]
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
  const double* c = s12.data();  // s1 of cell k, lane j at (k L + j) 2, s2 after it
  for (int j = 0; j < L; ++j) {
    double e = 0;
    each_cell([&](size_t k) {
      const double* q = c + (k * L + j) * 2;
      if (q[1] > 0) e += q[0] * q[0] / q[1];
    });
    out[j] = e;
  }
  if (cells) {
    c1.assign(static_cast<size_t>(G) * nlev * L, 0.0), c2.assign(c1.size(), 0.0);
    each_cell([&](size_t k) {
      const size_t q = static_cast<size_t>((k / nlev) % G) * nlev + k % nlev;
      for (int j = 0; j < L; ++j) c1[q * L + j] += c[(k * L + j) * 2], c2[q * L + j] += c[(k * L + j) * 2 + 1];
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
  using P = Pack<L>;
  using T = typename P::T;
  for (size_t u = 0; u < U;) {  // a run of units in one stratum: its sums held in registers
    const int s = stratum[u];
    const size_t o = static_cast<size_t>(s) * L;
    T a1[P::N], a2[P::N], a3[P::N];
    for (int h = 0; h < P::N; ++h)
      a1[h] = P::load(&s1[o + h * P::W]), a2[h] = P::load(&s2[o + h * P::W]), a3[h] = P::load(&s3[o + h * P::W]);
    for (; u < U && stratum[u] == s; ++u) {
      const T n = P::splat(un[u]), r = P::splat(ur[u]);
      for (int h = 0; h < P::N; ++h) {
        const T x = P::load(xz + u * L + h * P::W);
        a1[h] += n * x, a2[h] += n * x * x, a3[h] += x * r;
      }
    }
    for (int h = 0; h < P::N; ++h)
      P::store(&s1[o + h * P::W], a1[h]), P::store(&s2[o + h * P::W], a2[h]), P::store(&s3[o + h * P::W], a3[h]);
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
  using P = Pack<L>;
  using T = typename P::T;
  T bv[P::N] = {}, av[P::N] = {};
  for (size_t u = 0; u < U; ++u) {
    const T w1 = P::splat(urw[u]), w2 = P::splat(uw2[u]);
    for (int h = 0; h < P::N; ++h) {
      const T x = P::load(xz + u * L + h * P::W);
      bv[h] += x * w1, av[h] += x * x * w2;
    }
  }
  double b[L], a[L];
  for (int h = 0; h < P::N; ++h) P::store(b + h * P::W, bv[h]), P::store(a + h * P::W, av[h]);
  for (int j = 0; j < L; ++j) out[j] = a[j] > 1e-12 ? b[j] * b[j] / a[j] : 0.0;
}

// The quad probe: z and z^2, centred per stratum.
template <int L>
inline void ProbeDef::quad_ess(const double* xz, double* out) const {
  const size_t U = ur.size();
  s1.assign(static_cast<size_t>(nstrata) * L, 0.0), s2.assign(s1.size(), 0.0);
  count_per_stratum();
  using P = Pack<L>;
  using T = typename P::T;
  T v11[P::N] = {}, v12[P::N] = {}, v22[P::N] = {}, vb1[P::N] = {}, vb2[P::N] = {};
  for (size_t u = 0; u < U;) {  // runs of one stratum, as in slopes
    const int s = stratum[u];
    const size_t o = static_cast<size_t>(s) * L;
    T a1[P::N], a2[P::N];
    for (int h = 0; h < P::N; ++h) a1[h] = P::load(&s1[o + h * P::W]), a2[h] = P::load(&s2[o + h * P::W]);
    for (; u < U && stratum[u] == s; ++u) {
      const T n = P::splat(un[u]), r = P::splat(ur[u]);
      for (int h = 0; h < P::N; ++h) {
        const T x = P::load(xz + u * L + h * P::W), x2 = x * x;
        v11[h] += n * x2, v12[h] += n * x2 * x, v22[h] += n * x2 * x2;
        a1[h] += n * x, a2[h] += n * x2;
        vb1[h] += x * r, vb2[h] += x2 * r;
      }
    }
    for (int h = 0; h < P::N; ++h) P::store(&s1[o + h * P::W], a1[h]), P::store(&s2[o + h * P::W], a2[h]);
  }
  double q11[L], q12[L], q22[L], b1[L], b2[L];
  for (int h = 0; h < P::N; ++h) {
    const int j = h * P::W;
    P::store(q11 + j, v11[h]), P::store(q12 + j, v12[h]), P::store(q22 + j, v22[h]);
    P::store(b1 + j, vb1[h]), P::store(b2 + j, vb2[h]);
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
