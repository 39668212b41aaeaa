// Pairwise probes between undeclared numeric columns (issue 50, h50-pairs):
// an effect of two columns together, e.g. a pure crossover mu ~ z1 z2 with no
// main effect of either, which no single-column probe sees (E[z1 z2 | z1] = 0).
//
// Each pair (a, b) of numeric columns of the data (kind "column", not a
// function of a model input) is a candidate "a*b" whose value is the product
// of the centred columns (Design::values computes the same for the forms).
// The pairs are screened as ONE family per permutation scheme, with one
// permutation test of the family's maximum, so the family counts as one
// candidate in the Bonferroni threshold alpha / (candidates + families):
//   rows    pairs with at least one row-level column: the rows of each test
//           permuted (all columns jointly, so the same permutation for every
//           pair), the probe's values and the residual centred per test;
//   tests   every pair: the tests of each block permuted, per test the sum of
//           the residual and the mean of the product (a test-level column
//           times a row-level one's test mean: the between-test part of a
//           mixed pair, which the rows family cannot see), centred per block.
// Each pair's statistic is Z = (sum_u a_u p_u)^2 / E, a the (dF/dmu weighted)
// residual per unit, p the pair's product per unit, both centred per group,
// p made orthogonal to the two columns themselves (weighted by the unit's sum
// of squared dF/dmu), so a main effect of either column does not pass for a
// pair (without it, Chapter 7's synthetic study took a pair of the true column
// and a decoy, or a decoy pair, as steps on 3 of 150 effect sets);
// E is its exact mean under the permutation, sum_g (sum p^2)(sum a^2) / (m_g - 1),
// so every pair is on the chi^2(1) scale whatever its spread.  The family's
// statistic is the largest Z; its permutation p-value (the sequential
// Clopper-Pearson rule of the single screen) decides.  Cost: one dot product
// per pair and permutation; at most kMaxPairColumns columns are paired (the
// first in the candidates' order), C(16, 2) = 120 pairs.
#include <algorithm>
#include <cmath>

#include "loop/candidates.hpp"
#include "loop/effects.hpp"
#include "loop/fast_mod.hpp"
#include "loop/mt64.hpp"

namespace drawbend::loop {

namespace {

constexpr size_t kMaxPairColumns = 16;

// One family: units, their groups (permuted within), the residual per unit and
// each pair's centred product per unit.
struct PairFamily {
  std::vector<size_t> pairs;           // indices into the pair candidates
  std::vector<std::vector<int>> rows;  // per unit: its rows
  std::vector<int> group;              // per unit
  std::vector<std::vector<int>> members;  // per group: its units
  std::vector<double> a;               // per unit: weighted residual, centred per group
  std::vector<double> p;               // per pair j, unit u: p[j * U + u]
  std::vector<double> e;               // per pair: the statistic's mean under permutation
  size_t U = 0;
};

// Centre v per group (units of each group).
void centre(std::vector<double>& v, const std::vector<std::vector<int>>& members, size_t off = 0) {
  for (const auto& g : members) {
    double m = 0;
    for (int u : g) m += v[off + u];
    m /= static_cast<double>(g.size());
    for (int u : g) v[off + u] -= m;
  }
}

// The units and groups of a family: rows within tests, or tests within blocks.
void units(PairFamily& F, bool tests, const std::vector<double>& resid, const Folds& f) {
  const size_t n = resid.size();
  std::vector<int> uix, gix;  // dense keys: test -> unit (tests), test/block -> group
  int tmax = 0, bmax = 0;
  for (size_t i = 0; i < n; ++i) tmax = std::max(tmax, f.test[i]), bmax = std::max(bmax, f.block[i]);
  uix.assign(tmax + 1, -1), gix.assign(std::max(tmax, bmax) + 1, -1);
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(resid[i])) continue;
    const int gk = tests ? f.block[i] : f.test[i];
    int& g = gix[gk];
    if (g < 0) g = static_cast<int>(F.members.size()), F.members.push_back({});
    int u;
    if (tests) {
      int& t = uix[f.test[i]];
      if (t < 0) t = static_cast<int>(F.rows.size()), F.rows.push_back({}), F.group.push_back(g), F.members[g].push_back(t);
      u = t;
    } else {
      u = static_cast<int>(F.rows.size());
      F.rows.push_back({}), F.group.push_back(g), F.members[g].push_back(u);
    }
    F.rows[u].push_back(static_cast<int>(i));
  }
  F.U = F.rows.size();
}

// A column per unit (tests: its mean over the test's rows), centred per group;
// a missing value adds nothing (the value at the centre of its group).
std::vector<double> unit_values(const PairFamily& F, const std::vector<double>& x) {
  const size_t U = F.U;
  std::vector<double> v(U, 0.0), has(U, 0.0);
  for (size_t u = 0; u < U; ++u) {
    double sx = 0, k = 0;
    for (int i : F.rows[u])
      if (std::isfinite(x[i])) sx += x[i], k += 1;
    if (k > 0) v[u] = sx / k, has[u] = 1;
  }
  for (const auto& g : F.members) {
    double m = 0, k = 0;
    for (int u : g) m += v[u] * has[u], k += has[u];
    if (k > 0) m /= k;
    for (int u : g) v[u] = has[u] ? v[u] - m : 0.0;
  }
  return v;
}

