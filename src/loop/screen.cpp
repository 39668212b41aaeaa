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
#include "loop/fast_mod.hpp"
#include "loop/mt64.hpp"
#include "loop/screen_probe.hpp"

namespace drawbend::loop {

namespace {

using detail::kLanes;
using detail::ProbeDef;
using detail::Shape;
using detail::centred_by;
using detail::probe_z;

// Pilot permutations per candidate for the probes' calibration scales.
constexpr int kPilot = 200;

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

// How many distinct values the integer keys take over the rows.
size_t count_distinct(const std::vector<int>& keys, const std::vector<int>& rows) {
  DenseIndex seen(&keys, rows);
  size_t k = 0;
  for (int i : rows) {
    int& s = seen[keys[i]];
    if (s < 0) s = 0, ++k;
  }
  return k;
}

// The names by which a candidate is itself one of the model's inputs.
bool same_input(const std::string& cand, const std::string& input) {
  if (input == "pin") return cand == "pin" || cand == "pin_diameter_mm" || cand == "inv_R_per_mm";
  return cand == input;
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
                                             const Folds& f, int permutations, std::uint64_t seed, double alpha,
                                             const ScreenContext* ctx) {
  // One result per candidate, in the candidates' order whatever thread screens
  // it (each candidate has its own random streams): the same for any count.
  std::vector<CandidateResult> out(cands.size());
  const double thr = alpha / std::max<size_t>(1, cands.size());
  const size_t n = resid.size();
  int nblocks = 0;
  for (int b : f.block) nblocks = std::max(nblocks, b + 1);
  const bool weighted = ctx && ctx->mu_weight.size() == n;
  const int nth = ctx ? std::max(1, ctx->threads) : 1;
  const bool pooled_inputs = ctx && ctx->pooled_inputs;
#pragma omp parallel for schedule(dynamic, 1) num_threads(nth) if (nth > 1 && cands.size() > 1)
  for (size_t ci = 0; ci < cands.size(); ++ci) {
    const Candidate& c = cands[ci];
    std::vector<int> rows;
    for (size_t i = 0; i < n; ++i)
      if (std::isfinite(c.x[i]) && std::isfinite(resid[i])) rows.push_back(static_cast<int>(i));
    // The distinct values, ascending (a sorted vector, not a std::set: one node
    // per row was an allocation per row of every row-level column).
    const std::vector<double> distinct = distinct_values(c.x, rows);
    CandidateResult res;
    res.name = c.name;
    res.kind = c.kind;
    res.permuted = c.test_level ? "between tests" : "within tests";  // two-level: set below
    res.decision = "not significant";
    if (distinct.size() < 2) {
      res.p_value = 1;
      out[ci] = std::move(res);
      continue;
    }
    if (is_identity(c.name)) {  // random effect: one-way ANOVA of tests within blocks
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
      res.significant = res.p_value <= thr;
      res.decision = res.significant ? "significant (between-test scatter)" : "not significant";
      out[ci] = std::move(res);
      continue;
    }
    // Row values: z-score (numeric) and level index (categorical; numeric with
    // at most 8 distinct values: one level each; else 5 quantile bins).
    std::vector<double> z(n, 0.0);
    std::vector<int> lv(n, 0);
    int nlev = 1;
    std::vector<double> cutz;  // quantile-bin edges on the z scale (numeric with more than 8 values)
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
      if (dv.size() <= 8) {
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
    // Units and permutation groups.
    std::vector<int> unit_of(n, -1), unit_block;
    std::vector<std::vector<int>> groups;
    std::vector<double> xz;
    std::vector<int> xl;
    {
      // Units and groups numbered in order of first appearance (dense tables
      // of the keys, not std::maps: a node per row of a row-level column).
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
    }
    const size_t U = xz.size();
    // A row-level column whose values also differ between the tests of a block
    // (a travel, a count or a temperature that accumulates over the tests) is
    // permuted on both levels: its test means between the tests of a block, and
    // its deviations from them within each test, x* = mean(test pi(t)) + (x -
    // mean(test t)) of a row permuted within t.  Permuted within tests alone,
    // the between-test part, often the bulk of such an effect, was never tested.
    // Numeric columns with quantile bins only (the bins of x* are recomputed).
    // ug: the unit's test (permutation group); gz: the test's mean z; bgroups:
    // the tests of each block.
    const bool two_level = !c.test_level && !c.categorical && c.kind == "column" && !cutz.empty();
    std::vector<int> ug(U, 0), tp(groups.size(), 0);
    std::vector<double> gz(groups.size(), 0.0);
    std::vector<std::vector<int>> bgroups;
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
    // Lane j of a permuted pass: unit u takes unit p[u]'s value (p permutes
    // within tests); two-level, the test means are permuted as well (tp, drawn
    // from r after the within-test shuffle) and the bin recomputed.
    auto fill_unit_values = [&](const std::vector<int>& p, std::vector<double>& qz, std::vector<int>& ql, int j,
                                Mt64& r, const FastMod& mod) {
      if (!two_level) {
        for (size_t u = 0; u < U; ++u) qz[u * kLanes + j] = xz[p[u]], ql[u * kLanes + j] = xl[p[u]];
        return;
      }
      for (const auto& bg : bgroups)
        for (size_t k = bg.size(); k > 1; --k) std::swap(tp[bg[k - 1]], tp[bg[mod(r(), k)]]);
      for (size_t u = 0; u < U; ++u) {
        const double v = gz[tp[ug[u]]] + (xz[p[u]] - gz[ug[u]]);
        qz[u * kLanes + j] = v;
        ql[u * kLanes + j] = static_cast<int>(std::upper_bound(cutz.begin(), cutz.end(), v) - cutz.begin());
      }
    };
    // The probe family.
    std::vector<ProbeDef> probes;
    auto add = [&](Shape shape, const std::string& label, const std::vector<int>& row_group, int ngroups,
                   const std::string& input = "", bool pooled = false) {
      ProbeDef p;
      p.shape = shape;
      p.label = label;
      p.input = input;
      p.ngroups = ngroups;
      p.cells = !pooled && ctx && ctx->one_cell && !input.empty() && ngroups > 1 &&
                (shape == Shape::levels || shape == Shape::slopes);
      p.nlev = nlev;
      p.row_stratum.assign(n, 0);
      p.nstrata = pooled ? ngroups : nblocks * ngroups;
      for (int i : rows)
        p.row_stratum[i] = pooled ? row_group[i] : f.block[i] * ngroups + (row_group.empty() ? 0 : row_group[i]);
      const std::vector<double>& r0 = pooled ? (p.rpre = centred_by(f.block, nblocks, rows, resid)) : resid;
      std::vector<double> sm(p.nstrata, 0.0), sn(p.nstrata, 0.0);
      for (int i : rows) sm[p.row_stratum[i]] += r0[i], sn[p.row_stratum[i]] += 1;
      p.stratum.assign(U, 0);
      p.ur.assign(U, 0.0), p.urw.assign(U, 0.0), p.un.assign(U, 0.0), p.uw2.assign(U, 0.0);
      for (int i : rows) {
        const int s = p.row_stratum[i], u = unit_of[i];
        const double rc = r0[i] - sm[s] / sn[s], w = weighted ? ctx->mu_weight[i] : 1.0;
        p.stratum[u] = s;  // a test lies in one stratum (blocks and model inputs are constant within a test)
        p.ur[u] += rc, p.urw[u] += w * rc, p.un[u] += 1, p.uw2[u] += w * w;
        p.sst += rc * rc;
      }
      // degrees of freedom on the observed data (whole probe, then one per group)
      // per stratum with rows: the levels seen, and whether z takes two values or more
      const int S = p.nstrata;
      std::vector<int> nseen(S, 0), zvar(S, 0);
      std::vector<char> seen(static_cast<size_t>(S) * nlev, 0);
      std::vector<double> z0(S, 0.0);
      for (int i : rows) {
        const int s = p.row_stratum[i];
        if (!nseen[s]) z0[s] = z[i];
        else if (z[i] != z0[s]) zvar[s] = 1;
        char& sl = seen[static_cast<size_t>(s) * nlev + lv[i]];
        nseen[s] += !sl, sl = 1;
      }
      int dof = 0;
      if (shape == Shape::levels || shape == Shape::wlevels) {
        for (int s = 0; s < S; ++s) dof += nseen[s] ? nseen[s] - 1 + (shape == Shape::wlevels ? 1 : 0) : 0;
      } else if (shape == Shape::slopes)
        for (int s = 0; s < S; ++s) dof += zvar[s];
      else if (shape == Shape::quad)
        dof = distinct.size() >= 4 ? 2 : 1;
      else
        dof = 1;
      p.dof.assign(p.nsub(), 0);
      p.dof[0] = dof;
      if (p.cells) {
        std::vector<std::set<int>> lev_g(ngroups);
        for (int i : rows) lev_g[p.row_stratum[i] % ngroups].insert(lv[i]);
        for (int g = 0; g < ngroups; ++g) {
          if (shape == Shape::slopes) {
            for (int s = 0; s < S; ++s) p.dof[1 + g] = p.dof[1 + g] || (s % ngroups == g && zvar[s]);
          } else {
            p.dof[1 + g] = std::max(0, static_cast<int>(lev_g[g].size()) - 1);
          }
        }
      }
      p.scale.assign(p.nsub(), 1.0);
      p.kdof.assign(p.nsub(), 1.0);
      if (dof > 0 && p.sst > 0) probes.push_back(std::move(p));
    };
    const std::vector<int> none;
    if (c.categorical) add(Shape::levels, "levels", none, 1);
    else {
      add(Shape::quad, distinct.size() >= 4 ? "linear + quadratic" : "linear", none, 1);
      if (nlev > 2) add(Shape::levels, distinct.size() <= 8 ? "levels" : std::to_string(nlev) + " quantile bins", none, 1);
    }
    if (weighted) add(c.categorical ? Shape::wlevels : Shape::wslope, "scaled with dF/dmu", none, 1);
    if (weighted && !c.categorical && nlev > 2)  // a multiplicative effect of any shape
      add(Shape::wlevels, (distinct.size() <= 8 ? "levels" : std::to_string(nlev) + " quantile bins") +
                              std::string(" scaled with dF/dmu"), none, 1);
    if (ctx)
      for (const auto& [input, g] : ctx->modifiers) {
        if (same_input(c.name, input)) continue;
        int ng = 0;
        for (int i : rows) ng = std::max(ng, g[i] + 1);
        if (count_distinct(g, rows) < 2) continue;
        add(c.categorical || distinct.size() <= 8 ? Shape::levels : Shape::slopes, "per " + input, g, ng, input);
        if (!c.categorical && distinct.size() > 8) add(Shape::levels, "bins per " + input, g, ng, input);
        if (c.test_level && pooled_inputs)  // see centred_by
          add(c.categorical || distinct.size() <= 8 ? Shape::levels : Shape::slopes, "per " + input + ", pooled over cells",
              g, ng, input, true);
      }
    for (auto& p : probes) {  // levels: counts no permutation changes (see ProbeDef::fixed_counts)
      if (p.shape != Shape::levels || two_level) continue;
      bool fixed = true;
      for (const auto& g : groups)
        for (int u : g) fixed = fixed && p.stratum[u] == p.stratum[g[0]] && p.un[u] == p.un[g[0]];
      if (!fixed) continue;
      p.fixed_counts.assign(static_cast<size_t>(p.nstrata) * p.nlev, 0.0);
      for (size_t u = 0; u < U; ++u) p.fixed_counts[static_cast<size_t>(p.stratum[u]) * p.nlev + xl[u]] += p.un[u];
    }
    if (!two_level) {  // levels: the cells a permutation can reach (see ProbeDef::reach)
      std::vector<int> glev;  // the levels of one permutation group
      std::vector<char> has(static_cast<size_t>(nlev), 0);
      for (auto& p : probes) {
        if (p.shape != Shape::levels && p.shape != Shape::wlevels) continue;
        std::vector<char> cell(static_cast<size_t>(p.nstrata) * nlev, 0);
        for (const auto& g : groups) {
          glev.clear();
          for (int u : g)
            if (!has[xl[u]]) has[xl[u]] = 1, glev.push_back(xl[u]);
          for (int l : glev) has[l] = 0;
          for (int u : g)
            for (int l : glev) cell[static_cast<size_t>(p.stratum[u]) * nlev + l] = 1;
        }
        const size_t nreach = static_cast<size_t>(std::count(cell.begin(), cell.end(), 1));
        if (2 * nreach > cell.size()) continue;  // most cells reachable: every cell, as before
        for (size_t k = 0; k < cell.size(); ++k)
          if (cell[k]) p.reach.push_back(static_cast<int>(k));
      }
    }
    int dof_max = 0;
    for (const auto& p : probes) dof_max = std::max(dof_max, p.dof[0]);
    res.dof = dof_max;
    if (probes.empty()) {
      res.p_value = 1;
      out[ci] = std::move(res);
      continue;
    }
    // Statistic: the family's largest probe on a common scale.  Each probe's
    // explained sum of squares is X = ESS / scale (calibrated below), about
    // chi^2 with the probe's dof on null data; the Wilson-Hilferty cube root
    // maps it to a normal deviate, so a probe
    // of 1 dof and one of 8 compete by how surprising each is, not by the
    // explained fraction per dof (which buried every many-level probe).  The
    // permutation test calibrates the maximum, so the transform only decides
    // how the probes share the family's power.
    // Sub-probe values of every probe: vals[off[j] + k] is sub-probe k of probe j
    // (of L permutations side by side: lane i at lvals[(off[j] + k) L + i]).
    std::vector<size_t> off(probes.size() + 1, 0);
    for (size_t j = 0; j < probes.size(); ++j) off[j + 1] = off[j] + probes[j].nsub();
    std::vector<double> vals(off.back()), lvals(off.back() * kLanes);
    auto stat = [&](const std::vector<double>& a, const std::vector<int>& b, int* best, int* best_sub) {
      double t = -INFINITY;
      for (size_t j = 0; j < probes.size(); ++j) {
        probes[j].eval<1>(a.data(), b.data(), &vals[off[j]]);
        for (int k = 0; k < probes[j].nsub(); ++k) {
          if (probes[j].dof[k] <= 0) continue;
          const double v = probe_z(probes[j], k, vals[off[j] + k]);
          if (v > t) t = v, *best = static_cast<int>(j), *best_sub = k;
        }
      }
      return t;
    };
    // The same for kLanes permutations at once (unit values interleaved by lane),
    // the statistic of lane i: the same comparisons in the same order.
    auto eval_lanes = [&](const std::vector<double>& a, const std::vector<int>& b) {
      for (size_t j = 0; j < probes.size(); ++j) probes[j].eval<kLanes>(a.data(), b.data(), &lvals[off[j] * kLanes]);
    };
    auto lane_stat = [&](int i) {
      double t = -INFINITY;
      for (size_t j = 0; j < probes.size(); ++j)
        for (int k = 0; k < probes[j].nsub(); ++k) {
          if (probes[j].dof[k] <= 0) continue;
          const double v = probe_z(probes[j], k, lvals[(off[j] + k) * kLanes + i]);
          if (v > t) t = v;
        }
      return t;
    };
    // Lanes past the last permutation of a pass repeat lane 0 (their values unused).
    auto fill_lanes = [&](std::vector<double>& a, std::vector<int>& b, int used) {
      if (used == kLanes) return;
      for (size_t u = 0; u < U; ++u)
        for (int i = used; i < kLanes; ++i) a[u * kLanes + i] = a[u * kLanes], b[u * kLanes + i] = b[u * kLanes];
    };
    // Calibration: ESS of each probe under a pilot sample of permutations (its
    // own random stream, so the test's permutations stay independent of it).
    // The permutation distribution is the same whichever permutation the data
    // are, so constants taken from it keep the test exact.  scale = mean ESS /
    // dof puts every probe on the chi^2(dof) scale even when whole tests are
    // the units (a test's rows share its scatter, so ESS / s^2 of the rows
    // would inflate with the dof); a probe whose ESS does not change under
    // permutation (a variable constant within every permutation group) is
    // dropped (a sub-probe so: its dof set to 0).
    size_t kmax = 1;
    for (const auto& g : groups) kmax = std::max(kmax, g.size());
    for (const auto& bg : bgroups) kmax = std::max(kmax, bg.size());
    const FastMod mod(kmax);  // mod(rng(), k) == rng() % k, without the division
    // A group of consecutive units (rows of a test, in file order) is shuffled
    // in place without reading its unit list: the same draws, the same swaps.
    // Its first unit and size in flat arrays (read for every permutation; the
    // groups' own lists are scattered over the heap and missed the cache).
    std::vector<char> run(groups.size(), 1);
    std::vector<int> gfirst(groups.size()), gsize(groups.size());
    for (size_t gi = 0; gi < groups.size(); ++gi) {
      gfirst[gi] = groups[gi][0], gsize[gi] = static_cast<int>(groups[gi].size());
      for (size_t k = 1; k < groups[gi].size(); ++k) run[gi] = run[gi] && groups[gi][k] == groups[gi][0] + static_cast<int>(k);
    }
    {
      Mt64 prng(seed + 7919 * ci + 104729);
      std::vector<int> pp(U);
      for (size_t u = 0; u < U; ++u) pp[u] = static_cast<int>(u);
      std::vector<double> qz(U * kLanes);
      std::vector<int> ql(U * kLanes);
      const int P = kPilot;
      std::vector<double> m1(off.back(), 0.0), m2(off.back(), 0.0);
      for (int j0 = 0; j0 < P; j0 += kLanes) {
        const int used = std::min(kLanes, P - j0);
        for (int i = 0; i < used; ++i) {
          for (size_t gi = 0; gi < groups.size(); ++gi) {
            if (run[gi]) {
              int* q = pp.data() + gfirst[gi];
              for (size_t k = gsize[gi]; k > 1; --k) std::swap(q[k - 1], q[mod(prng(), k)]);
              continue;
            }
            const auto& g = groups[gi];
            for (size_t k = g.size(); k > 1; --k) std::swap(pp[g[k - 1]], pp[g[mod(prng(), k)]]);
          }
          fill_unit_values(pp, qz, ql, i, prng, mod);
        }
        fill_lanes(qz, ql, used);
        eval_lanes(qz, ql);
        for (int i = 0; i < used; ++i)
          for (size_t q = 0; q < off.back(); ++q) {
            const double v = lvals[q * kLanes + i];
            m1[q] += v / P, m2[q] += v * v / P;
          }
      }
      std::vector<ProbeDef> kept;
      for (size_t q = 0; q < probes.size(); ++q) {
        for (int k = 0; k < probes[q].nsub(); ++k) {
          const size_t h = off[q] + k;
          const double var = m2[h] - m1[h] * m1[h];
          if (!(m1[h] > 0) || !(var > 1e-12 * m1[h] * m1[h]) || probes[q].dof[k] <= 0) probes[q].dof[k] = 0;
          else if (k == 0) probes[q].kdof[k] = probes[q].dof[k], probes[q].scale[k] = m1[h] / probes[q].dof[k];
          else {
            // A one-group sub-probe: scaled chi^2 matched to the pilot's mean
            // AND variance (Satterthwaite).  Its ESS can be nearly constant
            // under permutation (a row-level variable permuted within tests
            // while the residual of its group varies between tests); on the
            // chi^2(dof) scale such a probe would sit at a fixed deviate and
            // could win every permutation's maximum, hiding the other probes.
            probes[q].kdof[k] = 2 * m1[h] * m1[h] / var;
            probes[q].scale[k] = m1[h] / probes[q].kdof[k];
          }
        }
        if (probes[q].dof[0] > 0 || std::any_of(probes[q].dof.begin(), probes[q].dof.end(), [](int v) { return v > 0; }))
          kept.push_back(std::move(probes[q]));
      }
      probes = std::move(kept);
      off.assign(probes.size() + 1, 0);
      for (size_t j = 0; j < probes.size(); ++j) off[j + 1] = off[j] + probes[j].nsub();
      vals.assign(off.back(), 0.0);
      lvals.assign(off.back() * kLanes, 0.0);
    }
    if (probes.empty()) {
      res.p_value = 1;
      out[ci] = std::move(res);
      continue;
    }
    int best = 0, best_sub = 0;
    const double T = stat(xz, xl, &best, &best_sub);
    res.stat = vals[off[best] + best_sub];
    res.probe = probes[best].sub_label(best_sub);
    // The strongest one-group sub-probe of the best probe's input (the cell
    // the forms try an effect confined to), when the best probe is per input.
    if (probes[best].cells) {
      double zb = -INFINITY;
      for (int k = 1; k < probes[best].nsub(); ++k)
        if (probes[best].dof[k] > 0) {
          const double v = probe_z(probes[best], k, vals[off[best] + k]);
          if (v > zb) zb = v, res.cell_group = k - 1, res.cell_by = probes[best].input;
        }
    }
    // Held-out gain: the best of the probes (a probe of the wrong shape must
    // not hide a variable), and of each per-input probe's strongest one-group
    // sub-probe.
    std::vector<double> wrow(n, 1.0);
    if (weighted) wrow = ctx->mu_weight;
    res.cv_reduction = -INFINITY;
    for (size_t j = 0; j < probes.size(); ++j) {
      const ProbeDef& p = probes[j];
      if (p.dof[0] > 0) {
        const double cv = probe_cv(p, rows, z, lv, wrow, p.rpre.empty() ? resid : p.rpre, f);
        if (cv > res.cv_reduction) res.cv_reduction = cv, res.cv_probe = p.label;
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
        if (cv > res.cv_reduction) res.cv_reduction = cv, res.cv_probe = p.sub_label(kb);
      }
    }
    Mt64 rng(seed + 7919 * ci);
    int ge = 0, b = 0, dec = 0;
    std::vector<int> perm(U);
    for (size_t u = 0; u < U; ++u) perm[u] = static_cast<int>(u);
    std::vector<double> pz(U * kLanes);
    std::vector<int> pl(U * kLanes);
    const int cap = std::max(1, permutations);
    for (int batch = 100; b < cap; batch = std::min(cap - b, 2 * batch)) {
      for (int j = 0; j < batch; j += kLanes) {  // kLanes permutations per pass over the units
        const int used = std::min(kLanes, batch - j);
        for (int i = 0; i < used; ++i) {
          for (size_t gi = 0; gi < groups.size(); ++gi) {  // Fisher-Yates within the group
            if (run[gi]) {
              int* q = perm.data() + gfirst[gi];
              for (size_t k = gsize[gi]; k > 1; --k) std::swap(q[k - 1], q[mod(rng(), k)]);
            } else {
              const auto& g = groups[gi];
              for (size_t k = g.size(); k > 1; --k) std::swap(perm[g[k - 1]], perm[g[mod(rng(), k)]]);
            }
          }
          fill_unit_values(perm, pz, pl, i, rng, mod);
        }
        fill_lanes(pz, pl, used);
        eval_lanes(pz, pl);
        for (int i = 0; i < used; ++i)
          if (lane_stat(i) >= T - 1e-12 * std::max(1.0, std::abs(T))) ++ge;
        b += used;
      }
      dec = sequential_decision(ge, b, thr);
      if (dec != 0) break;
    }
    res.n_perm = b;
    res.p_value = (1.0 + ge) / (1.0 + b);
    res.significant = dec > 0 && res.cv_reduction > 0;
    res.decision = dec > 0 ? (res.cv_reduction > 0 ? "significant" : "significant, no held-out gain")
                           : dec < 0 ? "not significant" : "undecided";
    out[ci] = std::move(res);
  }
  std::stable_sort(out.begin(), out.end(), [](const CandidateResult& a, const CandidateResult& b) {
    if (a.significant != b.significant) return a.significant;
    if (a.significant) return a.cv_reduction > b.cv_reduction;
    return a.p_value < b.p_value;
  });
  return out;
}

}  // namespace drawbend::loop
