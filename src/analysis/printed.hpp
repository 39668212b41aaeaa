#pragma once
// A number as printed in the thesis: its value, its text and the half unit in
// the last printed place.  The half unit is the largest rounding error the
// printed digits can hide, which is what re-derivation tolerances are built from.
#include <functional>
#include <string>
#include <vector>

namespace drawbend::analysis {

struct Printed {
  double value = 0.0;
  double half_ulp = 0.0;  ///< 0.5 * 10^-(decimals printed)
  std::string text;
};

/// Parse "106.76", "-0.0008", "4.5e-4", "1,450" (thousands separators removed).
/// Throws std::invalid_argument on anything that is not a finite number.
Printed parse_printed(const std::string& text);

/// First-order propagation of printed-digit rounding through f:
///   tol = half_ulp(output) + sum_i |df/dx_i| * half_ulp(x_i)
/// The derivative is taken by central differences at the printed values.
/// `output_half_ulp` is the rounding of the value we compare against.
double rounding_tolerance(const std::function<double(const std::vector<double>&)>& f,
                          const std::vector<Printed>& inputs, double output_half_ulp);

}  // namespace drawbend::analysis
