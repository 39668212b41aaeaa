#include "friction/surface_law.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/csv.hpp"
#include "core/strip_limits.hpp"

namespace drawbend::friction {

namespace {
// Monomial coefficients of the 1-D quadratic Lagrange functions on -1, 0, +1:
// L_i(s) = A[i][0] + A[i][1] s + A[i][2] s^2.
constexpr double A[3][3] = {{0.0, -0.5, 0.5}, {1.0, 0.0, -1.0}, {0.0, 0.5, 0.5}};

std::array<double, 9> monomials(const std::array<double, 9>& mu) {
  std::array<double, 9> c{};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double s = 0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s += A[i][a] * A[j][b] * mu[3 * i + j];
      c[3 * a + b] = s;
    }
  return c;
}

inline double horner(const std::array<double, 9>& c, double x, double e) {
  const double q0 = c[0] + e * (c[1] + e * c[2]);
  const double q1 = c[3] + e * (c[4] + e * c[5]);
  const double q2 = c[6] + e * (c[7] + e * c[8]);
  return std::max(0.0, q0 + x * (q1 + x * q2));
}
}  // namespace

SurfaceLaw::SurfaceLaw(const analysis::FrictionSurface& rd, const analysis::FrictionSurface& td, int interval)
    : rd_(rd), td_(td), interval_(interval) {
  if (interval < 1) throw std::invalid_argument("surface friction law: update interval must be >= 1 cycle");
  for (const auto* s : {&rd, &td}) {
    if (!(s->p_min < s->p_max)) throw std::invalid_argument("surface friction law: p_min must be < p_max");
    if (!(s->v_min < s->v_max)) throw std::invalid_argument("surface friction law: v_min must be < v_max");
    for (double m : s->mu)
      if (!(m >= 0.0)) throw std::invalid_argument("surface friction law: nodal friction coefficients must be >= 0");
  }
  if (rd.p_min != td.p_min || rd.p_max != td.p_max || rd.v_min != td.v_min || rd.v_max != td.v_max)
    throw std::invalid_argument("surface friction law: the RD and TD surfaces must share one domain");
  c_rd_ = monomials(rd.mu);
  c_td_ = monomials(td.mu);
  sx_ = 2.0 / (rd.p_max - rd.p_min);
  ox_ = -2.0 * rd.p_min / (rd.p_max - rd.p_min) - 1.0;
  se_ = 2.0 / (rd.v_max - rd.v_min);
  oe_ = -2.0 * rd.v_min / (rd.v_max - rd.v_min) - 1.0;
}

Limit SurfaceLaw::at(double p, double v) const {
  p = std::clamp(p, rd_.p_min, rd_.p_max);
  v = std::clamp(v, rd_.v_min, rd_.v_max);
  const double x = sx_ * p + ox_, e = se_ * v + oe_;
  return {horner(c_rd_, x, e), horner(c_td_, x, e)};
}

Limit SurfaceLaw::limit(const ContactState& s) const {
  double* st = s.state;  // [0] speed sum, [1] count, [2] last interval mean (-1 none; 0 at start = none)
  double v = s.slip_speed;
  if (interval_ > 1) {
    st[0] += s.slip_speed;
    st[1] += 1.0;
    if (st[1] >= interval_) {
      st[2] = st[0] / st[1] + 1.0;  // stored +1 so that a zero-initialised state reads "none yet"
      st[0] = st[1] = 0.0;
    }
    v = st[2] > 0.0 ? st[2] - 1.0 : st[0] / st[1];
  }
  st[3] += 1.0;
  if (s.pressure < rd_.p_min || s.pressure > rd_.p_max) st[4] += 1.0;
  if (v < rd_.v_min) st[5] += 1.0;
  else if (v > rd_.v_max) st[6] += 1.0;
  return at(s.pressure, v);
}

