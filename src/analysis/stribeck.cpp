#include "analysis/stribeck.hpp"

#include <cmath>
#include <stdexcept>

#include "core/csv.hpp"
#include "core/strip_limits.hpp"

namespace drawbend::analysis {

void StribeckParams::validate(const std::string& where) const {
  auto bad = [&](const std::string& what) { throw std::invalid_argument(where + ": " + what); };
  if (!(mu_BL >= 0.0) || !(mu_EHL >= 0.0)) bad("friction coefficients must be >= 0");
  if (mu_BL > kMaxFrictionCoefficient || mu_EHL > kMaxFrictionCoefficient)
    bad("friction coefficients must be at most " + fmt(kMaxFrictionCoefficient) + ", found mu_BL = " +
        fmt_shortest(mu_BL) + " and mu_EHL = " + fmt_shortest(mu_EHL));
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
  // Each parameter once, each value in its range, named by file:line (a
  // value out of range was named by the deck being written, without a line).
  struct Param {
    const char* name;
    double* v;
    double lo, hi;  // lo < v <= hi, or lo <= v when lo is 0 for the friction coefficients
    bool closed_lo;
    const CsvRow* row = nullptr;
  };
  Param ps[] = {{"mu_BL", &s.mu_BL, 0.0, kMaxFrictionCoefficient, true},
                {"mu_EHL", &s.mu_EHL, 0.0, kMaxFrictionCoefficient, true},
                {"L_BL", &s.L_BL, 0.0, HUGE_VAL, false},
                {"L_EHL", &s.L_EHL, 0.0, HUGE_VAL, false},
                {"Ra", &s.Ra_um, 0.0, HUGE_VAL, false},
                {"eta", &s.eta_Pa_s, 0.0, HUGE_VAL, false}};
  for (const auto& r : t.rows) {
    const std::string& name = t.text(r, "parameter");
    Param* p = nullptr;
    for (auto& q : ps)
      if (name == q.name) p = &q;
    if (!p) throw InputError(t.where(r, "parameter") + ": unknown Stribeck parameter '" + name + "'");
    if (p->row)
      throw InputError(t.where(r, "parameter") + ": Stribeck parameter '" + name + "' given twice (first on line " +
                       std::to_string(p->row->line) + ")");
    p->row = &r;
    const double v = t.number(r, "value");
    if (!(p->closed_lo ? v >= p->lo : v > p->lo) || v > p->hi)
      throw InputError(t.where(r, "value") + ": " + name + ": expected " +
                       (p->closed_lo ? "a friction coefficient in [0, " + fmt(p->hi) + "]" : std::string("a number > 0")) +
                       ", found " + fmt_shortest(v));
    *p->v = v;
  }
  for (const auto& p : ps)
    if (!p.row) throw InputError(path + ": missing Stribeck parameter '" + std::string(p.name) + "' (expected mu_BL, mu_EHL, L_BL, L_EHL, Ra, eta)");
  if (!(s.L_BL < s.L_EHL))
    throw InputError(t.where(*ps[2].row, "value") + ": L_BL: expected L_BL < L_EHL (boundary before hydrodynamic "
                     "lubrication), found " + fmt_shortest(s.L_BL) + " >= " + fmt_shortest(s.L_EHL));
  s.validate(path);
  return s;
}

}  // namespace drawbend::analysis
