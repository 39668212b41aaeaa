#include "analysis/linear_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/csv.hpp"

namespace drawbend::analysis {

Evaluation evaluate(const LinearFit& fit, double x) {
  Evaluation e;
  e.value = fit(x);
  e.range_known = fit.range.has_value();
  if (fit.range && !fit.range->contains(x)) {
    e.extrapolated = true;
    const Range& r = *fit.range;
    e.note = fit.label + ": F_back = " + fmt(x) + " N is outside the fit range " +
             (r.empty() ? std::string("(empty intersection)") : fmt(r.lo) + "-" + fmt(r.hi) + " N");
  }
  return e;
}

LinearFit subtract(const LinearFit& a, const LinearFit& b, const std::string& label) {
  LinearFit d;
  d.slope = a.slope - b.slope;
  d.intercept = a.intercept - b.intercept;
  if (a.range && b.range)
    d.range = Range{std::max(a.range->lo, b.range->lo), std::min(a.range->hi, b.range->hi)};
  else if (a.range)
    d.range = a.range;
  else if (b.range)
    d.range = b.range;
  d.label = label.empty() ? "(" + a.label + ") - (" + b.label + ")" : label;
  return d;
}

LinearFit fit_line(const std::vector<double>& x, const std::vector<double>& y, const std::string& label) {
  if (x.size() != y.size()) throw std::invalid_argument("fit_line: x and y differ in length");
  if (x.size() < 2) throw std::invalid_argument("fit_line: need at least two points");
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
  }
  const double mx = sx / n, my = sy / n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (sxx == 0.0) throw std::invalid_argument("fit_line: all x values are equal");
  LinearFit f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  f.range = Range{*std::min_element(x.begin(), x.end()), *std::max_element(x.begin(), x.end())};
  f.label = label;
  return f;
}

}  // namespace drawbend::analysis