// v made orthogonal to the columns m (in turn, Gram-Schmidt) in the metric q:
// sum_u q_u v_u m_u = 0 for each.  A main effect of either column in the
// residual (a_u ~ q_u m_u: the effect on mu is scaled by dF/dmu, and a is the
// dF/dmu-weighted residual) then adds nothing to the pair's observed statistic.
void orthogonal_to(std::vector<double>& v, std::vector<std::vector<double>> m, const std::vector<double>& q) {
  for (size_t k = 0; k < m.size(); ++k) {
    for (size_t l = 0; l < k; ++l) {  // m_k orthogonal to the earlier (already orthogonal) ones
      double num = 0, den = 0;
      for (size_t u = 0; u < v.size(); ++u) num += q[u] * m[k][u] * m[l][u], den += q[u] * m[l][u] * m[l][u];
      if (den > 0)
        for (size_t u = 0; u < v.size(); ++u) m[k][u] -= num / den * m[l][u];
    }
  }
  for (const auto& mk : m) {
    double num = 0, den = 0, vv = 0;
    for (size_t u = 0; u < v.size(); ++u) num += q[u] * v[u] * mk[u], den += q[u] * mk[u] * mk[u], vv += q[u] * v[u] * v[u];
    if (den > 1e-12 * vv)  // a column with no spread in this family (a test-level one centred per test)
      for (size_t u = 0; u < v.size(); ++u) v[u] -= num / den * mk[u];
  }
}

// Residual and products per unit (the products orthogonal to their two
// columns); the exact permutation means.
void fill(PairFamily& F, const std::vector<Candidate>& pc, const std::vector<Candidate>& cands,
          const std::vector<double>& resid, const std::vector<double>& w) {
  const size_t U = F.U, J = F.pairs.size();
  F.a.assign(U, 0.0);
  std::vector<double> q(U, 0.0);  // per unit: the sum of squared weights
  for (size_t u = 0; u < U; ++u)
    for (int i : F.rows[u]) F.a[u] += (w.empty() ? 1.0 : w[i]) * resid[i], q[u] += w.empty() ? 1.0 : w[i] * w[i];
  centre(F.a, F.members);
  F.p.assign(J * U, 0.0);
  F.e.assign(J, 0.0);
  for (size_t j = 0; j < J; ++j) {
    const Candidate& pj = pc[F.pairs[j]];
    std::vector<double> v = unit_values(F, pj.x);
    std::vector<std::vector<double>> mains;
    for (const auto& name : pj.pair)
      for (const auto& c : cands)
        if (c.name == name) mains.push_back(unit_values(F, c.x));
    orthogonal_to(v, mains, q);
    std::copy(v.begin(), v.end(), F.p.begin() + j * U);
    double e = 0;
    for (const auto& g : F.members) {
      if (g.size() < 2) continue;
      double sp = 0, sa = 0;
      for (int u : g) sp += v[u] * v[u], sa += F.a[u] * F.a[u];
      e += sp * sa / (g.size() - 1.0);
    }
    F.e[j] = e;
  }
}

// The family's statistic with the residual a (per unit): max over pairs of Z; the best pair.
double family_stat(const PairFamily& F, const std::vector<double>& a, size_t* best) {
  double t = -INFINITY;
  const size_t U = F.U;
  for (size_t j = 0; j < F.pairs.size(); ++j) {
    if (!(F.e[j] > 0)) continue;
    const double* pj = F.p.data() + j * U;
    double s = 0;
    for (size_t u = 0; u < U; ++u) s += pj[u] * a[u];
    const double z = s * s / F.e[j];
    if (z > t) t = z, *best = j;
  }
  return t;
}

// Held-out gain of the pair's slope on the model's folds (the slope fitted on
// the training rows, the held-out rows predicted; against no term).
double pair_cv(const PairFamily& F, size_t j, const std::vector<double>& resid, const std::vector<double>& w,
               const Folds& f) {
  int K = 0;
  for (const auto& r : F.rows)
    for (int i : r) K = std::max(K, f.fold[i] + 1);
  std::vector<double> sxr(K, 0.0), sxx(K, 0.0);
  double txr = 0, txx = 0;
  const double* pj = F.p.data() + j * F.U;
  for (size_t u = 0; u < F.U; ++u)
    for (int i : F.rows[u]) {
      const double x = (w.empty() ? 1.0 : w[i]) * pj[u];
      sxr[f.fold[i]] += x * resid[i], sxx[f.fold[i]] += x * x, txr += x * resid[i], txx += x * x;
    }
  double s0 = 0, s1 = 0;
  for (size_t u = 0; u < F.U; ++u)
    for (int i : F.rows[u]) {
      const int k = f.fold[i];
      const double den = txx - sxx[k], b = den > 0 ? (txr - sxr[k]) / den : 0.0;
      const double x = (w.empty() ? 1.0 : w[i]) * pj[u], e = resid[i] - b * x;
      s0 += resid[i] * resid[i], s1 += e * e;
    }
  return s0 > 0 ? 1 - s1 / s0 : 0.0;
}

