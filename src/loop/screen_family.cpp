// The probe family of one candidate (see screen_candidate.hpp): each probe's
// strata, per-unit sums and degrees of freedom; the level counts no
// permutation changes; the cells a permutation can reach.
#include <algorithm>
#include <set>

#include "loop/screen_candidate.hpp"

namespace drawbend::loop::detail {

namespace {

// The names by which a candidate is itself one of the model's inputs.
bool same_input(const std::string& cand, const std::string& input) {
  if (input == "pin") return cand == "pin" || cand == "pin_diameter_mm" || cand == "inv_R_per_mm";
  return cand == input;
}

}  // namespace

// A probe of the given shape over the strata block x group of row_group (pooled:
// the groups alone), kept when it has degrees of freedom and scatter.
void CandidateScreen::add(Shape shape, const std::string& label, const std::vector<int>& row_group, int ngroups,
                          const std::string& input, bool pooled) {
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
  centre_per_unit(p, pooled);
  count_dof(p, shape, ngroups);
  if (p.dof[0] > 0 && p.sst > 0) probes.push_back(std::move(p));
}

// The residual centred per stratum, summed per unit (ur, urw, un, uw2), and its sum of squares.
void CandidateScreen::centre_per_unit(ProbeDef& p, bool pooled) const {
  const std::vector<double>& r0 = pooled ? (p.rpre = centred_by(f.block, nblocks, rows, resid)) : resid;
  std::vector<double> sm(p.nstrata, 0.0), sn(p.nstrata, 0.0);
  for (int i : rows) sm[p.row_stratum[i]] += r0[i], sn[p.row_stratum[i]] += 1;
  p.mean.assign(p.nstrata, 0.0);
  for (int s = 0; s < p.nstrata; ++s)
    if (sn[s] > 0) p.mean[s] = sm[s] / sn[s];
  p.stratum.assign(U, 0);
  p.ur.assign(U, 0.0), p.urw.assign(U, 0.0), p.un.assign(U, 0.0), p.uw2.assign(U, 0.0);
  for (int i : rows) {
    const int s = p.row_stratum[i], u = unit_of[i];
    const double rc = r0[i] - p.mean[s], w = weighted ? ctx->mu_weight[i] : 1.0;
    p.stratum[u] = s;  // a test lies in one stratum (blocks and model inputs are constant within a test)
    p.ur[u] += rc, p.urw[u] += w * rc, p.un[u] += 1, p.uw2[u] += w * w;
    p.sst += rc * rc;
  }
}

// Degrees of freedom on the observed data (whole probe, then one per group).
void CandidateScreen::count_dof(ProbeDef& p, Shape shape, int ngroups) const {
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
}

// The family: the shapes on all the rows, scaled with dF/dmu, and per model input.
void CandidateScreen::build_family() {
  const std::vector<int> none;
  // A column whose own values are the levels (categorical, or numeric with at
  // most 8 values) gets no per-level probe when its levels are not replicated
  // (levels_replicated, candidates.hpp: fewer than two rows a level on
  // average): such a probe's dof nears the rows', it explains nearly the whole
  // residual under every permutation and no form of it is identifiable.  A
  // categorical column is then not probed at all (every probe of it is per level).
  const bool own_levels = c.categorical || distinct.size() <= kOwnLevelsMax;
  if (own_levels && !levels_replicated(distinct.size(), rows.size())) {
    if (c.categorical) return;
    add(Shape::quad, distinct.size() >= 4 ? "linear + quadratic" : "linear", none, 1);
    if (weighted) add(Shape::wslope, "scaled with dF/dmu", none, 1);
    return;
  }
  if (c.categorical) add(Shape::levels, "levels", none, 1);
  else {
    add(Shape::quad, distinct.size() >= 4 ? "linear + quadratic" : "linear", none, 1);
    if (nlev > 2) add(Shape::levels, distinct.size() <= kOwnLevelsMax ? "levels" : std::to_string(nlev) + " quantile bins", none, 1);
  }
  if (weighted) add(c.categorical ? Shape::wlevels : Shape::wslope, "scaled with dF/dmu", none, 1);
  if (weighted && !c.categorical && nlev > 2)  // a multiplicative effect of any shape
    add(Shape::wlevels, (distinct.size() <= kOwnLevelsMax ? "levels" : std::to_string(nlev) + " quantile bins") +
                            std::string(" scaled with dF/dmu"), none, 1);
  if (ctx)
    for (const auto& [input, g] : ctx->modifiers) {
      if (same_input(c.name, input)) continue;
      int ng = 0;
      for (int i : rows) ng = std::max(ng, g[i] + 1);
      if (count_distinct(g, rows) < 2) continue;
      add(c.categorical || distinct.size() <= kOwnLevelsMax ? Shape::levels : Shape::slopes, "per " + input, g, ng, input);
      if (!c.categorical && distinct.size() > kOwnLevelsMax) add(Shape::levels, "bins per " + input, g, ng, input);
      if (c.test_level && pooled_inputs)  // see centred_by
        add(c.categorical || distinct.size() <= kOwnLevelsMax ? Shape::levels : Shape::slopes, "per " + input + ", pooled over cells",
            g, ng, input, true);
      // A shape of any kind in one group of the input, pooled over the cells: with
      // a few tests per block, bins per block x group explain every test's mean
      // whatever the permutation (each test its own bin), so a curved effect
      // confined to one group is seen only with bins shared over the blocks.
      if (pooled_inputs && !c.categorical && distinct.size() > kOwnLevelsMax)
        add(Shape::levels, "bins per " + input + ", pooled over cells", g, ng, input, true);
    }
}

// levels: counts no permutation changes (see ProbeDef::fixed_counts).
void CandidateScreen::fixed_counts() {
  for (auto& p : probes) {
    if (p.shape != Shape::levels || two_level) continue;
    bool fixed = true;
    for (const auto& g : groups)
      for (int u : g) fixed = fixed && p.stratum[u] == p.stratum[g[0]] && p.un[u] == p.un[g[0]];
    if (!fixed) continue;
    p.fixed_counts.assign(static_cast<size_t>(p.nstrata) * p.nlev, 0.0);
    for (size_t u = 0; u < U; ++u) p.fixed_counts[static_cast<size_t>(p.stratum[u]) * p.nlev + xl[u]] += p.un[u];
  }
}

// levels: the cells a permutation can reach (see ProbeDef::reach).
void CandidateScreen::reachable_cells() {
  if (two_level) return;
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

// The largest whole-probe dof of the family (the result's dof).
int CandidateScreen::dof_max() const {
  int dof_max = 0;
  for (const auto& p : probes) dof_max = std::max(dof_max, p.dof[0]);
  return dof_max;
}

}  // namespace drawbend::loop::detail
