#pragma once
// Residual analysis: grouped cross-validation folds, candidate variables, and
// their ranking by cross-validated error reduction and a blocked permutation
// test.
//
// Folds ("whole tests or back-tension blocks held out"):
//   test      every test goes whole into one of K folds (index of the test
//             within its block, mod K), so no held-out row shares a test with
//             the training rows;
//   bt-block  within every test the rows are ranked by back tension and cut
//             into K blocks; fold k holds out block k of every test (used when
//             a block has a single test per pin, as the thesis data do);
//   auto      test when every block has at least 2 tests per pin, else bt-block.
// Blocks: the rotating-pin rows form one block, the fixed-pin rows of each
// model cell another.  Residuals and probe features are centred per block.
//
// The screen (screen.cpp).  Each candidate is probed by a FAMILY of probes,
// each a small regression of the residual (centred per stratum) on the
// variable:
//   main      categorical: one mean per level; numeric: z, plus z^2 with 4+
//             distinct values;
//             (no probe per level of a column whose levels average fewer than
//             two rows, levels_replicated below: a categorical such column,
//             a clock time or an id as text, is then not probed at all)
//   levels    numeric with 3-8 distinct values: one mean per value (a peak at
//             a middle level has no linear part); more values: quantile bins,
//             8 when the variable has 80 or more units (rows, or tests for a
//             test-level variable), else 5 (a step, bump, periodic or any
//             smooth shape);
//   scaled    the effect scaled with dF/dmu of the row (an effect on mu is
//             larger in newtons where the friction force is larger): a slope,
//             and for numeric variables also the levels/bins so scaled;
//   per input the main/levels probe separately within each group of each of
//             the model's inputs (pin, speed, direction, lubricant; residual
//             centred per block x group), for effects that act in one cell
//             only; numeric variables with more than 8 values get a slope and
//             the quantile bins per group;
//   pooled    (ScreenContext::pooled_inputs; the loop's default, `--pooled-inputs false` drops it)
//             for test-level variables, the per-input probe also with the
//             input's groups pooled over the blocks (residual centred per block,
//             then per group): centred per block x group, a stratum of a design
//             with many cells holds one or two tests, so an effect confined to
//             one pin, direction or lubricant had nothing to be compared with;
//             still permuted within blocks, so the test stays exact;
//   one cell  (opt-in, ScreenContext::one_cell) each per-input probe's shape pooled over the strata of ONE
//             group of its input (one common slope, 1 dof, or common level
//             means, levels - 1 dof, in that group and nothing elsewhere): an
//             effect confined to one pin, speed, direction or lubricant is
//             one surprise there instead of being diluted over every group's
//             slope; computed from the per-input probe's own sums, so it adds
//             no pass over the units.  The strongest such group of the best
//             per-input probe is passed to the forms (cell_by, cell_group).
//             Its scale matches the pilot's mean and variance (a scaled
//             chi^2 of moment-matched dof), as its ESS may hardly vary under
//             permutation.
// The candidate's statistic is the family's largest probe on a common scale:
// each probe's explained sum of squares over its calibration scale (the mean
// ESS under the pilot permutations, on their own random stream, divided by its
// dof; 100 pilot permutations) is about chi^2(dof), mapped to a normal deviate by the Wilson-Hilferty
// cube root, so probes of 1 and of 20 dof compete by how surprising each is;
// probes whose ESS does not change under permutation are dropped.  The
// permutation test permutes the variable (all probes at once) within blocks:
// test-level variables (constant within each test) between the tests of a
// block, row-level variables between the rows of a test; a numeric row-level
// column (with quantile bins) on both levels: its test means between the
// tests of a block and its deviations from them within each test (a column
// that accumulates over the tests has its bulk between them).  The permutation
// distribution of the maximum accounts for the family, so the candidate's
// p = (1 + #{T* >= T}) / (1 + B) is compared with alpha / (number of
// candidates) as before.  Its held-out gain (cv_reduction) is the best of the
// family's probes, fitted on the same folds as the model.

// Pairs (screen_pairs.cpp, LoopOptions::pair_probes): every pair of numeric
// columns of the data (at most the first 16 columns) as the product of the
// centred columns, for an effect of two columns together (a crossover has no
// main effect, so no single-column probe sees it).  The pairs are screened as
// two families, each one permutation test of its maximum (all columns
// permuted jointly): the rows of each test (pairs with a row-level column) and
// the tests of each block (every pair, the product's test mean).  Each family
// counts as one test in the threshold alpha / (tests + families), a group of
// candidates with the same information being one test (screen_same.cpp).

