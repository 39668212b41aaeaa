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
  FastMod mod{1};

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
  // screen_permute.cpp
  void flat_groups();
  void calibrate(std::uint64_t seed, size_t ci);
  double observed(CandidateResult& res);
  void permutation_test(CandidateResult& res, double T, std::uint64_t seed, size_t ci, int permutations, double thr);
  // the inner loops of the permutations (inline, defined and used in screen_permute.cpp only)
  inline void shuffle(std::vector<int>& p, Mt64& r) const;
  inline void fill_unit_values(const std::vector<int>& p, std::vector<double>& qz, std::vector<int>& ql, int j,
                               Mt64& r);
  inline void fill_lanes(std::vector<double>& a, std::vector<int>& b, int used) const;
  inline void eval_lanes(const std::vector<double>& a, const std::vector<int>& b);
  inline double lane_stat(int i) const;
  double stat(const std::vector<double>& a, const std::vector<int>& b, int* best, int* best_sub);
  void set_offsets();
};

}  // namespace drawbend::loop::detail
