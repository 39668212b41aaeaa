// The screen: every candidate probed by a family of probes, one permutation
// test of the family's maximum; see candidates.hpp.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/special_functions/beta.hpp>

#include "loop/candidates.hpp"
#include "loop/effects.hpp"
#include "loop/screen_candidate.hpp"

namespace drawbend::loop {

namespace {

using detail::CandidateScreen;
using detail::ProbeDef;
using detail::probe_z;

// The distinct values of x over the rows, ascending.
std::vector<double> distinct_values(const std::vector<double>& x, const std::vector<int>& rows) {
  std::vector<double> v;
  v.reserve(rows.size());
  for (int i : rows) v.push_back(x[i]);
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// Integer keys (test, block, group or row indices) of the rows to a slot
// each, -1 until set: a table over [min key, max key].  Without `keys` (null),
// the keys are the row indices themselves.
class DenseIndex {
 public:
  DenseIndex(const std::vector<int>* keys, const std::vector<int>& rows) {
    lo_ = rows.empty() ? 0 : keys ? (*keys)[rows[0]] : rows[0];
    int hi = lo_;
    for (int i : rows) lo_ = std::min(lo_, keys ? (*keys)[i] : i), hi = std::max(hi, keys ? (*keys)[i] : i);
    slot_.assign(static_cast<size_t>(static_cast<long long>(hi) - lo_ + 1), -1);
  }
  int& operator[](int key) { return slot_[static_cast<size_t>(static_cast<long long>(key) - lo_)]; }

 private:
  int lo_ = 0;
  std::vector<int> slot_;
};

}  // namespace

namespace detail {

size_t count_distinct(const std::vector<int>& keys, const std::vector<int>& rows) {
  DenseIndex seen(&keys, rows);
  size_t k = 0;
  for (int i : rows) {
    int& s = seen[keys[i]];
    if (s < 0) s = 0, ++k;
  }
  return k;
}

}  // namespace detail

int sequential_decision(int k, int b, double thr, double conf) {
  if (b <= 0) return 0;
  using boost::math::ibeta_inv;
  const double lo = k > 0 ? ibeta_inv(static_cast<double>(k), static_cast<double>(b - k + 1), conf) : 0.0;
  const double hi = k < b ? ibeta_inv(static_cast<double>(k + 1), static_cast<double>(b - k), 1 - conf) : 1.0;
  if (hi <= thr) return 1;
  if (lo > thr) return -1;
  return 0;
}

void permutation_decision(CandidateResult& res, int ge, int b, int dec, double thr) {
  res.n_perm = b;
  res.p_value = (1.0 + ge) / (1.0 + b);
  // At the cap with the interval still straddling the threshold, the Monte
  // Carlo p-value (1 + ge) / (1 + b), valid at any number of permutations,
  // decides: p <= thr is significant (a candidate at p 0.00125 against a
  // threshold of 0.00179 after 20000 permutations was left "undecided" and
  // never given a form, with a bending effect of 4.8 sd in the residual).
  const bool at_cap = dec == 0 && res.p_value <= thr;
  res.significant = (dec > 0 || at_cap) && res.cv_reduction > 0;
  res.decision = dec > 0 || at_cap
                     ? (res.cv_reduction > 0 ? (at_cap ? "significant (p at the permutation cap)" : "significant")
                                             : "significant, no held-out gain")
                     : dec < 0 ? "not significant" : "undecided";
}

namespace detail {

// The rows with a finite value and residual.  The distinct values, ascending
// (a sorted vector, not a std::set: one node per row was an allocation per row
// of every row-level column).
void CandidateScreen::select_rows() {
  for (size_t i = 0; i < n; ++i)
    if (std::isfinite(c.x[i]) && std::isfinite(resid[i])) rows.push_back(static_cast<int>(i));
  distinct = distinct_values(c.x, rows);
}

// Random effect: one-way ANOVA of tests within blocks.
void CandidateScreen::random_effect(CandidateResult& res) const {
  std::vector<double> bs(nblocks, 0.0), bn(nblocks, 0.0), rc(n, 0.0);
  for (int i : rows) bs[f.block[i]] += resid[i], bn[f.block[i]] += 1;
  for (int i : rows) rc[i] = resid[i] - bs[f.block[i]] / bn[f.block[i]];
  std::map<int, std::pair<double, double>> tsum;
  std::set<int> blocks;
  double sst = 0;
  for (int i : rows) {
    auto& t = tsum[f.test[i]];
    t.first += rc[i], t.second += 1;
    sst += rc[i] * rc[i];
    blocks.insert(f.block[i]);
  }
  double ssb = 0;
  for (auto& [t, v] : tsum) ssb += v.first * v.first / v.second;
  const double db = static_cast<double>(tsum.size()) - blocks.size(), dw = rows.size() - tsum.size();
  res.permuted = "random effect (F test, not permuted)";
  res.dof = static_cast<int>(db);
  res.stat = ssb;
  if (db > 0 && dw > 0 && sst - ssb > 0) {
    const double msb = ssb / db, msw = (sst - ssb) / dw, F = msb / msw;
    res.p_value = boost::math::cdf(boost::math::complement(boost::math::fisher_f_distribution<double>(db, dw), F));
    const double n0 = static_cast<double>(rows.size()) / tsum.size();
    res.sd_between = std::sqrt(std::max(0.0, (msb - msw) / n0));
  }
}

// Row values: z-score (numeric) and level index (categorical; numeric with
// at most kOwnLevelsMax distinct values: one level each; else quantile bins).
void CandidateScreen::row_values() {
  z.assign(n, 0.0);
  lv.assign(n, 0);
  if (c.categorical) {
    for (int i : rows) lv[i] = static_cast<int>(c.x[i]), nlev = std::max(nlev, lv[i] + 1);
  } else {
    double m = 0, q = 0;
    for (int i : rows) m += c.x[i];
    m /= rows.size();
    for (int i : rows) q += (c.x[i] - m) * (c.x[i] - m);
    const double sd = std::sqrt(q / rows.size());
    for (int i : rows) z[i] = sd > 0 ? (c.x[i] - m) / sd : 0;
    const std::vector<double>& dv = distinct;
    if (dv.size() <= kOwnLevelsMax) {
      for (int i : rows) lv[i] = static_cast<int>(std::lower_bound(dv.begin(), dv.end(), c.x[i]) - dv.begin());
      nlev = static_cast<int>(dv.size());
    } else {
      std::vector<double> xs;
      for (int i : rows) xs.push_back(c.x[i]);
      std::sort(xs.begin(), xs.end());
      std::vector<double> cut;
      // Quantile bins: 8 when the variable has enough units (tests for a
      // test-level variable) for a periodic or bump shape, else 5.
      const size_t units = c.test_level ? count_distinct(f.test, rows) : rows.size();
      const int nb = units >= 80 ? 8 : 5;
      for (int b = 1; b < nb; ++b) cut.push_back(xs[xs.size() * b / nb]);
      cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
      for (int i : rows) lv[i] = static_cast<int>(std::upper_bound(cut.begin(), cut.end(), c.x[i]) - cut.begin());
      nlev = static_cast<int>(cut.size()) + 1;
      for (double v : cut) cutz.push_back(sd > 0 ? (v - m) / sd : 0);
    }
  }
}

// Units (tests of a test-level variable, else rows) and permutation groups
// (blocks, else tests), numbered in order of first appearance (dense tables
// of the keys, not std::maps: a node per row of a row-level column).
void CandidateScreen::units_and_groups() {
  unit_of.assign(n, -1);
  DenseIndex unit_ix(c.test_level ? &f.test : nullptr, rows), group_ix(c.test_level ? &f.block : &f.test, rows);
  for (int i : rows) {
    const int key = c.test_level ? f.test[i] : i;
    int& ui = unit_ix[key];
    if (ui < 0) {
      ui = static_cast<int>(xz.size());
      xz.push_back(z[i]), xl.push_back(lv[i]), unit_block.push_back(f.block[i]);
      int& gi = group_ix[c.test_level ? f.block[i] : f.test[i]];
      if (gi < 0) gi = static_cast<int>(groups.size()), groups.push_back({});
      groups[gi].push_back(ui);
    }
    unit_of[i] = ui;
  }
  U = xz.size();
}

// A row-level column whose values also differ between the tests of a block
// (a travel, a count or a temperature that accumulates over the tests) is
// permuted on both levels: its test means between the tests of a block, and
// its deviations from them within each test, x* = mean(test pi(t)) + (x -
// mean(test t)) of a row permuted within t.  Permuted within tests alone,
// the between-test part, often the bulk of such an effect, was never tested.
// Numeric columns with quantile bins only (the bins of x* are recomputed).
// ug: the unit's test (permutation group); gz: the test's mean z; bgroups:
// the tests of each block.
void CandidateScreen::two_level_groups(CandidateResult& res) {
  two_level = !c.test_level && !c.categorical && c.kind == "column" && !cutz.empty();
  ug.assign(U, 0), tp.assign(groups.size(), 0);
  gz.assign(groups.size(), 0.0);
  if (two_level) {
    std::map<int, int> bix;
    for (size_t g = 0; g < groups.size(); ++g) {
      for (int u : groups[g]) ug[u] = static_cast<int>(g), gz[g] += xz[u];
      gz[g] /= groups[g].size();
      tp[g] = static_cast<int>(g);
      auto [it, fresh] = bix.emplace(unit_block[groups[g][0]], static_cast<int>(bgroups.size()));
      if (fresh) bgroups.push_back({});
      bgroups[it->second].push_back(static_cast<int>(g));
    }
  }
  if (two_level) res.permuted = "within and between tests";
}

// Held-out gain: the best of the probes (a probe of the wrong shape must
// not hide a variable), and of each per-input probe's strongest one-group
// sub-probe.
void CandidateScreen::held_out_gain(CandidateResult& res) const {
  std::vector<double> wrow(n, 1.0);
  if (weighted) wrow = ctx->mu_weight;
  res.cv_reduction = -INFINITY;
  for (size_t j = 0; j < probes.size(); ++j) {
    const ProbeDef& p = probes[j];
    if (p.dof[0] > 0) {
      const double cv = probe_cv(p, rows, z, lv, wrow, p.rpre.empty() ? resid : p.rpre, f);
      if (cv > res.cv_reduction) res.cv_reduction = cv, res.cv_probe = p.label, res.cv_probe_input = p.input;
    }
    if (!p.cells) continue;
    int kb = 0;
    double zb = -INFINITY;
    for (int k = 1; k < p.nsub(); ++k)
      if (p.dof[k] > 0) {
        const double v = probe_z(p, k, vals[off[j] + k]);
        if (v > zb) zb = v, kb = k;
      }
    if (kb > 0) {
      const double cv = probe_cv(p, rows, z, lv, wrow, resid, f, kb - 1);
      if (cv > res.cv_reduction) res.cv_reduction = cv, res.cv_probe = p.sub_label(kb), res.cv_probe_input = p.input;
    }
  }
}

}  // namespace detail

namespace {

// One candidate's screen, the recipe: its rows; a random effect's F test; its
// unit values and permutation groups; the probe family; the pilot calibration;
// the observed statistic, the held-out gain and the permutation test.
CandidateResult screen_candidate(const Candidate& c, size_t ci, const std::vector<double>& resid, const Folds& f,
                                 const ScreenContext* ctx, int nblocks, int permutations, std::uint64_t seed,
                                 double thr) {
  CandidateResult res;
  res.name = c.name;
  res.kind = c.kind;
  res.permuted = c.test_level ? "between tests" : "within tests";  // two-level: set below
  res.decision = "not significant";
  CandidateScreen s(c, resid, f, ctx, nblocks);
  s.select_rows();
  if (s.distinct.size() < 2) {
    res.p_value = 1;
    return res;
  }
  if (is_identity(c.name)) {  // random effect: one-way ANOVA of tests within blocks
    s.random_effect(res);
    res.significant = res.p_value <= thr;
    res.decision = res.significant ? "significant (between-test scatter)" : "not significant";
    return res;
  }
  s.row_values();
  s.units_and_groups();
  s.two_level_groups(res);
  s.build_family();
  s.fixed_counts();
  s.reachable_cells();
  res.dof = s.dof_max();
  if (s.probes.empty()) {
    res.p_value = 1;
    return res;
  }
  s.set_offsets();
  s.flat_groups();
  s.calibrate(seed, ci);
  if (s.probes.empty()) {
    res.p_value = 1;
    return res;
  }
  const double T = s.observed(res);
  s.held_out_gain(res);
  s.permutation_test(res, T, seed, ci, permutations, thr);
  return res;
}

}  // namespace

std::vector<CandidateResult> rank_candidates(const std::vector<Candidate>& cands, const std::vector<double>& resid,
                                             const Folds& f, int permutations, std::uint64_t seed, double alpha,
                                             const ScreenContext* ctx, const std::vector<Candidate>* pairs) {
  // One result per candidate, in the candidates' order whatever thread screens
  // it (each candidate has its own random streams): the same for any count.
  std::vector<CandidateResult> out(cands.size());
  // Candidates with the same information: one test each group (screen_same.cpp).
  const std::vector<int> leader = same_information(cands, resid);
  size_t tests = 0;
  for (size_t ci = 0; ci < cands.size(); ++ci) tests += leader[ci] == static_cast<int>(ci);
  const int nfam = pairs ? pair_families(*pairs) : 0;  // each pair family counts as one candidate
  const double thr = alpha / std::max<size_t>(1, tests + nfam);
  int nblocks = 0;
  for (int b : f.block) nblocks = std::max(nblocks, b + 1);
  const int nth = ctx ? std::max(1, ctx->threads) : 1;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nth) if (nth > 1 && cands.size() > 1)
  for (size_t ci = 0; ci < cands.size(); ++ci)
    if (leader[ci] == static_cast<int>(ci))
      out[ci] = screen_candidate(cands[ci], ci, resid, f, ctx, nblocks, permutations, seed, thr);
  for (size_t ci = 0; ci < cands.size(); ++ci) {
    const size_t l = static_cast<size_t>(leader[ci]);
    if (l == ci) continue;
    out[ci] = out[l];
    out[ci].name = cands[ci].name;
    out[ci].kind = cands[ci].kind;
    out[ci].same_as = cands[l].name;
  }
  if (nfam > 0)  // their own streams, after every candidate's (screen_pairs.cpp)
    for (auto& r : rank_pairs(*pairs, cands, resid, f, permutations, seed + 7919ULL * cands.size(), thr, ctx))
      out.push_back(std::move(r));
  std::stable_sort(out.begin(), out.end(), [](const CandidateResult& a, const CandidateResult& b) {
    if (a.significant != b.significant) return a.significant;
    if (a.significant) return a.cv_reduction > b.cv_reduction;
    return a.p_value < b.p_value;
  });
  return out;
}

}  // namespace drawbend::loop
