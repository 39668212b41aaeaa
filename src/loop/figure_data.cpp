// What a figure of many rows draws; see figure_data.hpp.
#include "loop/figure_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace drawbend::loop {

namespace {

// Mean and sample standard deviation of v over the rows idx, summed in the order given.
void mean_sd(const std::vector<double>& v, const std::vector<std::size_t>& idx, double& mean, double& sd) {
  double s = 0;
  for (std::size_t i : idx) s += v[i];
  mean = s / static_cast<double>(idx.size());
  double q = 0;
  for (std::size_t i : idx) q += (v[i] - mean) * (v[i] - mean);
  sd = idx.size() > 1 ? std::sqrt(q / static_cast<double>(idx.size() - 1)) : 0.0;
}

}  // namespace

std::vector<ResidualBin> residual_bins(const std::vector<double>& x, const std::vector<double>& before,
                                       const std::vector<double>& after, std::size_t max_values) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (std::isfinite(x[i]) && std::isfinite(before[i]) && std::isfinite(after[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::size_t distinct = 0;
  for (std::size_t k = 0; k < order.size(); ++k) distinct += (k == 0 || x[order[k]] != x[order[k - 1]]);
  // Each bin's rows, in row order within the bin (the sums' order).
  std::vector<std::vector<std::size_t>> bins;
  if (distinct <= max_values) {
    for (std::size_t k = 0; k < order.size(); ++k) {
      if (k == 0 || x[order[k]] != x[order[k - 1]]) bins.emplace_back();
      bins.back().push_back(order[k]);
    }
  } else {
    for (std::size_t b = 0; b < kFigureBins; ++b) {
      const std::size_t lo = order.size() * b / kFigureBins, hi = order.size() * (b + 1) / kFigureBins;
      bins.emplace_back(order.begin() + static_cast<std::ptrdiff_t>(lo), order.begin() + static_cast<std::ptrdiff_t>(hi));
    }
  }
  std::vector<ResidualBin> out;
  for (auto& idx : bins) {
    if (idx.empty()) continue;
    std::sort(idx.begin(), idx.end());
    ResidualBin b;
    b.rows = idx.size();
    double sd_x = 0;
    mean_sd(x, idx, b.x, sd_x);
    mean_sd(before, idx, b.before_mean, b.before_sd);
    mean_sd(after, idx, b.after_mean, b.after_sd);
    out.push_back(b);
  }
  return out;
}

std::vector<PlotPoint> distinct_points(const std::vector<double>& u, const std::vector<double>& v, int cells) {
  double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
  for (std::size_t i = 0; i < u.size(); ++i)
    if (std::isfinite(u[i]) && std::isfinite(v[i]))
      u0 = std::min(u0, u[i]), u1 = std::max(u1, u[i]), v0 = std::min(v0, v[i]), v1 = std::max(v1, v[i]);
  // The cell of a value: 0 for a range of zero width.
  auto cell = [cells](double a, double lo, double hi) -> std::int64_t {
    return hi > lo ? std::llround((a - lo) / (hi - lo) * cells) : 0;
  };
  std::vector<PlotPoint> out;
  std::unordered_map<std::int64_t, std::size_t> seen;
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!(std::isfinite(u[i]) && std::isfinite(v[i]))) continue;
    const std::int64_t key = cell(u[i], u0, u1) * (cells + 1) + cell(v[i], v0, v1);
    const auto [it, fresh] = seen.emplace(key, out.size());
    if (fresh) out.push_back({u[i], v[i], 0});
    ++out[it->second].rows;
  }
  return out;
}

}  // namespace drawbend::loop
