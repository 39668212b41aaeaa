// Which cell the one-cell forms are tried in (cells.hpp).
#include "loop/cells.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace drawbend::loop {

int worst_group(const Design& d, const CvResult& cur, const std::string& by) {
  int n = 0;
  const std::vector<int> g = d.groups(by, &n);
  std::vector<double> ss(n, 0.0), cnt(n, 0.0);
  for (size_t i = 0; i < g.size(); ++i)
    if (!d.rows[i].rotating && i < cur.resid.size() && std::isfinite(cur.resid[i]))
      ss[g[i]] += cur.resid[i] * cur.resid[i], cnt[g[i]] += 1;
  int best = 0;
  for (int k = 0; k < n; ++k)
    if (cnt[k] > 0 && (cnt[best] == 0 || ss[k] / cnt[k] > ss[best] / cnt[best])) best = k;
  return best;
}

std::optional<Split> scan_split(const Design& d, const CvResult& cur, const std::vector<double>& x,
                                bool categorical, const std::string& input) {
  if (input != "speed_mm_s" && input != "direction_deg") return std::nullopt;
  struct Pt {
    double v, x, r;
  };
  std::vector<Pt> pts;  // fixed-pin rows with a residual and a value, in row order
  for (size_t i = 0; i < d.rows.size() && i < cur.resid.size() && i < x.size(); ++i)
    if (!d.rows[i].rotating && std::isfinite(cur.resid[i]) && std::isfinite(x[i]))
      pts.push_back({input == "speed_mm_s" ? d.data->rows[i].speed_mm_s : d.data->rows[i].direction_deg, x[i],
                     cur.resid[i]});
  std::stable_sort(pts.begin(), pts.end(), [](const Pt& a, const Pt& b) { return a.v < b.v; });
  const size_t n = pts.size(), edge = std::max<size_t>(10, n / 10);
  std::set<double> distinct;
  for (const Pt& p : pts) distinct.insert(p.v);
  if (distinct.size() <= 6 || n < 2 * edge) return std::nullopt;
  // Running sums below the threshold (rows [0, k) in v order); above = all - below.
  // Numeric: sums of 1, x, r, x^2, x r; categorical: per level, sum r and count.
  struct Sums {
    double m = 0, x = 0, r = 0, xx = 0, xr = 0;
    std::map<double, std::pair<double, double>> lv;
    void add(const Pt& p, double s) {
      m += s, x += s * p.x, r += s * p.r, xx += s * p.x * p.x, xr += s * p.x * p.r;
      auto& l = lv[p.x];
      l.first += s * p.r, l.second += s;
    }
  };
  // The sum of squares x explains of r on one side (numeric: the slope's; categorical: between levels).
  auto explained = [&](const Sums& q) {
    if (!(q.m > 1)) return 0.0;
    if (categorical) {
      double ss = 0;
      for (const auto& [l, sc] : q.lv)
        if (sc.second > 0.5) ss += sc.first * sc.first / sc.second;
      return ss - q.r * q.r / q.m;
    }
    const double sxx = q.xx - q.x * q.x / q.m, sxr = q.xr - q.x * q.r / q.m;
    return sxx > 1e-12 * std::max(1.0, q.xx) ? sxr * sxr / sxx : 0.0;
  };
  Sums below, above;
  for (const Pt& p : pts) above.add(p, 1.0);
  double best = 0, t_best = std::nan("");
  int side_best = 0;
  for (size_t k = 0; k + edge <= n; ++k) {
    if (k >= edge && pts[k].v > pts[k - 1].v) {  // a threshold between two distinct values
      const double e0 = explained(below), e1 = explained(above);
      if (e0 > best) best = e0, t_best = 0.5 * (pts[k - 1].v + pts[k].v), side_best = 0;
      if (e1 > best) best = e1, t_best = 0.5 * (pts[k - 1].v + pts[k].v), side_best = 1;
    }
    below.add(pts[k], 1.0), above.add(pts[k], -1.0);
  }
  if (std::isnan(t_best)) return std::nullopt;
  return Split{t_best, side_best};
}

}  // namespace drawbend::loop
