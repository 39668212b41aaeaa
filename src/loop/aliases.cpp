// Columns that explain the same structure as a step; see aliases.hpp.
#include "loop/aliases.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/csv.hpp"
#include "loop/effects.hpp"
#include "loop/forms.hpp"
#include "loop/loop.hpp"

namespace drawbend::loop {

namespace {

// Group index per row of y (-1: skipped), or empty when y has too many levels.
std::vector<int> groups_of(const Candidate& y, const std::vector<char>& use) {
  const size_t n = y.x.size();
  std::vector<int> g(n, -1);
  if (y.categorical) {
    if (y.levels.size() > static_cast<size_t>(kAliasMaxLevels)) return {};
    for (size_t i = 0; i < n; ++i)
      if (use[i]) g[i] = static_cast<int>(y.x[i]);
    return g;
  }
  std::map<double, int> count;  // distinct value -> rows
  for (size_t i = 0; i < n; ++i)
    if (use[i]) count[y.x[i]]++;
  std::map<double, int> bin;
  if (count.size() <= 8) {
    int k = 0;
    for (const auto& [v, c] : count) bin[v] = k++;
  } else {
    // 8 quantile bins by rank; a value's rows stay in one bin.
    int total = 0;
    for (const auto& [v, c] : count) total += c;
    int seen = 0;
    for (const auto& [v, c] : count) {
      bin[v] = std::min(7, 8 * seen / total);
      seen += c;
    }
  }
  for (size_t i = 0; i < n; ++i)
    if (use[i]) g[i] = bin.at(y.x[i]);
  return g;
}

}  // namespace

double explained_share(const std::vector<double>& e, const std::vector<int>& block, const Candidate& y) {
  const size_t n = e.size();
  if (y.x.size() != n || block.size() != n) return 0;
  std::vector<char> use(n, 0);
  for (size_t i = 0; i < n; ++i) use[i] = std::isfinite(e[i]) && std::isfinite(y.x[i]);
  // e centred per block (sums in row order: deterministic).
  std::map<int, std::pair<double, int>> bm;
  for (size_t i = 0; i < n; ++i)
    if (use[i]) bm[block[i]].first += e[i], bm[block[i]].second++;
  std::vector<double> c(n, 0.0);
  for (size_t i = 0; i < n; ++i)
    if (use[i]) c[i] = e[i] - bm[block[i]].first / bm[block[i]].second;
  const std::vector<int> g = groups_of(y, use);
  if (g.empty()) return 0;
  std::map<int, std::pair<double, int>> gm;
  double sst = 0;
  for (size_t i = 0; i < n; ++i)
    if (use[i]) gm[g[i]].first += c[i], gm[g[i]].second++, sst += c[i] * c[i];
  if (gm.size() < 2 || !(sst > 0)) return 0;
  double ssw = 0;
  for (size_t i = 0; i < n; ++i)
    if (use[i]) {
      const double r = c[i] - gm[g[i]].first / gm[g[i]].second;
      ssw += r * r;
    }
  return std::max(0.0, 1 - ssw / sst);
}

std::vector<AliasColumn> alias_columns(const std::vector<Candidate>& cands, const std::vector<double>& e,
                                       const std::vector<int>& block, const std::string& x,
                                       const std::vector<std::string>& skip, double min_share, int max) {
  std::vector<AliasColumn> out;
  for (const auto& y : cands) {
    if (y.kind != "column" || is_identity(y.name) || !y.confounded_with.empty() || y.name == x) continue;
    if (std::find(skip.begin(), skip.end(), y.name) != skip.end()) continue;
    const double s = explained_share(e, block, y);
    if (s >= min_share) out.push_back({y.name, s});
  }
  std::sort(out.begin(), out.end(), [](const AliasColumn& a, const AliasColumn& b) {
    return a.share != b.share ? a.share > b.share : a.name < b.name;
  });
  if (static_cast<int>(out.size()) > max) out.resize(max);
  return out;
}

double prediction_rms_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double ss = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (std::isfinite(a[i]) && std::isfinite(b[i])) ss += (a[i] - b[i]) * (a[i] - b[i]), ++n;
  return n ? std::sqrt(ss / static_cast<double>(n)) : std::nan("");
}

bool takes_the_step(const FormTrial& a, const CvResult& held, int held_q) {
  const double dp = prediction_rms_diff(a.cv.pred, held.pred);
  if (dp <= kSameModelShare * held.rms) return a.q < held_q;  // false for NaN: compared by RMS below
  return a.cv.rms < held.rms;
}

void name_alikes(Step& s, const std::vector<std::pair<std::string, CvResult>>& kept, const CvResult& best,
                 const Folds& f, double min_effect_N) {
  std::vector<std::string> same;  // names of same_effect_as, appended after aliased_with's
  for (const auto& [name, cv] : kept) {
    if (name == s.variable) continue;
    if (cv.rms * cv.rms - best.rms * best.rms <= mse_diff_se(cv, best, f)) {
      s.aliased_with.push_back(name + " (held-out RMS " + fmt(cv.rms, 4) + " N)");
      s.alike_names.push_back(name);
      continue;
    }
    const double dp = prediction_rms_diff(cv.pred, best.pred);
    if (dp <= min_effect_N) {  // false for NaN
      s.same_effect_as.push_back(name + " (held-out RMS " + fmt(cv.rms, 4) + " N; predictions within " + fmt(dp, 3) +
                                 " N RMS of the step's, the minimum effect " + fmt(min_effect_N, 3) + " N)");
      same.push_back(name);
    }
  }
  s.alike_names.insert(s.alike_names.end(), same.begin(), same.end());
}

}  // namespace drawbend::loop
