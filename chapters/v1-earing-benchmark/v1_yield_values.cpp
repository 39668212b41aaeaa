// The yield functions' and the fit's numbers the prose quotes (v1_yield_values.hpp).
#include "v1_yield_values.hpp"

#include <cmath>
#include <string>

namespace v1 {

using namespace drawbend;

namespace {

/// "37.5" -> "37_5": a key's angle.
std::string angle_key(double a) {
  std::string s = fmt_shortest(a);
  for (auto& ch : s)
    if (ch == '.') ch = '_';
  return s;
}

}  // namespace

void yield_values(study::Chapter& c, const std::vector<material::NamedYield>& models,
                  const material::SheetTests& tests, const std::vector<material::Yld2004Fit::Local>& minima,
                  const std::vector<std::size_t>& groups) {
  for (const auto& m : models) {
    for (double a : {0.0, 37.5, 45.0, 52.5, 90.0})
      c.value("flange_" + m.name + "_" + angle_key(a), fmt_fixed(m.flange_shear_ratio(a), 3));
    for (double a : {52.5, 60.0}) {
      c.value("r_" + m.name + "_" + angle_key(a), fmt_fixed(m.r_value(a), 3));
      c.value("sigma_" + m.name + "_" + angle_key(a), fmt_fixed(m.uniaxial_ratio(a), 3));
    }
    // the lowest r(theta) and sigma(theta)/sigma0 on tables/yield_angles.csv's grid (every 7.5 deg)
    double ra = 0, rv = 1e30, sa = 0, sv = 1e30;
    for (int k = 0; k <= 12; ++k) {
      const double t = 7.5 * k;
      if (m.r_value(t) < rv) rv = m.r_value(t), ra = t;
      if (m.uniaxial_ratio(t) < sv) sv = m.uniaxial_ratio(t), sa = t;
    }
    c.value(m.name + "_rmin", fmt_fixed(rv, 3) + " at " + fmt_shortest(ra) + "°");
    c.value(m.name + "_smin", fmt_fixed(sv, 3) + " at " + fmt_shortest(sa) + "°");
    if (m.name != "yld2004") continue;
    // Where the fitted set's flange ratio is turned: above 1 on the RD side of 45 deg or below 1 on the TD side
    // (every Hill'48 set, and POSTECH's, is below 1 on the RD side and above on the TD side).
    double lo = 1e30, hi = -1e30;
    for (int k = 0; k <= 12; ++k) {
      const double t = 7.5 * k, f = m.flange_shear_ratio(t);
      if ((t < 45 && f > 1) || (t > 45 && f < 1)) lo = std::min(lo, t), hi = std::max(hi, t);
    }
    c.value("flange_yld2004_turned", lo > hi ? std::string("nowhere") : fmt_shortest(lo) + "–" + fmt_shortest(hi) + "°");
  }
  if (groups.empty()) return;
  c.value("yld_cost", fmt(minima[groups[0]].cost, 2));
  std::string next;
  for (std::size_t g = 1; g < groups.size() && g <= 4; ++g) {
    const std::size_t i = groups[g], j = g + 1 < groups.size() ? groups[g + 1] : minima.size();
    const material::NamedYield y{"y", &minima[i].yield, nullptr};
    std::string starts;
    for (std::size_t k = i; k < j; ++k) starts += (starts.empty() ? "" : ", ") + std::to_string(minima[k].start);
    next += (next.empty() ? "" : "; ") + std::string(j - i > 1 ? "starts " : "start ") + starts + " (cost " +
            fmt(minima[i].cost, 3) + ", RMS " + fmt_fixed(y.rms(tests, material::SheetDatum::uniaxial_stress), 3) +
            " and " + fmt_fixed(y.rms(tests, material::SheetDatum::uniaxial_r), 3) + "): " +
            fmt_fixed(y.flange_shear_ratio(37.5), 3) + " / " + fmt_fixed(y.flange_shear_ratio(52.5), 3);
  }
  c.value("yld_minima_next", next);
}

}  // namespace v1
