#include "material/swift_fit.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/csv.hpp"

namespace drawbend::material {

double SwiftLaw::stress(double ep) const { return K * std::pow(eps0 + ep, n); }

double SwiftLaw::engineering_uts() const {
  const double eu = necking_strain();
  return stress(eu) * std::exp(-eu);
}

SwiftLaw fit_swift(double ys, double uts, double n, double eps_y) {
  if (!(ys > 0.0) || !(uts > ys))
    throw std::invalid_argument("fit_swift: need 0 < YS < UTS, got YS = " + fmt(ys) + ", UTS = " + fmt(uts));
  if (!(n > 0.0 && n < 1.0)) throw std::invalid_argument("fit_swift: need 0 < n < 1, got " + fmt(n));
  if (!(eps_y >= 0.0 && eps_y < n))
    throw std::invalid_argument("fit_swift: need 0 <= eps_y < n, got " + fmt(eps_y));
  const double lr = std::log(uts / ys);
  const auto g = [&](double e0) { return n * std::log(n / (e0 + eps_y)) + e0 - n - lr; };
  // g decreases on (0, n - eps_y); g(n - eps_y) = -eps_y - ln(UTS/YS) < 0.
  double lo = 0.0, hi = n - eps_y;
  if (eps_y > 0.0 && !(g(0.0) > 0.0))
    throw std::invalid_argument("fit_swift: no eps0 >= 0 fits YS at eps_p = " + fmt(eps_y) +
                                " (UTS/YS too small for this n)");
  for (int it = 0; it < 200 && hi - lo > 0.0; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (g(mid) > 0.0 ? lo : hi) = mid;
  }
  SwiftLaw law;
  law.n = n;
  law.eps0 = 0.5 * (lo + hi);
  law.K = ys / std::pow(law.eps0 + eps_y, n);
  return law;
}

std::vector<double> swift_table_strains() {
  return {0,     0.0005, 0.001, 0.0015, 0.002, 0.003, 0.004, 0.005, 0.006, 0.007, 0.008, 0.009, 0.01,
          0.012, 0.014,  0.016, 0.018,  0.02,  0.0225, 0.025, 0.0275, 0.03, 0.0325, 0.035, 0.04, 0.045, 0.05,
          0.055, 0.06,   0.065, 0.07,   0.075, 0.08,  0.09,  0.1,   0.11,  0.12,  0.135, 0.15,  0.165, 0.18,
          0.2,   0.22,   0.24,  0.26,   0.28,  0.3,   0.325, 0.35,  0.375, 0.4,   0.45,  0.5,   0.55,
          0.6,   0.65,   0.7,   0.75,   0.8,   0.85,  0.9,   0.95,  1.0};
}

HardeningCurve tabulate(const SwiftLaw& law, const std::vector<double>& strains) {
  const double scale = std::pow(10.0, swift_table_stress_decimals);
  std::vector<double> y;
  y.reserve(strains.size());
  for (double e : strains) y.push_back(std::round(law.stress(e) * scale) / scale);
  return HardeningCurve(strains, std::move(y), "Swift table");
}

}  // namespace drawbend::material