std::vector<std::pair<std::string, double>> SurfaceLaw::counters(const std::vector<double>& state) const {
  double n[4] = {0, 0, 0, 0};
  for (std::size_t k = 0; k + 7 <= state.size(); k += 7)
    for (int j = 0; j < 4; ++j) n[j] += state[k + 3 + j];
  return {{"surface_law_evaluations", n[0]},
          {"clamped_pressure", n[1]},
          {"clamped_speed_below_v_min", n[2]},
          {"clamped_speed_above_v_max", n[3]}};
}

std::string SurfaceLaw::describe() const {
  return "surface mu(p, v) RD/TD, p " + std::to_string(rd_.p_min) + "-" + std::to_string(rd_.p_max) + " MPa, v " +
         std::to_string(rd_.v_min) + "-" + std::to_string(rd_.v_max) + " mm/s, interval=" + std::to_string(interval_);
}

std::pair<analysis::FrictionSurface, analysis::FrictionSurface> load_surface_nodes(const std::string& csv,
                                                                                   const SurfaceDomain& d) {
  const CsvTable t = read_csv(csv);
  if (t.rows.size() != 9)
    throw InputError(csv + ": nodal friction values: expected 9 rows (nodes 1-9), found " + std::to_string(t.rows.size()));
  analysis::FrictionSurface rd, td;
  for (auto* s : {&rd, &td}) {
    s->p_min = d.p_min;
    s->p_max = d.p_max;
    s->v_min = d.v_min;
    s->v_max = d.v_max;
  }
  for (std::size_t k = 0; k < 9; ++k) {
    const auto& r = t.rows[k];
    if (t.number(r, "node") != static_cast<double>(k + 1))
      throw InputError(t.where(r, "node") + ": nodes must be numbered 1 to 9 in order (node k = 3i + j + 1: "
                                            "pressure index i, speed index j); expected " + std::to_string(k + 1));
    for (const auto& [col, s] : {std::pair{"mu_RD", &rd}, std::pair{"mu_TD", &td}}) {
      const double m = t.number(r, col);
      if (!(m >= 0.0)) throw InputError(t.where(r, col) + ": friction coefficient must be >= 0");
      if (m > kMaxFrictionCoefficient)
        throw InputError(t.where(r, col) + ": friction coefficient must be at most " + fmt(kMaxFrictionCoefficient) +
                         " (sticking is reached far below), found " + fmt_shortest(m));
      s->mu[k] = m;
    }
  }
  return {rd, td};
}

std::pair<analysis::FrictionSurface, analysis::FrictionSurface> load_surface_lines(const std::string& csv,
                                                                                   double p_min, double p_max) {
  const CsvTable t = read_csv(csv);
  std::vector<analysis::SpeedLine> lines[2];
  const char* dirs[2] = {"RD", "TD"};
  for (const auto& r : t.rows) {
    const std::string& dir = t.text(r, "direction");
    const int k = dir == "RD" ? 0 : dir == "TD" ? 1 : -1;
    if (k < 0) throw InputError(t.where(r, "direction") + ": expected RD or TD");
    const double v = t.number(r, "speed_mm_s");
    if (!lines[k].empty() && !(v > lines[k].back().v_mm_s))
      throw InputError(t.where(r, "speed_mm_s") + ": the " + dir + " lines must be listed in strictly increasing speed");
    lines[k].push_back({v, analysis::Polynomial{{t.number(r, "a0"), t.number(r, "a1_per_MPa")}}});
  }
  analysis::FrictionSurface s[2];
  for (int k = 0; k < 2; ++k) {
    if (lines[k].size() != 3)
      throw InputError(csv + ": expected three " + std::string(dirs[k]) + " speed lines, found " +
                       std::to_string(lines[k].size()));
    s[k] = analysis::surface_from_lines(lines[k], p_min, p_max);
  }
  if (s[0].v_min != s[1].v_min || s[0].v_max != s[1].v_max)
    throw InputError(csv + ": the RD and TD lines must be measured at the same slowest and fastest speeds");
  return {s[0], s[1]};
}

}  // namespace drawbend::friction
