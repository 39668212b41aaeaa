#pragma once
// Linear force fits F = slope * F_back + intercept (thesis Tables 5.3, 5.5-5.12)
// and their arithmetic.  Every fit carries the back-tension range over which it
// was measured; arithmetic intersects the ranges, and every evaluation says
// whether it extrapolates.  Forces in N.
#include <optional>
#include <string>
#include <vector>

namespace drawbend::analysis {

struct Range {
  double lo = 0.0, hi = 0.0;
  bool empty() const { return hi < lo; }
  bool contains(double x) const { return !empty() && x >= lo && x <= hi; }
};

struct LinearFit {
  double slope = 0.0;
  double intercept = 0.0;
  std::optional<Range> range;  ///< stated validity range; nullopt = not stated
  std::string label;           ///< provenance, e.g. "Table 5.5 RD 6.35 mm/s 12.7 mm"

  double operator()(double x) const { return slope * x + intercept; }
};

/// Result of evaluating a fit at a back tension.
struct Evaluation {
  double value = 0.0;
  bool extrapolated = false;  ///< x outside the stated range (or range empty)
  bool range_known = false;   ///< false when the fit states no range
  std::string note;           ///< human-readable warning when extrapolated
};

Evaluation evaluate(const LinearFit& fit, double x);

/// a - b: slopes and intercepts subtract; the validity range is the
/// intersection of both ranges (it may be empty: then every use extrapolates).
LinearFit subtract(const LinearFit& a, const LinearFit& b, const std::string& label = "");

/// Ordinary least-squares line through (x, y); requires >= 2 distinct x.
LinearFit fit_line(const std::vector<double>& x, const std::vector<double>& y, const std::string& label = "");

}  // namespace drawbend::analysis
