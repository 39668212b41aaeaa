#include "material/yld2004_fit.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "core/csv.hpp"
#include "material/yield_points.hpp"

namespace drawbend::material {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Hill'48 as a yield function with a gradient, for material/yield_points.hpp.
struct HillFn {
  const Hill48& h;
  double equivalent(const double x[6]) const {
    const double a = x[1] - x[2], b = x[2] - x[0], c = x[0] - x[1];
    return std::sqrt(h.F * a * a + h.G * b * b + h.H * c * c +
                     2.0 * (h.N * x[3] * x[3] + h.L * x[4] * x[4] + h.M * x[5] * x[5]));
  }
  double gradient(const double x[6], double n[6]) const {
    const double q = equivalent(x);
    n[0] = ((h.G + h.H) * x[0] - h.H * x[1] - h.G * x[2]) / q;
    n[1] = (-h.H * x[0] + (h.F + h.H) * x[1] - h.F * x[2]) / q;
    n[2] = (-h.G * x[0] - h.F * x[1] + (h.F + h.G) * x[2]) / q;
    n[3] = h.N * x[3] / q, n[4] = h.L * x[4] / q, n[5] = h.M * x[5] / q;
    return q;
  }
};

template <class F>
double predict_of(const F& f, const SheetDatum& d) {
  const double t = d.angle_deg * kDeg;
  switch (d.kind) {
    case SheetDatum::uniaxial_stress: return points::uniaxial_ratio(f, t);
    case SheetDatum::uniaxial_r: return points::r_value(f, t);
    case SheetDatum::biaxial_stress: return points::biaxial_ratio(f);
    case SheetDatum::biaxial_r: return points::biaxial_r(f);
    case SheetDatum::plane_strain: return points::plane_strain_ratio(f, t);
  }
  return std::nan("");
}

template <class F>
double rms_of(const F& f, const SheetTests& t, SheetDatum::Kind kind) {
  double s = 0;
  int n = 0;
  for (const auto& d : t.data)
    if (d.kind == kind) s += std::pow(predict_of(f, d) - d.value, 2), ++n;
  return n ? std::sqrt(s / n) : std::nan("");
}

// The 14 free coefficients <-> a Yld2004 (c44 = c55 = 1).
constexpr int kFree[7] = {0, 1, 2, 3, 4, 5, 8};
Yld2004 from_params(const std::vector<double>& p, double a) {
  Yld2004 y;
  y.a = a;
  for (int i = 0; i < 7; ++i) y.c1[kFree[i]] = p[i], y.c2[kFree[i]] = p[7 + i];
  return y;
}

// Weighted relative residuals; false when a prediction is not finite (no closed surface there).
bool residuals(const Yld2004& y, const SheetTests& t, const FitWeights& w, std::vector<double>& r) {
  r.clear();
  for (const auto& d : t.data) {
    const double wt = w.of(d.kind);
    if (!(wt > 0)) continue;
    const double p = predict_of(y, d);
    if (!std::isfinite(p)) return false;
    r.push_back(std::sqrt(wt) * (p - d.value) / d.value);
  }
  return true;
}
double sumsq(const std::vector<double>& r) {
  double s = 0;
  for (double v : r) s += v * v;
  return s;
}

// Solve A x = b (n x n) by Gaussian elimination with partial pivoting; false when singular.
bool solve(std::vector<std::vector<double>> A, std::vector<double>& b) {
  const int n = static_cast<int>(b.size());
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(A[i][k]) > std::abs(A[p][k])) p = i;
    if (!(std::abs(A[p][k]) > 0)) return false;
    std::swap(A[k], A[p]);
    std::swap(b[k], b[p]);
    for (int i = k + 1; i < n; ++i) {
      const double f = A[i][k] / A[k][k];
      for (int j = k; j < n; ++j) A[i][j] -= f * A[k][j];
      b[i] -= f * b[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    for (int j = k + 1; j < n; ++j) b[k] -= A[k][j] * b[j];
    b[k] /= A[k][k];
  }
  return true;
}

// Levenberg-Marquardt from p; returns the cost (infinite when it never had a finite one).
double levenberg_marquardt(std::vector<double>& p, double a, const SheetTests& t, const FitWeights& w) {
  const int np = static_cast<int>(p.size());
  std::vector<double> r, rp;
  if (!residuals(from_params(p, a), t, w, r)) return INFINITY;
  double cost = sumsq(r), lambda = 1e-3;
  for (int it = 0; it < 400; ++it) {
    const int m = static_cast<int>(r.size());
    std::vector<std::vector<double>> J(m, std::vector<double>(np));
    for (int j = 0; j < np; ++j) {
      std::vector<double> q = p;
      const double h = 1e-7 * std::max(1.0, std::abs(p[j]));
      q[j] += h;
      if (!residuals(from_params(q, a), t, w, rp)) return cost;
      for (int i = 0; i < m; ++i) J[i][j] = (rp[i] - r[i]) / h;
    }
    std::vector<std::vector<double>> A(np, std::vector<double>(np, 0.0));
    std::vector<double> g(np, 0.0);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < np; ++j) {
        g[j] -= J[i][j] * r[i];
        for (int k = 0; k < np; ++k) A[j][k] += J[i][j] * J[i][k];
      }
    bool improved = false;
    for (int tries = 0; tries < 20 && !improved; ++tries) {
      auto B = A;
      for (int j = 0; j < np; ++j) B[j][j] += lambda * (A[j][j] + 1e-12);
      std::vector<double> d = g;
      if (!solve(B, d)) {
        lambda *= 10;
        continue;
      }
      std::vector<double> q = p;
      for (int j = 0; j < np; ++j) q[j] += d[j];
      if (residuals(from_params(q, a), t, w, rp) && sumsq(rp) < cost) {
        const double drop = cost - sumsq(rp);
        p = q, r = rp, cost = sumsq(rp);
        lambda = std::max(lambda / 3, 1e-12);
        improved = true;
        if (drop <= 1e-15 * std::max(cost, 1e-30)) return cost;
      } else {
        lambda *= 4;
      }
    }
    if (!improved || cost < 1e-28) return cost;
  }
  return cost;
}
}  // namespace

