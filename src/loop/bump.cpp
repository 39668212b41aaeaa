// A local bump of a column as a form; see bump.hpp.
#include "loop/bump.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace drawbend::loop {

double bump_value(double x, double c, double w) {
  const double u = (x - c) / w;
  return std::exp(-0.5 * u * u);
}

namespace {

// b centred and scaled to unit standard deviation over the rows (sums in row
// order), all zeros when it does not vary: bump_basis's and step_basis's.
std::vector<double> standardised(std::vector<double> b) {
  const double n = static_cast<double>(std::max<size_t>(1, b.size()));
  double m = 0;
  for (double v : b) m += v / n;
  double q = 0;
  for (double& v : b) {
    v -= m;
    q += v * v / n;
  }
  const double sd = q > 1e-24 ? std::sqrt(q) : 0.0;
  for (double& v : b) v = sd > 0 ? v / sd : 0.0;
  return b;
}

// Per distinct value of x: its rows and their sum of r (ascending x), over
// the rows scan_bump and scan_step read; N and R: all of them.
std::map<double, std::pair<double, double>> per_value(const std::vector<double>& x, const std::vector<double>& r,
                                                      const std::vector<char>& use, double& N, double& R) {
  std::map<double, std::pair<double, double>> per;  // x -> (rows, sum of r)
  N = 0, R = 0;
  for (size_t i = 0; i < x.size() && i < r.size(); ++i) {
    if ((!use.empty() && (i >= use.size() || !use[i])) || !std::isfinite(x[i]) || !std::isfinite(r[i])) continue;
    auto& p = per[x[i]];
    p.first += 1, p.second += r[i];
    N += 1, R += r[i];
  }
  return per;
}

}  // namespace

std::vector<double> bump_basis(const std::vector<double>& x, double c, double w) {
  std::vector<double> b(x.size());
  for (size_t i = 0; i < x.size(); ++i) b[i] = bump_value(x[i], c, w);
  return standardised(std::move(b));
}

std::vector<double> step_basis(const std::vector<double>& x, double c) {
  std::vector<double> b(x.size());
  for (size_t i = 0; i < x.size(); ++i) b[i] = x[i] > c ? 1.0 : 0.0;
  return standardised(std::move(b));
}

std::optional<Step1> scan_step(const std::vector<double>& x, const std::vector<double>& r,
                               const std::vector<char>& use) {
  double N = 0, R = 0;
  const auto per = per_value(x, r, use, N, R);
  if (per.size() < static_cast<size_t>(kBumpMinValues)) return std::nullopt;
  std::vector<double> v, m, s;
  for (const auto& [xv, p] : per) v.push_back(xv), m.push_back(p.first), s.push_back(p.second);
  const double need = std::max<double>(kBumpMinRows, std::floor(N / kBumpRowShare));
  std::optional<Step1> best;
  double below = 0, sum_below = 0;  // rows and sum of r at or below v[j]
  for (size_t j = 0; j + 1 < v.size(); ++j) {
    below += m[j], sum_below += s[j];
    const double n1 = N - below, s1 = R - sum_below;  // above the threshold
    if (j < 1 || j + 2 >= v.size() || below < need || n1 < need) continue;  // 2 values, `need` rows a side
    const double sxx = n1 * (1 - n1 / N), sxr = s1 - n1 * R / N;
    if (!(sxx > 1e-12)) continue;
    const double ex = sxr * sxr / sxx;
    if (ex > 0 && (!best || ex > best->explained)) best = Step1{0.5 * (v[j] + v[j + 1]), ex};
  }
  return best;
}

std::optional<Bump> scan_bump(const std::vector<double>& x, const std::vector<double>& r,
                              const std::vector<char>& use) {
  double N = 0, R = 0;
  const auto per = per_value(x, r, use, N, R);  // per distinct value of x: its rows and their sum of r
  if (per.size() < static_cast<size_t>(kBumpMinValues)) return std::nullopt;
  std::vector<double> v, m, s;
  for (const auto& [xv, p] : per) v.push_back(xv), m.push_back(p.first), s.push_back(p.second);
  const double lo = v.front(), hi = v.back(), range = hi - lo;
  if (!(range > 0)) return std::nullopt;
  // Support from the cumulative rows and distinct values below a point (v ascending).
  std::vector<double> cum(v.size() + 1, 0.0);
  for (size_t j = 0; j < v.size(); ++j) cum[j + 1] = cum[j] + m[j];
  const double need = std::max<double>(kBumpMinRows, std::floor(N / kBumpRowShare));
  std::optional<Bump> best;
  std::vector<double> b(v.size());
  for (int k = 0; k < kBumpWidths; ++k) {
    const double w = range * kBumpWidthMin * std::pow(kBumpWidthMax / kBumpWidthMin, k / (kBumpWidths - 1.0));
    for (int j = 0; j < kBumpCentres; ++j) {
      const double c = lo + range * j / (kBumpCentres - 1.0);
      const size_t a = std::lower_bound(v.begin(), v.end(), c - kBumpReach * w) - v.begin();
      const size_t e = std::upper_bound(v.begin(), v.end(), c + kBumpReach * w) - v.begin();
      if (e < a + kBumpMinValues || cum[e] - cum[a] < need) continue;  // too few values or rows near c
      double sb = 0, sbb = 0, sbr = 0;
      for (size_t t = 0; t < v.size(); ++t) {
        const double bv = bump_value(v[t], c, w);
        sb += m[t] * bv, sbb += m[t] * bv * bv, sbr += s[t] * bv;
      }
      const double sxx = sbb - sb * sb / N, sxr = sbr - sb * R / N;
      if (!(sxx > 1e-12 * std::max(1.0, sbb))) continue;
      const double ex = sxr * sxr / sxx;
      if (ex > 0 && (!best || ex > best->explained)) best = Bump{c, w, ex};
    }
  }
  return best;
}

}  // namespace drawbend::loop
