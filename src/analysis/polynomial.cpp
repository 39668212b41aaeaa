#include "analysis/polynomial.hpp"

#include <cmath>

#include "core/csv.hpp"

namespace drawbend::analysis {

std::string Polynomial::str(int digits) const {
  std::string s;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double c = a[k];
    std::string term = fmt(std::abs(c), digits);
    if (k == 1) term += " p";
    if (k > 1) term += " p^" + std::to_string(k);
    if (k == 0)
      s = (c < 0 ? "-" : "") + term;
    else
      s += (c < 0 ? " - " : " + ") + term;
  }
  return s;
}

}  // namespace drawbend::analysis
