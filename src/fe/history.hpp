#pragma once
// A scalar time history: piecewise linear through (t_i, v_i), constant beyond
// the ends.  Units follow the quantity (mm/s, N, rad/s, ...); time in s.
#include <stdexcept>
#include <vector>

namespace drawbend::fe {

struct History {
  std::vector<double> t{0.0}, v{0.0};

  static History constant(double value) { return {{0.0}, {value}}; }
  double operator()(double time) const {
    if (time <= t.front()) return v.front();
    if (time >= t.back()) return v.back();
    std::size_t i = 1;
    while (t[i] < time) ++i;
    const double s = (time - t[i - 1]) / (t[i] - t[i - 1]);
    return v[i - 1] + s * (v[i] - v[i - 1]);
  }
  void validate(const char* what) const {
    if (t.empty() || t.size() != v.size()) throw std::invalid_argument(std::string(what) + ": history needs equal, non-empty t and v lists");
    for (std::size_t i = 1; i < t.size(); ++i)
      if (!(t[i] > t[i - 1])) throw std::invalid_argument(std::string(what) + ": history times must increase");
  }
};


}  // namespace drawbend::fe
