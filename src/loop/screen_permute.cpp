// The permutations of one candidate's screen (see screen_candidate.hpp): the
// pilot calibration of the probes' scales, the observed statistic and the
// sequential permutation test of the family's maximum.  The inner loops are
// the loop's hot spot: kLanes permutations per pass over the units, the same
// draws and swaps, sums in the same order as one permutation alone.
#include <algorithm>
#include <cmath>

#include "loop/screen_candidate.hpp"

namespace drawbend::loop::detail {

namespace {

// Pilot permutations per candidate for the probes' calibration scales: the
// mean explained sum of squares of each probe (its scale, to 1 / sqrt(dof
// kPilot / 2) relative, 14 % at one dof) and, for a one-group sub-probe, its
// variance (the moment-matched dof).  The test is exact for any scales (they
// only share the family's power among its probes).  200 until 2026-12-07;
// 100 halves the pilot, which was a sixth of a 50,000-row file's time (issue
// 50 item 6; heldout_record.md, h50-pilot).
constexpr int kPilot = 100;

}  // namespace

// Sub-probe values of every probe: vals[off[j] + k] is sub-probe k of probe j
// (of L permutations side by side: lane i at lvals[(off[j] + k) L + i]).
void CandidateScreen::set_offsets() {
  off.assign(probes.size() + 1, 0);
  for (size_t j = 0; j < probes.size(); ++j) off[j + 1] = off[j] + probes[j].nsub();
  vals.assign(off.back(), 0.0);
  lvals.assign(off.back() * kLanes, 0.0);
}

// A group of consecutive units (rows of a test, in file order) is shuffled
// in place without reading its unit list: the same draws, the same swaps.
// The draws are 32 bits (Mt64Halves: two per number of the 64-bit stream;
// 64-bit draws until 2026-12-07), reduced by FastMod32.
// Its first unit and size in flat arrays (read for every permutation; the
// groups' own lists are scattered over the heap and missed the cache).
void CandidateScreen::flat_groups() {
  size_t kmax = 1;
  for (const auto& g : groups) kmax = std::max(kmax, g.size());
  for (const auto& bg : bgroups) kmax = std::max(kmax, bg.size());
  mod = FastMod32(kmax);  // mod(rng(), k) == rng() % k, without the division
  size_t m = 1;  // the cuts padded with +inf to 2^m - 1 (fill_unit_values)
  while (m < cutz.size() + 1) m *= 2;
  cutp = cutz;
  cutp.resize(m - 1, INFINITY);
  run.assign(groups.size(), 1);
  gfirst.assign(groups.size(), 0), gsize.assign(groups.size(), 0);
  for (size_t gi = 0; gi < groups.size(); ++gi) {
    gfirst[gi] = groups[gi][0], gsize[gi] = static_cast<int>(groups[gi].size());
    for (size_t k = 1; k < groups[gi].size(); ++k) run[gi] = run[gi] && groups[gi][k] == groups[gi][0] + static_cast<int>(k);
  }
}

// Fisher-Yates within each permutation group.
inline void CandidateScreen::shuffle(std::vector<int>& p, Mt64Halves& r) const {
  for (size_t gi = 0; gi < groups.size(); ++gi) {
    if (run[gi]) {  // the draws in blocks of the stream's buffer (the same numbers)
      int* q = p.data() + gfirst[gi];
      // The block's swap targets first, then its swaps: the reductions (a
      // multiply chain each) no longer wait on the swaps' loads and stores,
      // and the swaps' addresses are ready when they run.  The same draws,
      // the same swaps in the same order.
      std::uint32_t j[Mt64Halves::kBlock];
      for (size_t k = gsize[gi]; k > 1;) {
        const size_t n = std::min(r.available(), k - 1);
        const std::uint32_t* y = r.take(n);
        for (size_t t = 0; t < n; ++t) j[t] = static_cast<std::uint32_t>(mod(y[t], k - t));
        for (size_t t = 0; t < n; ++t, --k) std::swap(q[k - 1], q[j[t]]);
      }
    } else {
      const auto& g = groups[gi];
      for (size_t k = g.size(); k > 1; --k) std::swap(p[g[k - 1]], p[g[mod(r(), k)]]);
    }
  }
}

// Lane j of a permuted pass: unit u takes unit p[u]'s value (p permutes
// within tests); two-level, the test means are permuted as well (tp, drawn
// from r after the within-test shuffle) and the bin recomputed.
inline void CandidateScreen::fill_unit_values(const std::vector<int>& p, std::vector<double>& qz,
                                              std::vector<int>& ql, int j, Mt64Halves& r) {
  if (!two_level) {
    for (size_t u = 0; u < U; ++u) qz[u * kLanes + j] = xz[p[u]], ql[u * kLanes + j] = xl[p[u]];
    return;
  }
  for (const auto& bg : bgroups)
    for (size_t k = bg.size(); k > 1; --k) std::swap(tp[bg[k - 1]], tp[bg[mod(r(), k)]]);
  // The bin: the count of the cuts c with !(v < c), a prefix of the ascending
  // cuts (of all of them for a NaN v), found by halving over the cuts padded
  // with +inf to 2^m - 1 (cutp: no finite v passes a pad; a NaN passes all, so
  // the count is capped at the cuts'): m compares per unit, not one per cut.
  const double* cut = cutp.data();
  const int ncut = static_cast<int>(cutz.size()), top = static_cast<int>(cutp.size() + 1) / 2;
  for (size_t u = 0; u < U; ++u) {
    const double v = gz[tp[ug[u]]] + (xz[p[u]] - gz[ug[u]]);
    qz[u * kLanes + j] = v;
    int l = 0;
    for (int h = top; h > 0; h >>= 1) l += !(v < cut[l + h - 1]) ? h : 0;
    ql[u * kLanes + j] = std::min(l, ncut);
  }
}

// Lanes past the last permutation of a pass repeat lane 0 (their values unused).
inline void CandidateScreen::fill_lanes(std::vector<double>& a, std::vector<int>& b, int used) const {
  if (used == kLanes) return;
  for (size_t u = 0; u < U; ++u)
    for (int i = used; i < kLanes; ++i) a[u * kLanes + i] = a[u * kLanes], b[u * kLanes + i] = b[u * kLanes];
}

// Every probe's sub-probe values for kLanes permutations at once (unit values
// interleaved by lane); which = 0: the probes outside the bounded pass only,
// 1: those in it only (bfast, screen_bound.cpp), -1: all.
inline void CandidateScreen::eval_lanes(const std::vector<double>& a, const std::vector<int>& b, int which) {
  for (size_t j = 0; j < probes.size(); ++j)
    if (which < 0 || (bfast.size() == probes.size() && bfast[j] == which))
      probes[j].eval<kLanes>(a.data(), b.data(), &lvals[off[j] * kLanes]);
}

// The statistic of lane i: the same comparisons in the same order as stat
// (bounded_too false: of the probes outside the bounded pass only).
inline double CandidateScreen::lane_stat(int i, bool bounded_too) const {
  double t = -INFINITY;
  for (size_t j = 0; j < probes.size(); ++j)
    for (int k = 0; k < probes[j].nsub(); ++k) {
      if (!bounded_too && bfast[j]) continue;
      if (probes[j].dof[k] <= 0) continue;
      const double v = probe_z(probes[j], k, lvals[(off[j] + k) * kLanes + i]);
      if (v > t) t = v;
    }
  return t;
}

// Statistic: the family's largest probe on a common scale.  Each probe's
// explained sum of squares is X = ESS / scale (calibrated below), about
// chi^2 with the probe's dof on null data; the Wilson-Hilferty cube root
// maps it to a normal deviate, so a probe
// of 1 dof and one of 8 compete by how surprising each is, not by the
// explained fraction per dof (which buried every many-level probe).  The
// permutation test calibrates the maximum, so the transform only decides
// how the probes share the family's power.
double CandidateScreen::stat(const std::vector<double>& a, const std::vector<int>& b, int* best, int* best_sub) {
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
}

// Calibration: ESS of each probe under a pilot sample of permutations (its
// own random stream, so the test's permutations stay independent of it).
// The permutation distribution is the same whichever permutation the data
// are, so constants taken from it keep the test exact.  scale = mean ESS /
// dof puts every probe on the chi^2(dof) scale even when whole tests are
// the units (a test's rows share its scatter, so ESS / s^2 of the rows
// would inflate with the dof); a probe whose ESS does not change under
// permutation (a variable constant within every permutation group) is
// dropped (a sub-probe so: its dof set to 0).
void CandidateScreen::calibrate(std::uint64_t seed, size_t ci) {
  Mt64Halves prng(seed + 7919 * ci + 104729);
  std::vector<int> pp(U);
  for (size_t u = 0; u < U; ++u) pp[u] = static_cast<int>(u);
  std::vector<double> qz(U * kLanes);
  std::vector<int> ql(U * kLanes);
  const int P = kPilot;
  std::vector<double> m1(off.back(), 0.0), m2(off.back(), 0.0);
  for (int j0 = 0; j0 < P; j0 += kLanes) {
    const int used = std::min(kLanes, P - j0);
    for (int i = 0; i < used; ++i) {
      shuffle(pp, prng);
      fill_unit_values(pp, qz, ql, i, prng);
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
  set_offsets();
}

// The observed statistic T, its probe, and the strongest one-group sub-probe
// of the best probe's input (the cell the forms try an effect confined to),
// when the best probe is per input.
double CandidateScreen::observed(CandidateResult& res) {
  int best = 0, best_sub = 0;
  const double T = stat(xz, xl, &best, &best_sub);
  res.stat = vals[off[best] + best_sub];
  res.probe = probes[best].sub_label(best_sub);
  res.probe_dof = probes[best].dof[best_sub];
  res.probe_input = probes[best].input;
  if (probes[best].cells) {
    double zb = -INFINITY;
    for (int k = 1; k < probes[best].nsub(); ++k)
      if (probes[best].dof[k] > 0) {
        const double v = probe_z(probes[best], k, vals[off[best] + k]);
        if (v > zb) zb = v, res.cell_group = k - 1, res.cell_by = probes[best].input;
      }
  }
  return T;
}

// Sequential permutation test of T: batches of 100, 200, ... permutations
// until the Clopper-Pearson decision is made or the cap is reached.
void CandidateScreen::permutation_test(CandidateResult& res, double T, std::uint64_t seed, size_t ci,
                                       int permutations, double thr) {
  Mt64Halves rng(seed + 7919 * ci);
  int ge = 0, b = 0, dec = 0;
  std::vector<int> perm(U);
  for (size_t u = 0; u < U; ++u) perm[u] = static_cast<int>(u);
  std::vector<double> pz(U * kLanes);
  std::vector<int> pl(U * kLanes);
  const int cap = std::max(1, permutations);
  const double Tp = T - 1e-12 * std::max(1.0, std::abs(T));
  // The bounded pass (screen_bound.cpp): a lane whose bound lies below Tcut cannot count.
  if (!ctx || ctx->bounded_pass) setup_bounds();
  std::vector<int> lperm[kLanes];  // the bounded pass: each lane's permutation
  const bool exact_probes = std::count(bfast.begin(), bfast.end(), 0) > 0;  // probes outside the bounded pass
  const double Tcut = Tp - 1e-8 * std::max(1.0, std::abs(Tp));
  int nbound = 0, nnear = 0;  // permutations through the bounded pass, and those near T
  for (int batch = 100; b < cap; batch = std::min(cap - b, 2 * batch)) {
    for (int j = 0; j < batch; j += kLanes) {  // kLanes permutations per pass over the units
      const int used = std::min(kLanes, batch - j);
      // The bounded pass reads each lane's permutation itself; the lanes' unit
      // values (pz, pl) are gathered only for the exact passes that need them.
      const bool lanes_only = bounded;
      for (int i = 0; i < used; ++i) {
        shuffle(perm, rng);
        if (lanes_only) lperm[i] = perm;
        else fill_unit_values(perm, pz, pl, i, rng);
      }
      if (!lanes_only) {
        fill_lanes(pz, pl, used);
        eval_lanes(pz, pl);
        for (int i = 0; i < used; ++i)
          if (lane_stat(i) >= Tp) ++ge;
      } else {
        for (int i = used; i < kLanes; ++i) lperm[i] = lperm[0];
        bool filled = false;
        auto fill = [&]() {  // (bounded: never two-level, so no draws here)
          if (filled) return;
          for (int i = 0; i < used; ++i) fill_unit_values(lperm[i], pz, pl, i, rng);
          fill_lanes(pz, pl, used);
          filled = true;
        };
        if (exact_probes) fill(), eval_lanes(pz, pl, 0);
        double zb[kLanes];
        bounded_max(lperm, zb);
        bool near[kLanes] = {}, any = false;
        for (int i = 0; i < used; ++i) near[i] = !(zb[i] < Tcut), any = any || near[i], nnear += near[i];
        // Most permutations near T (a candidate far from significance): the
        // bounded pass only adds work, the exact passes alone from here on.
        nbound += used;
        if (nbound >= 40 && 2 * nnear > nbound) bounded = false;
        if (any) fill(), eval_lanes(pz, pl, 1);
        for (int i = 0; i < used; ++i)
          if (lane_stat(i, near[i]) >= Tp) ++ge;
      }
      b += used;
    }
    dec = sequential_decision(ge, b, thr);
    if (dec != 0) break;
  }
  permutation_decision(res, ge, b, dec, thr);
}

}  // namespace drawbend::loop::detail