std::string SheetDatum::label() const {
  const std::string a = fmt_shortest(angle_deg);
  switch (kind) {
    case uniaxial_stress: return "sigma(" + a + ")/sigma0";
    case uniaxial_r: return "r(" + a + ")";
    case biaxial_stress: return "sigma_b/sigma0";
    case biaxial_r: return "r_b";
    case plane_strain: return "sigma_ps(" + a + ")/sigma0";
  }
  return "";
}

double FitWeights::of(SheetDatum::Kind k) const {
  switch (k) {
    case SheetDatum::uniaxial_stress: return stress;
    case SheetDatum::uniaxial_r: return r;
    case SheetDatum::biaxial_stress:
    case SheetDatum::biaxial_r: return biaxial;
    case SheetDatum::plane_strain: return plane_strain;
  }
  return 0;
}

static double find_value(const SheetTests& t, SheetDatum::Kind k, double angle) {
  for (const auto& d : t.data)
    if (d.kind == k && std::abs(d.angle_deg - angle) < 1e-9) return d.value;
  return std::nan("");
}
double SheetTests::uniaxial_stress(double a) const { return find_value(*this, SheetDatum::uniaxial_stress, a); }
double SheetTests::r_value(double a) const { return find_value(*this, SheetDatum::uniaxial_r, a); }
double SheetTests::biaxial_stress() const { return find_value(*this, SheetDatum::biaxial_stress, 0.0); }

