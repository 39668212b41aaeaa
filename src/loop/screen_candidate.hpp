#pragma once
// Internal to the screen (candidates.hpp is the public header): one candidate's
// screen as a recipe of named steps over its state (rank_candidates runs it per
// candidate, each thread its own CandidateScreen).
//
//   screen.cpp          rank_candidates and the recipe; the rows, their values,
//                       the units and permutation groups; the random-effect F
//                       test; the held-out gain
//   screen_family.cpp   the probe family: each probe's strata, sums and dof;
//                       the counts no permutation changes; the reachable cells
//   screen_permute.cpp  the permutations: the pilot calibration of the probes'
//                       scales, the observed statistic and the permutation test
//   screen_bound.cpp    the permutation test's bounded pass: an upper bound on a
//                       permutation's statistic from per-test sums (row-level
//                       candidates permuted within tests)
#include <cstdint>
#include <string>
#include <vector>

#include "loop/candidates.hpp"
#include "loop/fast_mod.hpp"
#include "loop/mt64.hpp"
#include "loop/screen_probe.hpp"

namespace drawbend::loop::detail {

// How many distinct values the integer keys take over the rows.
size_t count_distinct(const std::vector<int>& keys, const std::vector<int>& rows);

// One probe of the permutation test's bounded pass (screen_bound.cpp).
struct BoundProbe {
  int j = 0;                // the probe's index in the family
  std::vector<double> e;    // per stratum: bound on |exact - bounded| of a cell's sum (levels) or of s3 (slopes)
  std::vector<double> alo;  // slopes, per stratum: lower bound on the exact a (0: the stratum adds no term);
                            // wlevels: (1 - the relative bound) of a cell's sum of squared weights
  std::vector<double> sx;   // slopes, per stratum: the sum of x (the same under every permutation)
  std::vector<int> gstratum;  // per test (permutation group): its stratum
  std::vector<double> acc;  // the lanes' sums: per (stratum, level) cell, or per stratum, and lane
  std::vector<double> sxx;  // quad, per stratum: the sum of x^2
  std::vector<double> bsum;  // pooled levels, per (stratum, level) cell: the sum of its rows' block means
  double eb = 0, arel = 0;  // wslope: bound on |exact - bounded| of b, and a's relative one; quad: of b1
  double eb2 = 0;           // quad: of b2
  double q11 = 0, q12 = 0, q22 = 0, eq = 0, lam = 0, cond = 0;  // quad: Q, its entries' bound, eigenvalue
  int mode = 0;             // quad: the exact pass's branch (0: no term, 1: line, 2: both)
  double factor = 1;        // (1 + slack) on the computed sum of the terms' upper bounds
};

struct CandidateScreen {
  CandidateScreen(const Candidate& c, const std::vector<double>& resid, const Folds& f, const ScreenContext* ctx,
                  int nblocks)
      : c(c), resid(resid), f(f), ctx(ctx), n(resid.size()), nblocks(nblocks),
        weighted(ctx && ctx->mu_weight.size() == resid.size()), pooled_inputs(ctx && ctx->pooled_inputs) {}

  // The screen's inputs.
  const Candidate& c;
  const std::vector<double>& resid;
  const Folds& f;
  const ScreenContext* ctx;
  const size_t n;
  const int nblocks;
  const bool weighted, pooled_inputs;

  // select_rows: the rows with a finite value and residual; the distinct values, ascending.
  std::vector<int> rows;
  std::vector<double> distinct;
  // row_values: z-score and level index per row; quantile-bin edges on the z scale.
  std::vector<double> z;
  std::vector<int> lv;
  int nlev = 1;
  std::vector<double> cutz;
  // units_and_groups: each row's unit; per unit its value, level and block;
  // the permutation groups (lists of units).
  std::vector<int> unit_of, unit_block;
  std::vector<std::vector<int>> groups;
  std::vector<double> xz;
  std::vector<int> xl;
  size_t U = 0;
  // two_level_groups: permuted within and between tests (see there).
  bool two_level = false;
  std::vector<int> ug, tp;
  std::vector<double> gz;
  std::vector<std::vector<int>> bgroups;
  // The probe family and its sub-probe values (single and lane-interleaved).
  std::vector<ProbeDef> probes;
  std::vector<size_t> off;
  std::vector<double> vals, lvals;
  // flat_groups: the groups as runs of consecutive units, and the shuffle's modulus.
  std::vector<char> run;
  std::vector<int> gfirst, gsize;
  FastMod32 mod{1};
  std::vector<double> cutp;  // cutz padded with +inf to 2^m - 1 entries (the bins' halving search)
  // setup_bounds: the permutation test's bounded pass (screen_bound.cpp).
  bool bounded = false;
  std::vector<BoundProbe> bprobes;
  std::vector<char> bfast;  // per probe: in bprobes
  std::vector<double> r0;   // per unit (a row): the residual the probes centre
  int bws = -1;             // bprobes' wslope, or -1
  bool quad = false;        // a quad probe in bprobes
  int bwl = -1;             // bprobes' wlevels, or -1
  // The tests by their strata: tests with the same stratum in every bounded
  // probe share a key (gkey, per test; kstratum[k * bprobes.size() + i]: key
  // k's stratum in bprobes[i]), and the bounded pass sums per key, not per test.
  std::vector<int> gkey, kstratum;
  int nkeys = 0;
  std::vector<double> ka, kaw, kx;  // per key: level sums (and wlevels'), and x r, x^2 r; by lane
  std::vector<long> xlo;  // per unit: xl * kLanes, the lane-0 offset of its level's sums (64-bit: no widening per row)

  // screen.cpp
  void select_rows();
  void random_effect(CandidateResult& res) const;
  void row_values();
  void units_and_groups();
  void two_level_groups(CandidateResult& res);
  void held_out_gain(CandidateResult& res) const;
  // screen_family.cpp
  void add(Shape shape, const std::string& label, const std::vector<int>& row_group, int ngroups,
           const std::string& input = "", bool pooled = false);
  void centre_per_unit(ProbeDef& p, bool pooled) const;
  void count_dof(ProbeDef& p, Shape shape, int ngroups) const;
  void build_family();
  void fixed_counts();
  void reachable_cells();
  int dof_max() const;
  // screen_bound.cpp
  void setup_bounds();
  double quad_bound(const ProbeDef& p, const BoundProbe& b, int j) const;
  void bounded_max(const std::vector<int>* lp, double* zmax);
  // screen_permute.cpp
  void flat_groups();
  void calibrate(std::uint64_t seed, size_t ci);
  double observed(CandidateResult& res);
  void permutation_test(CandidateResult& res, double T, std::uint64_t seed, size_t ci, int permutations, double thr);
  // the inner loops of the permutations (inline, defined and used in screen_permute.cpp only)
  inline void shuffle(std::vector<int>& p, Mt64Halves& r) const;
  inline void fill_unit_values(const std::vector<int>& p, std::vector<double>& qz, std::vector<int>& ql, int j,
                               Mt64Halves& r);
  inline void fill_lanes(std::vector<double>& a, std::vector<int>& b, int used) const;
  inline void eval_lanes(const std::vector<double>& a, const std::vector<int>& b, int which = -1);
  inline double lane_stat(int i, bool bounded_too = true) const;
  double stat(const std::vector<double>& a, const std::vector<int>& b, int* best, int* best_sub);
  void set_offsets();
};

}  // namespace drawbend::loop::detail
