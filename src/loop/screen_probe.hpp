#pragma once
// Internal to the screen (candidates.hpp is the public header): one probe of a
// candidate and its two uses.
//
//   screen.cpp        rank_candidates: each candidate's screen as a recipe of
//                     steps (screen_candidate.hpp); the probe family in
//                     screen_family.cpp, its calibration and the permutation
//                     test in screen_permute.cpp
//   screen_probe.cpp  ProbeDef::eval: explained sums of squares of several
//                     permutations in one pass over the units; probe_cv: a
//                     probe's held-out gain on the model's folds; centred_by
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "loop/candidates.hpp"

namespace drawbend::loop::detail {

enum class Shape { levels, wlevels, quad, slopes, wslope };

// Permutations evaluated side by side in one pass over the units (each in its
// own lane, with the same operations in the same order as one alone).
constexpr int kLanes = 4;

// One probe of a candidate over units (tests or rows).  Its residual is centred
// per stratum (a block, or a block x group of a model input); ur/urw/un/uw2 are
// per unit: sum of centred residual, of weight x centred residual, row count
// and sum of squared weights.  A per-input probe (ngroups > 1, stratum = block
// x ngroups + group) also gives one sub-probe per group g, the same shape
// pooled over the strata of group g only (a common slope, or common level
// means, in that one cell and none elsewhere): an effect confined to one pin,
// speed, direction or lubricant is one surprise of 1 (or levels - 1) dof
// there, not diluted over every cell's slope.  Sub-probe 0 is the probe itself.
struct ProbeDef {
  Shape shape = Shape::levels;
  std::string label, input;
  std::vector<int> stratum;  // per unit
  int nstrata = 1, nlev = 1, ngroups = 1;
  bool cells = false;            // sub-probes per group of the input
  // Pooled over blocks (test-level variables, ScreenContext::pooled_inputs): strata
  // are the input's groups, the residual centred per block, then per group;
  // rpre is that residual per row (centred_by).
  std::vector<double> rpre;
  std::vector<int> dof;          // per sub-probe (0: dropped)
  std::vector<double> scale;     // per sub-probe: ESS / scale ~ chi^2(kdof) under permutation (pilot)
  std::vector<double> kdof;      // per sub-probe: the chi^2's dof (0: dof; one-group: moment-matched)
  std::vector<double> ur, urw, un, uw2;
  std::vector<double> mean;  // per stratum: the mean the residual is centred by (0: no rows)
  double sst = 0;  // sum of squares of the centred residual (constant under permutation)
  // levels (unweighted): the rows per (stratum, level) cell when no permutation
  // changes them (every permutation group in one stratum, with one row count per
  // unit: a row-level variable permuted within tests); sums of whole numbers, so
  // the same bit for bit in any order; empty: summed on every eval.
  std::vector<double> fixed_counts;
  // levels, wlevels: the (stratum, level) cells a permutation can reach, in
  // ascending order (a unit's stratum with a level of its permutation group);
  // the other cells stay empty under every permutation, so their zeroing and
  // their terms (none: an empty cell adds nothing) are skipped, the sums over
  // the reachable cells made in the same order.  A test-level variable with
  // many levels has far more cells than units (issue 50 item 6).  Empty: all.
  std::vector<int> reach;
  // row-level data for the held-out probe
  std::vector<int> row_stratum;
  mutable std::vector<double> s1, s2, s3, s4, c1, c2;
  mutable std::vector<double> s12;  // levels, wlevels: per (cell, lane) its s1 and s2 side by side
  int nsub() const { return cells ? 1 + ngroups : 1; }
  // s4 = rows per stratum (sum of un in unit order): it does not depend on the
  // permutation, so it is summed once, on the first eval.
  void count_per_stratum() const {
    if (s4.size() == static_cast<size_t>(nstrata)) return;
    s4.assign(nstrata, 0.0);
    for (size_t u = 0; u < un.size(); ++u) s4[stratum[u]] += un[u];
  }
  // Explained sums of squares of every sub-probe with the unit values xz
  // (z-score) and xl (level) of L permutations side by side: unit u's value in
  // lane j is xz[u L + j]; sub-probe k's ESS in lane j goes to out[k L + j].
  // Every lane's ESS is bit for bit that of the permutation evaluated alone
  // (L = 1: the plain unit values).
  template <int L>
  void eval(const double* xz, const int* xl, double* out) const;
  // eval's steps, one per shape (screen_probe.cpp; the levels shapes in two)
  template <int L>
  inline void level_sums(const int* xl) const;
  template <int L>
  inline void level_ess(double* out) const;
  template <int L>
  inline void slopes_ess(const double* xz, double* out) const;
  template <int L>
  inline void wslope_ess(const double* xz, double* out) const;
  template <int L>
  inline void quad_ess(const double* xz, double* out) const;
  std::string sub_label(int j) const {
    return j == 0 ? label : label + ": " + input + " group " + std::to_string(j) + " only";
  }
};

// Wilson-Hilferty normal deviate of X = ESS / scale ~ chi^2(dof) (see the statistic in rank_candidates).
inline double probe_z(const ProbeDef& p, int j, double ess) {
  const double k = p.kdof[j], x = std::max(0.0, ess) / p.scale[j], c = 2.0 / (9.0 * k);
  return (std::cbrt(x / k) - (1 - c)) / std::sqrt(c);
}

// Held-out fractional reduction of the residual SSE by a probe, with the same
// folds as the model: on the training rows of each fold the probe is fitted
// (stratum means plus its shape), the held-out rows predicted; against the
// stratum means alone.  z, l, w per row.  cell >= 0: the probe's one-group
// sub-probe (levels or slope pooled over the strata of group `cell`, nothing
// elsewhere).
double probe_cv(const ProbeDef& p, const std::vector<int>& rows, const std::vector<double>& z,
                const std::vector<int>& l, const std::vector<double>& w, const std::vector<double>& r,
                const Folds& f, int cell = -1);

// The residual centred per group (a block) over the rows.  A test-level
// variable is permuted between the tests of a block, and its per-input probe
// is centred per block x group: with many cells and few tests per cell (the
// bt-block designs) such a stratum holds one test or two, so an effect
// confined to one pin, direction or lubricant had no test to be compared
// with.  The pooled per-input probe takes the input's groups as strata over
// all blocks, the residual centred per block and then per group, so the tests
// of one pin in different cells are compared; it is still a permutation within
// blocks, so the test stays exact.
std::vector<double> centred_by(const std::vector<int>& group, int ngroups, const std::vector<int>& rows,
                               const std::vector<double>& r);

}  // namespace drawbend::loop::detail