SheetTests load_sheet_tests(const std::string& path) {
  const CsvTable t = read_csv(path);
  SheetTests out;
  out.path = path;
  for (const char* c : {"test", "angle_deg", "stress_ratio", "r_value"}) t.column(c);
  for (const auto& row : t.rows) {
    const std::string test = t.text(row, "test");
    const bool uni = test == "uniaxial", bi = test == "balanced_biaxial", ps = test == "plane_strain";
    if (!uni && !bi && !ps)
      throw InputError(t.where(row, "test") + ": expected uniaxial, balanced_biaxial or plane_strain, found '" + test + "'");
    double angle = 0;
    if (!bi) {
      angle = t.number(row, "angle_deg");
      if (!(angle >= 0 && angle <= 90)) throw InputError(t.where(row, "angle_deg") + ": expected an angle in [0, 90] deg");
    } else if (!t.text(row, "angle_deg").empty()) {
      throw InputError(t.where(row, "angle_deg") + ": a balanced biaxial test has no angle");
    }
    const auto add = [&](const char* col, SheetDatum::Kind k) {
      if (t.text(row, col).empty()) return;
      const double v = t.number(row, col);
      if (!(v > 0)) throw InputError(t.where(row, col) + ": must be > 0, found " + fmt_shortest(v));
      // Beyond any sheet metal: yield-stress ratios to RD lie near 0.7 to 1.4 and
      // r-values near 0.2 to 3; a ratio outside [0.1, 10] or an r-value outside
      // Hill'48's [0.001, 1000] (material/hill48.hpp) is a unit or typing error
      // (a stress in MPa instead of a ratio), which the fit would turn into a
      // meaningless yield surface (before issue 53 a ratio 1e300 gave exit 0).
      const bool ratio = std::string(col) == "stress_ratio";
      const double lo = ratio ? 0.1 : 1e-3, hi = ratio ? 10 : 1e3;
      if (!(v >= lo && v <= hi))
        throw InputError(t.where(row, col) + ": expected " + (ratio ? "a yield-stress ratio to RD" : "an r-value") +
                         " in [" + fmt_shortest(lo) + ", " + fmt_shortest(hi) + "] (sheet metals: " +
                         (ratio ? "0.7 to 1.4" : "0.2 to 3") + "), found " + fmt_shortest(v));
      for (const auto& d : out.data)
        if (d.kind == k && std::abs(d.angle_deg - angle) < 1e-9)
          throw InputError(t.where(row, col) + ": the same test is given twice (also " + d.where + ")");
      out.data.push_back({k, angle, v, t.where(row, col)});
    };
    add("stress_ratio", uni ? SheetDatum::uniaxial_stress : bi ? SheetDatum::biaxial_stress : SheetDatum::plane_strain);
    if (ps && !t.text(row, "r_value").empty())
      throw InputError(t.where(row, "r_value") + ": a plane-strain test has no r-value");
    if (!ps) add("r_value", uni ? SheetDatum::uniaxial_r : SheetDatum::biaxial_r);
  }
  if (std::isnan(out.uniaxial_stress(0.0)) || std::abs(out.uniaxial_stress(0.0) - 1.0) > 1e-12)
    throw InputError(path + ": expected a uniaxial row at 0 deg with stress_ratio 1 (the ratios are to sigma_0 along RD)");
  return out;
}

double predict(const Yld2004& y, const SheetDatum& d) { return predict_of(y, d); }
double predict(const Hill48& h, const SheetDatum& d) { return predict_of(HillFn{h}, d); }
double rms_residual(const Yld2004& y, const SheetTests& t, SheetDatum::Kind k) { return rms_of(y, t, k); }
double rms_residual(const Hill48& h, const SheetTests& t, SheetDatum::Kind k) { return rms_of(HillFn{h}, t, k); }

double NamedYield::predict(const SheetDatum& d) const { return yld ? predict_of(*yld, d) : predict_of(HillFn{*hill}, d); }
double NamedYield::rms(const SheetTests& t, SheetDatum::Kind k) const {
  return yld ? rms_of(*yld, t, k) : rms_of(HillFn{*hill}, t, k);
}

