#include "analysis/stribeck.hpp"

#include <cmath>
#include <stdexcept>

#include "core/csv.hpp"

namespace drawbend::analysis {

void StribeckParams::validate(const std::string& where) const {
  auto bad = [&](const std::string& what) { throw std::invalid_argument(where + ": " + what); };
  if (!(mu_BL >= 0.0) || !(mu_EHL >= 0.0)) bad("friction coefficients must be >= 0");
  if (!(L_BL > 0.0) || !(L_EHL > 0.0)) bad("lubricant numbers L_BL and L_EHL must be > 0");
  if (!(L_BL < L_EHL)) bad("L_BL must be smaller than L_EHL (found L_BL >= L_EHL)");
  if (!(Ra_um > 0.0)) bad("roughness R_a must be > 0 um");
  if (!(eta_Pa_s > 0.0)) bad("viscosity eta must be > 0 Pa s");
}

double lubricant_number(double v_mm_s, double p_MPa, const StribeckParams& s) {
  if (!(p_MPa > 0.0)) throw std::domain_error("lubricant_number: pressure must be > 0 MPa");
  const double v = std::abs(v_mm_s) * 1e-3;  // m/s
  const double p = p_MPa * 1e6;              // Pa
  const double Ra = s.Ra_um * 1e-6;          // m
  return v * s.eta_Pa_s / (p * Ra);
}

double stribeck_mu(double L, const StribeckParams& s) {
  if (L == 0.0) return s.mu_BL;  // the L -> 0 limit (sticking contact)
  if (!(L > 0.0)) throw std::domain_error("stribeck_mu: L must be >= 0");
  const double arg = std::log(L * L / (s.L_BL * s.L_EHL)) / std::log(s.L_BL / s.L_EHL);
  return 0.5 * ((s.mu_BL + s.mu_EHL) + (s.mu_BL - s.mu_EHL) * std::tanh(arg));
}

double stribeck_mu(double v_mm_s, double p_MPa, const StribeckParams& s) {
  return stribeck_mu(lubricant_number(v_mm_s, p_MPa, s), s);
}

StribeckParams load_stribeck(const std::string& path) {
  const CsvTable t = read_csv(path);
  StribeckParams s;
  int seen = 0;
  for (const auto& r : t.rows) {
    const std::string& name = t.text(r, "parameter");
    const double v = t.number(r, "value");
    if (name == "mu_BL") s.mu_BL = v;
    else if (name == "mu_EHL") s.mu_EHL = v;
    else if (name == "L_BL") s.L_BL = v;
    else if (name == "L_EHL") s.L_EHL = v;
    else if (name == "Ra") s.Ra_um = v;
    else if (name == "eta") s.eta_Pa_s = v;
    else throw InputError(t.where(r, "parameter") + ": unknown Stribeck parameter '" + name + "'");
    ++seen;
  }
  if (seen != 6) throw InputError(path + ": expected the 6 Stribeck parameters, found " + std::to_string(seen));
  s.validate(path);
  return s;
}

}  // namespace drawbend::analysis
