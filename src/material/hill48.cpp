#include "material/hill48.hpp"

#include <cmath>
#include <stdexcept>

#include "core/csv.hpp"

namespace drawbend::material {

namespace {
void require_positive(double v, const char* name) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(name) + " must be positive and finite, found " + fmt_shortest(v));
  // r-values of sheet metals lie between about 0.2 and 3, yield-stress ratios
  // near 1; outside [1e-3, 1e3] the coefficients lose their digits (r = 1e-300
  // gave H = 1e-300, a yield surface indistinguishable from a degenerate one).
  if (v < 1e-3 || v > 1e3)
    throw std::invalid_argument(std::string(name) + " = " + fmt_shortest(v) +
                                " is outside [0.001, 1000], beyond any sheet metal (r-values 0.2 to 3)");
}
}  // namespace

Hill48 Hill48::from_r_values(double r0, double r45, double r90) {
  require_positive(r0, "r0");
  require_positive(r45, "r45");
  require_positive(r90, "r90");
  Hill48 h;
  h.G = 1.0 / (1.0 + r0);
  h.H = r0 / (1.0 + r0);
  h.F = r0 / (r90 * (1.0 + r0));
  h.N = (r0 + r90) * (1.0 + 2.0 * r45) / (2.0 * r90 * (1.0 + r0));
  h.validate();
  return h;
}

Hill48 Hill48::from_stress_ratios(double s45, double s90, double sb) {
  require_positive(s45, "s45 (sigma45/sigma0)");
  require_positive(s90, "s90 (sigma90/sigma0)");
  require_positive(sb, "sb (sigma_b/sigma0)");
  const double S = 1.0 + 1.0 / (s90 * s90) + 1.0 / (sb * sb);
  Hill48 h;
  h.F = 0.5 * S - 1.0;
  h.G = 0.5 * S - 1.0 / (s90 * s90);
  h.H = 0.5 * S - 1.0 / (sb * sb);
  h.N = 0.5 * (4.0 / (s45 * s45) - h.F - h.G);
  h.validate();
  return h;
}

void Hill48::validate() const {
  for (double v : {F, G, H, L, M, N})
    if (!std::isfinite(v)) throw std::invalid_argument("Hill'48: a coefficient is not finite");
  // Positive definite on deviators: the 2x2 form on (s11 - s33, s22 - s33)
  // [[G + H, -H], [-H, F + H]] and the shear coefficients.
  if (!(G + H > 0 && F + H > 0 && F * G + G * H + H * F > 0))
    throw std::invalid_argument("Hill'48: F = " + fmt_shortest(F) + ", G = " + fmt_shortest(G) + ", H = " +
                                fmt_shortest(H) + " give no closed, convex yield surface (need G + H > 0, F + H > 0, "
                                "FG + GH + HF > 0)");
  if (!(L > 0 && M > 0 && N > 0))
    throw std::invalid_argument("Hill'48: the shear coefficients L, M, N must be positive, found N = " + fmt_shortest(N));
}

double Hill48::uniaxial_ratio(double t) const {
  const double c = std::cos(t), s = std::sin(t);
  const double c2 = c * c, s2 = s * s;
  return 1.0 / std::sqrt(F * s2 * s2 + G * c2 * c2 + H * (c2 - s2) * (c2 - s2) + 2.0 * N * s2 * c2);
}

double Hill48::r_value(double t) const {
  const double c = std::cos(t), s = std::sin(t);
  const double c2 = c * c, s2 = s * s;
  return (H + (2.0 * N - F - G - 4.0 * H) * s2 * c2) / (F * s2 + G * c2);
}

double Hill48::biaxial_ratio() const { return 1.0 / std::sqrt(F + G); }

std::string Hill48::describe() const {
  return "Hill'48 F = " + fmt_shortest(F) + ", G = " + fmt_shortest(G) + ", H = " + fmt_shortest(H) + ", L = " +
         fmt_shortest(L) + ", M = " + fmt_shortest(M) + ", N = " + fmt_shortest(N) + " (r0/r45/r90 = " +
         fmt(r_value(0.0)) + "/" + fmt(r_value(M_PI / 4)) + "/" + fmt(r_value(M_PI / 2)) + ")";
}

}  // namespace drawbend::material