double NamedYield::uniaxial_ratio(double t) const {
  return yld ? points::uniaxial_ratio(*yld, t * kDeg) : points::uniaxial_ratio(HillFn{*hill}, t * kDeg);
}
double NamedYield::r_value(double t) const {
  return yld ? points::r_value(*yld, t * kDeg) : points::r_value(HillFn{*hill}, t * kDeg);
}
double NamedYield::flange_shear_ratio(double t) const {
  return yld ? points::flange_shear_ratio(*yld, t * kDeg) : points::flange_shear_ratio(HillFn{*hill}, t * kDeg);
}

std::vector<std::vector<std::string>> calibration_table(const SheetTests& t, const FitWeights& w,
                                                        const std::vector<NamedYield>& models, std::size_t residual_of) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> head = {"datum", "angle_deg", "measured", "weight"};
  for (const auto& m : models) head.push_back(m.name);
  head.push_back("residual_" + models.at(residual_of).name);
  rows.push_back(head);
  for (const auto& d : t.data) {
    const bool angled = d.kind != SheetDatum::biaxial_stress && d.kind != SheetDatum::biaxial_r;
    std::vector<std::string> r = {d.label(), angled ? fmt_shortest(d.angle_deg) : "", fmt_fixed(d.value, 4),
                                  fmt_shortest(w.of(d.kind))};
    for (const auto& m : models) r.push_back(fmt_fixed(m.predict(d), 4));
    r.push_back(fmt_fixed(models[residual_of].predict(d) - d.value, 4));
    rows.push_back(r);
  }
  return rows;
}

void require_fittable(const SheetTests& tests, const FitWeights& w) {
  // The in-plane anisotropy of an orthotropic sheet needs the yield stress and
  // the r-value at 0, 45 and 90 deg at least (Hill'48 from either set needs
  // three of them); with fewer the fit puts the untested directions wherever
  // its start lies and still reports a residual of zero.
  std::string missing;
  for (double ang : {0.0, 45.0, 90.0}) {
    if (!std::isfinite(tests.uniaxial_stress(ang))) missing += " sigma(" + fmt_shortest(ang) + ")";
    if (!std::isfinite(tests.r_value(ang))) missing += " r(" + fmt_shortest(ang) + ")";
  }
  if (!missing.empty())
    throw InputError(tests.path + ": the fit needs uniaxial rows at 0, 45 and 90 deg with both stress_ratio and "
                     "r_value; missing:" + missing);
  if (!(w.stress > 0) || !(w.r > 0))
    throw InputError(tests.path + ": the weights of the uniaxial stress ratios and r-values must be > 0 (found " +
                     fmt_shortest(w.stress) + " and " + fmt_shortest(w.r) +
                     "): with either at 0 nothing fixes that half of the anisotropy");
}

Yld2004Fit fit_yld2004(const SheetTests& tests, const FitWeights& w, double a) {
  if (!(a >= 2) || !std::isfinite(a)) throw std::invalid_argument("Yld2004-18p fit: the exponent a must be >= 2");
  require_fittable(tests, w);
  Yld2004Fit best;
  best.cost = INFINITY;
  std::mt19937 rng(2004);
  std::uniform_real_distribution<double> U(-0.5, 0.5);
  constexpr int kStarts = 16;
  for (int s = 0; s < kStarts; ++s) {
    std::vector<double> p(14, 1.0);
    if (s > 0)
      for (double& v : p) v += U(rng);
    const double cost = levenberg_marquardt(p, a, tests, w);
    ++best.starts;
    if (!std::isfinite(cost)) continue;
    try {
      const Yld2004 raw = from_params(p, a);
      const Yld2004 y = raw.normalised();
      y.validate();
      ++best.accepted;
      best.local.push_back({s, cost, y});
      const double u[6] = {1, 0, 0, 0, 0, 0};
      if (cost < best.cost) best.yield = y, best.raw = raw, best.scale = raw.equivalent(u), best.cost = cost;
    } catch (const std::invalid_argument&) {
    }
  }
  if (!std::isfinite(best.cost))
    throw std::invalid_argument("Yld2004-18p fit: no start converged to a closed, convex yield surface");
  return best;
}

}  // namespace drawbend::material
