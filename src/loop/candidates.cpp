// Folds, candidates and their ranking; see candidates.hpp.
#include "loop/candidates.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>

#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/special_functions/beta.hpp>

#include "core/csv.hpp"
#include "loop/effects.hpp"
#include "loop/fast_mod.hpp"

namespace drawbend::loop {

Folds make_folds(const Design& d, const std::string& mode_in, int k) {
  Folds f;
  f.k = k;
  const auto& rows = d.data->rows;
  const size_t n = rows.size();
  std::map<std::string, int> test_ix;
  f.block.resize(n);
  f.test.resize(n);
  for (size_t i = 0; i < n; ++i) {
    f.block[i] = d.rows[i].rotating ? 0 : 1 + d.rows[i].cell;
    f.test[i] = test_ix.emplace(rows[i].test_id, static_cast<int>(test_ix.size())).first->second;
  }
  // tests per (block, pin), in order of first appearance
  std::map<std::pair<int, int>, std::vector<int>> bp;
  std::vector<int> seen(test_ix.size(), 0);
  for (size_t i = 0; i < n; ++i)
    if (!seen[f.test[i]]++) bp[{f.block[i], d.rows[i].pin}].push_back(f.test[i]);
  std::string mode = mode_in;
  if (mode == "auto") {
    mode = "test";
    for (const auto& [key, tests] : bp)
      if (tests.size() < 2) mode = "bt-block";
  }
  f.mode = mode;
  f.fold.assign(n, 0);
  if (mode == "test") {
    std::vector<int> tf(test_ix.size(), 0);
    for (const auto& [key, tests] : bp)
      for (size_t j = 0; j < tests.size(); ++j) tf[tests[j]] = static_cast<int>((j + key.second) % k);
    for (size_t i = 0; i < n; ++i) f.fold[i] = tf[f.test[i]];
  } else if (mode == "bt-block") {
    std::map<int, std::vector<int>> by_test;
    for (size_t i = 0; i < n; ++i) by_test[f.test[i]].push_back(static_cast<int>(i));
    for (auto& [t, ix] : by_test) {
      std::stable_sort(ix.begin(), ix.end(), [&](int a, int b) { return d.rows[a].fback < d.rows[b].fback; });
      for (size_t j = 0; j < ix.size(); ++j) f.fold[ix[j]] = static_cast<int>(j * k / ix.size());
    }
  } else {
    throw std::invalid_argument("unknown cross-validation mode '" + mode_in + "' (auto, test, bt-block)");
  }
  return f;
}

CvResult cross_validate(const Design& d, const ModelSpec& spec, const Folds& f) {
  const size_t n = d.rows.size();
  CvResult r;
  r.pred.assign(n, std::nan(""));
  r.resid.assign(n, std::nan(""));
  for (int k = 0; k < f.k; ++k) {
    std::vector<int> train;
    for (size_t i = 0; i < n; ++i)
      if (f.fold[i] != k) train.push_back(static_cast<int>(i));
    if (train.size() == n) continue;
    const Fit fit = fit_model(d, spec, train);
    for (size_t i = 0; i < n; ++i)
      if (f.fold[i] == k) {
        r.pred[i] = predict(d, fit, static_cast<int>(i));
        r.resid[i] = d.rows[i].y - r.pred[i];
      }
  }
  double ss = 0;
  for (double e : r.resid)
    if (std::isfinite(e)) {
      ss += e * e;
      r.max_abs = std::max(r.max_abs, std::abs(e));
      ++r.n;
    }
  r.rms = r.n ? std::sqrt(ss / r.n) : std::nan("");
  return r;
}

std::vector<Candidate> make_candidates(const Design& d, const std::vector<double>& pred) {
  const auto& data = *d.data;
  const size_t n = data.rows.size();
  std::vector<Candidate> c;
  auto numeric = [&](const std::string& name, const std::string& kind, auto get) {
    Candidate k{name, kind, false, false, std::vector<double>(n), {}};
    for (size_t i = 0; i < n; ++i) k.x[i] = get(i);
    c.push_back(std::move(k));
  };
  auto categorical = [&](const std::string& name, const std::string& kind, auto get) {
    Candidate k{name, kind, true, false, std::vector<double>(n), {}};
    std::map<std::string, int> ix;
    for (size_t i = 0; i < n; ++i) {
      auto [it, fresh] = ix.emplace(get(i), static_cast<int>(k.levels.size()));
      if (fresh) k.levels.push_back(it->first);
      k.x[i] = it->second;
    }
    c.push_back(std::move(k));
  };
  const auto& R = data.rows;
  // Columns beyond the model's inputs.
  if (data.has_sliding) numeric("sliding_distance_mm", "column", [&](size_t i) { return R[i].sliding_mm; });
  if (data.has_time) numeric("time_s", "column", [&](size_t i) { return R[i].time_s; });
  for (size_t e = 0; e < data.extra_columns.size(); ++e) {
    bool num = true;
    for (const auto& s : R) {
      try {
        size_t used = 0;
        const double v = std::stod(s.extra[e], &used);
        if (used != s.extra[e].size() || !std::isfinite(v)) num = false;
      } catch (...) {
        if (!s.extra[e].empty()) num = false;
      }
    }
    if (num)
      numeric(data.extra_columns[e], "column", [&](size_t i) {
        return R[i].extra[e].empty() ? std::nan("") : std::stod(R[i].extra[e]);
      });
    else
      categorical(data.extra_columns[e], "column", [&](size_t i) { return R[i].extra[e]; });
  }
  // Derived quantities.
  numeric("avg_pressure_MPa", "derived", [&](size_t i) {  // Eq. (2.2) at the predicted outlet force
    return (R[i].back_tension_N + pred[i]) / (R[i].pin_d_mm * kStripWidthMm);
  });
  numeric("inv_R_per_mm", "derived", [&](size_t i) { return 2.0 / R[i].pin_d_mm; });
  // The model's inputs.
  numeric("pin_diameter_mm", "input", [&](size_t i) { return R[i].pin_d_mm; });
  numeric("back_tension_N", "input", [&](size_t i) { return R[i].back_tension_N; });
  numeric("speed_mm_s", "input", [&](size_t i) { return R[i].speed_mm_s; });
  numeric("direction_deg", "input", [&](size_t i) { return R[i].direction_deg; });
  categorical("lubricant", "input", [&](size_t i) { return R[i].lubricant; });
  // Group identities.
  categorical("pin", "group", [&](size_t i) { return fmt(R[i].pin_d_mm) + " mm"; });
  categorical("test_id", "group", [&](size_t i) { return R[i].test_id; });
  // Level of each candidate: constant within every test?
  std::map<std::string, std::vector<size_t>> by_test;
  for (size_t i = 0; i < n; ++i) by_test[R[i].test_id].push_back(i);
  for (auto& k : c) {
    k.test_level = true;
    for (const auto& [t, ix] : by_test)
      for (size_t j : ix)
        if (!(k.x[j] == k.x[ix[0]] || (std::isnan(k.x[j]) && std::isnan(k.x[ix[0]])))) k.test_level = false;
  }
  return c;
}

namespace {

// A probe on one candidate: the rows it uses and its features.
struct Probe {
  std::vector<int> rows;
  bool categorical = false;
  int dof = 0;
};

// Explained sum of squares of the block-centred residual rc by x over units.
// A unit is a test (test-level candidates: x constant within it) or a row;
// ur[u] = sum of rc over the unit's rows, un[u] its row count, ub[u] its block.
// Numeric: features x and x^2 centred per block (least squares); categorical:
// one mean per (block, level).  With rc block-centred, sum(f_c rc) = sum(f rc).
struct UnitProbe {
  std::vector<double> ur, un;
  std::vector<int> ub;
  int nblocks = 0, nlev = 0, dof = 1;
  bool categorical = false;
  mutable std::vector<double> s1, s2, sn;
  double ess(const std::vector<double>& xu) const {
    if (categorical) {
      s1.assign(static_cast<size_t>(nblocks) * nlev, 0.0);
      sn.assign(s1.size(), 0.0);
      for (size_t u = 0; u < ur.size(); ++u) {
        const size_t k = static_cast<size_t>(ub[u]) * nlev + static_cast<size_t>(xu[u]);
        s1[k] += ur[u], sn[k] += un[u];
      }
      double e = 0;
      for (size_t k = 0; k < s1.size(); ++k)
        if (sn[k] > 0) e += s1[k] * s1[k] / sn[k];
      return e;
    }
    const Gram A = gram(xu);
    double b1 = 0, b2 = 0;
    for (size_t u = 0; u < ur.size(); ++u) b1 += xu[u] * ur[u], b2 += xu[u] * xu[u] * ur[u];
    return solve(A, b1, b2);
  }
  /// The block-centred Gram matrix of (x, x^2) over the units.
  struct Gram {
    double A11, A12, A22;
  };
  Gram gram(const std::vector<double>& xu) const {
    s1.assign(nblocks, 0.0), s2.assign(nblocks, 0.0), sn.assign(nblocks, 0.0);
    double q11 = 0, q12 = 0, q22 = 0;
    for (size_t u = 0; u < ur.size(); ++u) {
      const double x = xu[u], x2 = x * x, n = un[u];
      q11 += n * x2, q12 += n * x2 * x, q22 += n * x2 * x2;
      s1[ub[u]] += n * x, s2[ub[u]] += n * x2, sn[ub[u]] += n;
    }
    Gram A{q11, q12, q22};
    for (int k = 0; k < nblocks; ++k)
      if (sn[k] > 0)
        A.A11 -= s1[k] * s1[k] / sn[k], A.A12 -= s1[k] * s2[k] / sn[k], A.A22 -= s2[k] * s2[k] / sn[k];
    return A;
  }
  /// The explained sum of squares b' A^-1 b (1 or 2 regressors).
  double solve(const Gram& A, double b1, double b2) const {
    if (dof == 1) return A.A11 > 1e-12 ? b1 * b1 / A.A11 : 0.0;
    const double det = A.A11 * A.A22 - A.A12 * A.A12;
    if (det <= 1e-12 * std::max(1.0, A.A11 * A.A22)) return A.A11 > 1e-12 ? b1 * b1 / A.A11 : 0.0;
    const double c1 = (A.A22 * b1 - A.A12 * b2) / det, c2 = (A.A11 * b2 - A.A12 * b1) / det;
    return c1 * b1 + c2 * b2;
  }
  /// ess() of a permutation of xu that moves x only among units of one block
  /// with equal counts: A is then unchanged (same sums, up to rounding, far
  /// inside the 1e-12 tie margin of the test), so only b is recomputed.
  double ess_permuted(const std::vector<double>& xp, const Gram& A) const {
    double b1 = 0, b2 = 0;
    if (dof == 1)
      for (size_t u = 0; u < ur.size(); ++u) b1 += xp[u] * ur[u];
    else
      for (size_t u = 0; u < ur.size(); ++u) b1 += xp[u] * ur[u], b2 += xp[u] * xp[u] * ur[u];
    return solve(A, b1, b2);
  }
};

// Cross-validated fractional reduction of the residual SSE by the probe.
double probe_cv(const Probe& p, const std::vector<double>& x, const std::vector<double>& r, const Folds& f) {
  double sse0 = 0, sse1 = 0;
  for (int k = 0; k < f.k; ++k) {
    std::map<int, std::array<double, 4>> bm;
    std::map<std::pair<int, int>, std::pair<double, int>> lm;
    for (int i : p.rows)
      if (f.fold[i] != k) {
        auto& a = bm[f.block[i]];
        a[0] += r[i], a[1] += x[i], a[2] += x[i] * x[i], a[3] += 1;
        if (p.categorical) {
          auto& l = lm[{f.block[i], static_cast<int>(x[i])}];
          l.first += r[i], l.second++;
        }
      }
    double A11 = 0, A12 = 0, A22 = 0, b1 = 0, b2 = 0;
    if (!p.categorical)
      for (int i : p.rows)
        if (f.fold[i] != k) {
          const auto& a = bm[f.block[i]];
          const double rc = r[i] - a[0] / a[3], f1 = x[i] - a[1] / a[3], f2 = x[i] * x[i] - a[2] / a[3];
          A11 += f1 * f1, b1 += f1 * rc, A12 += f1 * f2, A22 += f2 * f2, b2 += f2 * rc;
        }
    double c1 = 0, c2 = 0;
    if (!p.categorical) {
      const double det = A11 * A22 - A12 * A12;
      if (p.dof == 2 && det > 1e-12 * std::max(1.0, A11 * A22)) {
        c1 = (A22 * b1 - A12 * b2) / det;
        c2 = (A11 * b2 - A12 * b1) / det;
      } else if (A11 > 1e-12) {
        c1 = b1 / A11;
      }
    }
    for (int i : p.rows)
      if (f.fold[i] == k) {
        auto it = bm.find(f.block[i]);
        if (it == bm.end()) continue;
        const auto& a = it->second;
        const double base = a[0] / a[3];
        double pr = base;
        if (p.categorical) {
          auto l = lm.find({f.block[i], static_cast<int>(x[i])});
          if (l != lm.end()) pr = l->second.first / l->second.second;
        } else {
          pr = base + c1 * (x[i] - a[1] / a[3]) + c2 * (x[i] * x[i] - a[2] / a[3]);
        }
        sse0 += (r[i] - base) * (r[i] - base);
        sse1 += (r[i] - pr) * (r[i] - pr);
      }
  }
  return sse0 > 0 ? 1 - sse1 / sse0 : 0.0;
}

}  // namespace

int sequential_decision(int k, int b, double thr, double conf) {
  if (b <= 0) return 0;
  using boost::math::ibeta_inv;
  const double lo = k > 0 ? ibeta_inv(static_cast<double>(k), static_cast<double>(b - k + 1), conf) : 0.0;
  const double hi = k < b ? ibeta_inv(static_cast<double>(k + 1), static_cast<double>(b - k), 1 - conf) : 1.0;
  if (hi <= thr) return 1;
  if (lo > thr) return -1;
  return 0;
}

std::vector<CandidateResult> rank_candidates(const std::vector<Candidate>& cands, const std::vector<double>& resid,
                                             const Folds& f, int permutations, std::uint64_t seed, double alpha) {
  std::vector<CandidateResult> out;
  const double thr = alpha / std::max<size_t>(1, cands.size());
  const size_t n = resid.size();
  int nblocks = 0;
  for (int b : f.block) nblocks = std::max(nblocks, b + 1);
  for (size_t ci = 0; ci < cands.size(); ++ci) {
    const Candidate& c = cands[ci];
    Probe p;
    p.categorical = c.categorical;
    std::vector<double> x = c.x;
    std::set<double> distinct;
    for (size_t i = 0; i < n; ++i)
      if (std::isfinite(x[i]) && std::isfinite(resid[i])) {
        p.rows.push_back(static_cast<int>(i));
        distinct.insert(x[i]);
      }
    CandidateResult res;
    res.name = c.name;
    res.kind = c.kind;
    res.permuted = c.test_level ? "between tests" : "within tests";
    res.decision = "not significant";
    if (distinct.size() < 2) {
      res.p_value = 1;
      out.push_back(res);
      continue;
    }
    // Block-centred residuals over the probe rows.
    std::vector<double> bs(nblocks, 0.0), bn(nblocks, 0.0), rc(n, 0.0);
    for (int i : p.rows) bs[f.block[i]] += resid[i], bn[f.block[i]] += 1;
    for (int i : p.rows) rc[i] = resid[i] - bs[f.block[i]] / bn[f.block[i]];
    if (is_identity(c.name)) {  // random effect: one-way ANOVA of tests within blocks
      std::map<int, std::pair<double, double>> tsum;
      std::set<int> blocks;
      double sst = 0;
      for (int i : p.rows) {
        auto& t = tsum[f.test[i]];
        t.first += rc[i], t.second += 1;
        sst += rc[i] * rc[i];
        blocks.insert(f.block[i]);
      }
      double ssb = 0;
      for (auto& [t, v] : tsum) ssb += v.first * v.first / v.second;
      const double db = static_cast<double>(tsum.size()) - blocks.size(), dw = p.rows.size() - tsum.size();
      res.permuted = "random effect (F test, not permuted)";
      res.dof = static_cast<int>(db);
      res.stat = ssb;
      if (db > 0 && dw > 0 && sst - ssb > 0) {
        const double msb = ssb / db, msw = (sst - ssb) / dw, F = msb / msw;
        res.p_value = boost::math::cdf(boost::math::complement(boost::math::fisher_f_distribution<double>(db, dw), F));
        const double n0 = static_cast<double>(p.rows.size()) / tsum.size();
        res.sd_between = std::sqrt(std::max(0.0, (msb - msw) / n0));
      }
      res.significant = res.p_value <= thr;
      res.decision = res.significant ? "significant (between-test scatter)" : "not significant";
      out.push_back(res);
      continue;
    }
    if (!c.categorical) {  // standardise for conditioning
      double m = 0, q = 0;
      for (int i : p.rows) m += x[i];
      m /= p.rows.size();
      for (int i : p.rows) q += (x[i] - m) * (x[i] - m);
      const double sd = std::sqrt(q / p.rows.size());
      for (int i : p.rows) x[i] = sd > 0 ? (x[i] - m) / sd : 0;
      p.dof = distinct.size() >= 4 ? 2 : 1;
    } else {
      p.dof = static_cast<int>(distinct.size()) - 1;
    }
    res.dof = p.dof;
    res.cv_reduction = probe_cv(p, x, resid, f);
    // Units (tests or rows) and permutation groups (blocks or tests).
    UnitProbe up;
    up.nblocks = nblocks;
    up.dof = p.dof;
    up.categorical = c.categorical;
    if (c.categorical)
      for (int i : p.rows) up.nlev = std::max(up.nlev, static_cast<int>(x[i]) + 1);
    std::vector<double> xu;
    std::vector<std::vector<int>> groups;
    {
      std::map<int, int> unit_ix, group_ix;
      for (int i : p.rows) {
        const int key = c.test_level ? f.test[i] : i;
        auto [it, fresh] = unit_ix.emplace(key, static_cast<int>(xu.size()));
        if (fresh) {
          xu.push_back(x[i]);
          up.ur.push_back(0), up.un.push_back(0), up.ub.push_back(f.block[i]);
          const int g = c.test_level ? f.block[i] : f.test[i];
          auto [gt, gfresh] = group_ix.emplace(g, static_cast<int>(groups.size()));
          if (gfresh) groups.push_back({});
          groups[gt->second].push_back(it->second);
        }
        up.ur[it->second] += rc[i], up.un[it->second] += 1;
      }
    }
    res.stat = up.ess(xu);
    std::mt19937_64 rng(seed + 7919 * ci);
    int ge = 0, b = 0, dec = 0;
    std::vector<double> xp = xu;
    // Permutations that keep each group in one block with equal unit counts
    // leave the Gram matrix as it is: only x'r is recomputed per permutation.
    bool fixed_gram = !c.categorical;
    for (const auto& g : groups)
      for (int u : g) fixed_gram = fixed_gram && up.ub[u] == up.ub[g[0]] && up.un[u] == up.un[g[0]];
    const UnitProbe::Gram A = fixed_gram ? up.gram(xu) : UnitProbe::Gram{};
    const int cap = std::max(1, permutations);
    size_t kmax = 1;
    for (const auto& g : groups) kmax = std::max(kmax, g.size());
    const FastMod mod(kmax);  // mod(rng(), k) == rng() % k, without the division
    for (int batch = 100; b < cap; batch = std::min(cap - b, 2 * batch)) {
      for (int j = 0; j < batch; ++j, ++b) {
        for (const auto& g : groups)  // Fisher-Yates within the group
          for (size_t k = g.size(); k > 1; --k) std::swap(xp[g[k - 1]], xp[g[mod(rng(), k)]]);
        if ((fixed_gram ? up.ess_permuted(xp, A) : up.ess(xp)) >= res.stat * (1 - 1e-12)) ++ge;
      }
      dec = sequential_decision(ge, b, thr);
      if (dec != 0) break;
    }
    res.n_perm = b;
    res.p_value = (1.0 + ge) / (1.0 + b);
    res.significant = dec > 0 && res.cv_reduction > 0;
    res.decision = dec > 0 ? (res.cv_reduction > 0 ? "significant" : "significant, no held-out gain")
                           : dec < 0 ? "not significant" : "undecided";
    out.push_back(res);
  }
  std::stable_sort(out.begin(), out.end(), [](const CandidateResult& a, const CandidateResult& b) {
    if (a.significant != b.significant) return a.significant;
    if (a.significant) return a.cv_reduction > b.cv_reduction;
    return a.p_value < b.p_value;
  });
  return out;
}

}  // namespace drawbend::loop