// Sequential decisions (seed-independent): permutations run in batches; after
// each batch the Clopper-Pearson interval of p at confidence 1 - 1e-3 is
// compared with the threshold alpha / (number of tests): wholly below ->
// significant, wholly above -> not significant; at `permutations` (the cap)
// still straddling -> decided by the Monte Carlo p-value (1 + k) / (1 + b),
// valid at any b: p <= thr significant, else "undecided".  So a decision
// differs between two seeds with probability below 2e-3 per candidate, except
// for a candidate whose p is within the cap's Monte Carlo error of thr.
//
// Identity variables (test_id) are not permuted (permuting test labels
// between tests leaves the partition unchanged, so p = 1 by construction):
// they are tested as a random effect, a one-way ANOVA F test of the residuals'
// between-test scatter against the within-test scatter, block-centred.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "loop/model.hpp"

namespace drawbend::loop {

struct Folds {
  std::string mode;
  int k = 5;
  std::vector<int> fold;   ///< per row
  std::vector<int> block;  ///< per row
  std::vector<int> test;   ///< per row: test index
};

Folds make_folds(const Design& d, const std::string& mode, int k);

struct CvResult {
  std::vector<double> pred, resid;  ///< held-out prediction and residual per row (NaN: not predictable)
  double rms = 0, max_abs = 0;
  int n = 0;
};

CvResult cross_validate(const Design& d, const ModelSpec& spec, const Folds& f);

/// Whether a column's levels may each carry a parameter (the screen's per-level
/// probes, the loop's per-level forms): only when they average at least two
/// rows each, 2 L <= n (L levels on the n rows with a value).  A per-level probe
/// or form spends one parameter per level; a level seen in one row only is
/// fitted exactly by its own parameter (one parameter per row: the row's noise
/// absorbed, nothing to estimate it against, and a held-out fold never has that
/// level among its training rows).  With 2 L > n at least 2 L - n levels are
/// such single rows, and the rows left over the levels' first (n - L, the
/// within-level degrees of freedom) fall short of the form's L - 1 parameters
/// as L nears n: a clock time or a per-row id as text, 616 levels in 621 rows,
/// is not identifiable per level.  With 2 L <= n no level need be a single row
/// and the replication n - L is at least the L - 1 parameters.  The bound is
/// the least replication (two rows a level) that identifies every level's
/// parameter apart from its own row's noise, not a value fitted to a data set.
inline bool levels_replicated(size_t levels, size_t rows) { return 2 * levels <= rows; }

/// A numeric column with at most this many distinct values is probed per value
/// (its values are its levels, like a categorical column's); with more, by a
/// line, a quadratic and quantile bins (screen.cpp, screen_family.cpp; the
/// same-information groups of screen_same.cpp follow the same rule).
constexpr size_t kOwnLevelsMax = 8;

struct Candidate {
  std::string name, kind;  ///< kind: column, derived, group
  bool categorical = false, test_level = false;
  std::vector<double> x;       ///< numeric value or level index per row; NaN = missing
  std::vector<std::string> levels;  ///< level names (categorical)
  /// A column that is a function of one of the model's inputs (constant within
  /// each pin, speed, direction or lubricant): that input's name.  Its effect
  /// cannot be told apart from the input's, so it counts as a base-model term.
  std::string confounded_with;
  /// kind "pair" (screen_pairs.cpp): the two columns whose centred product x is.
  std::vector<std::string> pair;
};

/// Every candidate: extra columns, optional columns, derived quantities
/// (average pressure Eq. 2.2 at the predicted outlet force, 1/R), the model's
/// own inputs and group identities (pin, test).
std::vector<Candidate> make_candidates(const Design& d, const std::vector<double>& pred);

struct CandidateResult {
  std::string name, kind;
  int dof = 0;
  double stat = 0, p_value = 1, cv_reduction = 0;
  bool significant = false;
  std::string permuted;  ///< "between tests", "within tests", "within and between tests" or "random effect (F test)"
  std::string decision;  ///< significant, not significant, undecided
  int n_perm = 0;        ///< permutations used (sequential)
  double sd_between = 0; ///< identity variables: between-test standard deviation [N]
  std::string probe;     ///< the probe of the family with the largest statistic
  int probe_dof = 0;     ///< that probe's own dof (dof above is the family's largest; 0: not a probe family)
  std::string cv_probe;  ///< the probe with the largest held-out gain
  std::string cv_probe_input;  ///< that probe's model input when it is a per-input one ("": an overall probe)
  /// When the strongest probe is a per-input one: the input and the group of
  /// its strongest one-group sub-probe (the cell an effect may be confined
  /// to; -1: none).
  std::string cell_by;
  int cell_group = -1;
  /// The model input of the strongest probe when it is a per-input one ("": an overall probe).
  std::string probe_input;
  /// A candidate with the same information as another (same_information): the
  /// candidate whose test it shares ("": its own test).
  std::string same_as;
};

/// The test a result reports: its own (its name) or the one it shares (same_as).
inline const std::string& test_of(const CandidateResult& c) { return c.same_as.empty() ? c.name : c.same_as; }
/// How many tests a ranking holds (the Bonferroni family: each shared test once).
inline size_t tests_in(const std::vector<CandidateResult>& rank) {
  size_t n = 0;
  for (const auto& c : rank) n += c.same_as.empty();
  return n;
}

/// What the screen knows of the model: the model's inputs as groups per row
/// (for the per-input probes) and dF/dmu per row (0 on rotating rows; empty:
/// no scaled probe).
struct ScreenContext {
  std::vector<std::pair<std::string, std::vector<int>>> modifiers;
  std::vector<double> mu_weight;
  /// The one-cell sub-probes (off by default: development only, see
  /// LoopOptions::cell_probes; off, the screen is exactly the one before them).
  bool one_cell = false;
  /// Per-input probes of test-level variables pooled over blocks (screen.cpp: centred_by).
  bool pooled_inputs = false;
  /// Threads screening candidates at once (results identical for any count).
  int threads = 1;
  /// The permutation test's bounded pass (screen_bound.cpp); false: the exact
  /// passes for every permutation (the same results: for tests).
  bool bounded_pass = true;
};

/// The pairs of numeric undeclared columns (kind "pair", name "a*b", x the
/// product of the centred columns; at most the first 16 columns are paired),
/// and the number of pair families they form (rows: when a pair has a row-level
/// column; tests: every pair; screen_pairs.cpp).
std::vector<Candidate> pair_candidates(const std::vector<Candidate>& cands);
int pair_families(const std::vector<Candidate>& pairs);
/// The pair families' screen: one result per family (its strongest pair), a
/// permutation test of the family's maximum against thr; cands holds the
/// pairs' columns (each product is made orthogonal to its two columns).
std::vector<CandidateResult> rank_pairs(const std::vector<Candidate>& pairs, const std::vector<Candidate>& cands,
                                        const std::vector<double>& resid,
                                        const Folds& f, int permutations, std::uint64_t seed, double thr,
                                        const ScreenContext* ctx);

/// Clopper-Pearson decision of a permutation p-value with k exceedances in b
/// permutations against thr: -1 not significant, +1 significant, 0 undecided.
int sequential_decision(int k, int b, double thr, double confidence = 1e-3);
/// The result of a sequential permutation test (ge exceedances in b
/// permutations, sequential_decision dec): n_perm, p = (1 + ge) / (1 + b), the
/// decision (at the cap, p <= thr is significant) and significant (with a
/// positive held-out gain).
void permutation_decision(CandidateResult& res, int ge, int b, int dec, double thr);

/// Candidates with the same information (screen_same.cpp): per candidate, the
/// index of the candidate whose test it shares (itself when none).  Two
/// candidates share one when their values are their own levels (categorical,
/// or numeric with at most 8 values) and split the rows with a finite value and
/// residual into the same groups; the leader is the group's first numeric
/// member in the candidates' order, else its first.
std::vector<int> same_information(const std::vector<Candidate>& cands, const std::vector<double>& resid);

/// Rank candidates; results sorted: significant first by CV reduction, then the
/// rest by p-value.  Candidates with the same information (same_information)
/// get one test, their leader's, reported for each with same_as set.
/// Significance: p <= alpha / (number of tests: candidates counted once per
/// same-information group, + pair families); with pairs (pair_candidates), one
/// result per pair family too.
std::vector<CandidateResult> rank_candidates(const std::vector<Candidate>& cands, const std::vector<double>& resid,
                                             const Folds& f, int permutations, std::uint64_t seed, double alpha,
                                             const ScreenContext* ctx = nullptr,
                                             const std::vector<Candidate>* pairs = nullptr);

}  // namespace drawbend::loop