CandidateResult screen_family(PairFamily& F, const std::vector<Candidate>& pc, bool tests,
                              const std::vector<double>& resid, const std::vector<double>& w, const Folds& f,
                              int permutations, std::uint64_t seed, double thr) {
  CandidateResult res;
  size_t best = 0;
  const double T = family_stat(F, F.a, &best);
  const Candidate& c = pc[F.pairs[best]];
  res.name = c.name;
  res.kind = "pair";
  res.dof = 1;
  res.stat = T;
  res.permuted = tests ? "between tests (pair family)" : "within tests (pair family)";
  res.probe = "product of the centred columns" + std::string(w.empty() ? "" : " scaled with dF/dmu") +
              " (family of " + std::to_string(F.pairs.size()) + " pairs)";
  res.cv_probe = res.probe;
  res.decision = "not significant";
  if (!std::isfinite(T)) return res;
  res.cv_reduction = pair_cv(F, best, resid, w, f);
  // Sequential permutation test of the family's maximum.
  size_t kmax = 1;
  for (const auto& g : F.members) kmax = std::max(kmax, g.size());
  const FastMod mod(kmax);
  Mt64 rng(seed);
  std::vector<double> ap = F.a;
  const double Tp = T - 1e-12 * std::max(1.0, std::abs(T));
  int ge = 0, b = 0, dec = 0;
  const int cap = std::max(1, permutations);
  size_t dummy = 0;
  // Batches of 25, 50, 100, ...: a family far from significance (the usual
  // case) is decided after 25 (its cost is one dot product per pair, row and
  // permutation, on 50,000 rows as much as a candidate's whole screen).
  for (int batch = 25; b < cap; batch = std::min(cap - b, 2 * batch)) {
    for (int k = 0; k < batch; ++k, ++b) {
      for (const auto& g : F.members)
        for (size_t m = g.size(); m > 1; --m) std::swap(ap[g[m - 1]], ap[g[mod(rng(), m)]]);
      if (family_stat(F, ap, &dummy) >= Tp) ++ge;
    }
    dec = sequential_decision(ge, b, thr);
    if (dec != 0) break;
  }
  permutation_decision(res, ge, b, dec, thr);
  return res;
}

}  // namespace

std::vector<Candidate> pair_candidates(const std::vector<Candidate>& cands) {
  std::vector<const Candidate*> cols;
  for (const auto& c : cands)
    if (c.kind == "column" && !c.categorical && c.confounded_with.empty() && !is_identity(c.name) &&
        cols.size() < kMaxPairColumns)
      cols.push_back(&c);
  std::vector<Candidate> out;
  for (size_t i = 0; i < cols.size(); ++i)
    for (size_t j = i + 1; j < cols.size(); ++j) {
      const Candidate &a = *cols[i], &b = *cols[j];
      Candidate p;
      p.name = a.name + "*" + b.name;
      p.kind = "pair";
      p.test_level = a.test_level && b.test_level;
      p.pair = {a.name, b.name};
      double ma = 0, mb = 0, na = 0, nb = 0;  // the means over the rows with a value
      for (double v : a.x)
        if (std::isfinite(v)) ma += v, na += 1;
      for (double v : b.x)
        if (std::isfinite(v)) mb += v, nb += 1;
      ma /= std::max(1.0, na), mb /= std::max(1.0, nb);
      p.x.resize(a.x.size());
      for (size_t r = 0; r < a.x.size(); ++r) p.x[r] = (a.x[r] - ma) * (b.x[r] - mb);
      out.push_back(std::move(p));
    }
  return out;
}

int pair_families(const std::vector<Candidate>& pairs) {
  bool rows = false;
  for (const auto& p : pairs) rows = rows || !p.test_level;
  return static_cast<int>(rows) + (pairs.empty() ? 0 : 1);
}

std::vector<CandidateResult> rank_pairs(const std::vector<Candidate>& pairs, const std::vector<Candidate>& cands,
                                        const std::vector<double>& resid,
                                        const Folds& f, int permutations, std::uint64_t seed, double thr,
                                        const ScreenContext* ctx) {
  std::vector<CandidateResult> out;
  const std::vector<double> none;
  const std::vector<double>& w = ctx && ctx->mu_weight.size() == resid.size() ? ctx->mu_weight : none;
  for (int tests = 0; tests < 2; ++tests) {
    PairFamily F;
    for (size_t j = 0; j < pairs.size(); ++j)
      if (tests || !pairs[j].test_level) F.pairs.push_back(j);
    if (F.pairs.empty()) continue;
    units(F, tests, resid, f);
    fill(F, pairs, cands, resid, w);
    out.push_back(screen_family(F, pairs, tests, resid, w, f, permutations, seed + 7919ULL * (1 + tests), thr));
  }
  return out;
}

}  // namespace drawbend::loop
