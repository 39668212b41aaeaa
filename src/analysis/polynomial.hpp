#pragma once
// A polynomial mu(p) = a_0 + a_1 p + ... + a_m p^m (thesis Eqs. 4.4, 5.2); p in MPa.
#include <vector>

namespace drawbend::analysis {

struct Polynomial {
  std::vector<double> a;  ///< a[k] multiplies p^k

  double operator()(double p) const {
    double v = 0.0;
    for (auto it = a.rbegin(); it != a.rend(); ++it) v = v * p + *it;  // Horner
    return v;
  }
  int order() const { return static_cast<int>(a.size()) - 1; }
};

}  // namespace drawbend::analysis
