// Candidates with the same information, tested once (issue 50, h50-same).
//
// On every draw-bend data set `pin`, `pin_diameter_mm` and `inv_R_per_mm` take
// one value per pin: the same levels on the same rows.  Each used to get its
// own permutation test with its own random stream and its own place in the
// Bonferroni family, so three Monte Carlo estimates of one p decided a step by
// which of them happened to fall below the threshold (on the thesis data:
// 0.00465, 0.00525 and 0.0058 against 0.005 in round 2; one stream for all
// three gave 0.0052 each), and the family's threshold counted one hypothesis
// three times.
//
// Same information: two candidates whose values are their own levels
// (categorical, or numeric with at most kOwnLevelsMax distinct values, where the screen's
// probe family is built on the levels; screen_family.cpp) and that split the
// screened rows (a finite value and a finite residual) into the same groups,
// with the same test_level flag.  Identities (random effects, F test) and
// pairs are never grouped.  The group is one hypothesis, "the residual depends
// on these levels", and gets one test: the probe family of its leader (the
// first numeric member in the candidates' order, whose family holds the
// levels probes and the linear ones, else the first member), one random
// stream, one place in the Bonferroni family.  Each member is reported with
// the leader's result and still gets its own forms (the held-out error of its
// forms names the step, as between any contenders).
#include <cmath>
#include <unordered_map>

#include "loop/candidates.hpp"
#include "loop/effects.hpp"

namespace drawbend::loop {

namespace {

struct CodeHash {
  size_t operator()(const std::vector<int>& v) const noexcept {
    size_t h = 1469598103934665603ULL;
    for (int x : v) h = (h ^ static_cast<size_t>(x + 2)) * 1099511628211ULL;
    return h;
  }
};

// Each row's level by first appearance (-1: not screened), or empty when the
// candidate is not probed per level (a numeric column with more than
// kOwnLevelsMax values).
std::vector<int> level_codes(const Candidate& c, const std::vector<double>& resid) {
  std::vector<int> code(resid.size(), -1);
  std::unordered_map<double, int> seen;
  for (size_t i = 0; i < resid.size(); ++i) {
    if (!std::isfinite(c.x[i]) || !std::isfinite(resid[i])) continue;
    const double v = c.x[i] == 0 ? 0.0 : c.x[i];  // -0 and +0 are one value
    auto [it, fresh] = seen.try_emplace(v, static_cast<int>(seen.size()));
    if (fresh && !c.categorical && seen.size() > kOwnLevelsMax) return {};
    code[i] = it->second;
  }
  if (seen.size() < 2) return {};  // constant: p = 1 whatever its group
  return code;
}

}  // namespace

std::vector<int> same_information(const std::vector<Candidate>& cands, const std::vector<double>& resid) {
  std::vector<int> leader(cands.size());
  for (size_t i = 0; i < cands.size(); ++i) leader[i] = static_cast<int>(i);
  // Members of each partition, in the candidates' order.
  std::unordered_map<std::vector<int>, std::vector<int>, CodeHash> groups[2];
  for (size_t i = 0; i < cands.size(); ++i) {
    const Candidate& c = cands[i];
    if (is_identity(c.name) || c.kind == "pair") continue;
    std::vector<int> code = level_codes(c, resid);
    if (code.empty()) continue;
    auto [it, fresh] = groups[c.test_level ? 1 : 0].try_emplace(std::move(code));
    it->second.push_back(static_cast<int>(i));
  }
  for (auto& g : groups)
    for (auto& [code, members] : g) {
      if (members.size() < 2) continue;
      int lead = members.front();
      for (int m : members)
        if (!cands[m].categorical) {
          lead = m;
          break;
        }
      for (int m : members) leader[m] = lead;
    }
  return leader;
}

}  // namespace drawbend::loop
