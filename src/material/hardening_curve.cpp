#include "material/hardening_curve.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "core/csv.hpp"

namespace drawbend::material {

namespace {

constexpr double kMaxFlowStressMPa = 1e5;

// Checks the requirements of HardeningCurve; `where(i)` names point i in messages.
void validate(const std::vector<double>& x, const std::vector<double>& y,
              const std::function<std::string(std::size_t)>& where, const std::string& source) {
  if (x.empty()) throw InputError(source + ": a hardening curve needs at least one point");
  if (x.size() != y.size()) throw InputError(source + ": plastic strain and stress lists differ in length");
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
      throw InputError(where(i) + ": plastic strain and stress must be finite numbers");
    if (i == 0 && x[i] != 0.0)
      throw InputError(where(i) + ": the first plastic strain must be 0 (initial yield), found " + fmt_shortest(x[i]));
    if (i > 0 && !(x[i] > x[i - 1]))
      throw InputError(where(i) + ": plastic strain must increase strictly, found " + fmt(x[i], 17) +
                       " after " + fmt(x[i - 1], 17));
    if (!(y[i] > 0.0)) throw InputError(where(i) + ": true stress must be positive, found " + fmt(y[i], 17));
    // 1e5 MPa (100 GPa) is above the modulus of aluminium and twenty times the
    // strongest steels' flow stress (~5 GPa): a stress beyond it is in other
    // units (Pa, kPa), and as a flow stress it never yields (issue 53: 1e308 was accepted).
    if (y[i] > kMaxFlowStressMPa)
      throw InputError(where(i) + ": true stress " + fmt(y[i], 6) + " MPa is above " + fmt(kMaxFlowStressMPa, 6) +
                       " MPa, beyond any metal (check the units: MPa)");
    if (i > 0 && y[i] < y[i - 1])
      throw InputError(where(i) + ": true stress must not decrease (no softening), found " + fmt(y[i], 17) +
                       " after " + fmt(y[i - 1], 17));
  }
}

}  // namespace

HardeningCurve::HardeningCurve(std::vector<double> plastic_strain, std::vector<double> stress,
                               const std::string& source)
    : x_(std::move(plastic_strain)), y_(std::move(stress)) {
  validate(x_, y_, [&](std::size_t i) { return source + ": point " + std::to_string(i); }, source);
  const std::size_t n = x_.size();
  h_.assign(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) h_[k] = (y_[k + 1] - y_[k]) / (x_[k + 1] - x_[k]);
  if (n > 1) h_[n - 1] = h_[n - 2];  // extrapolate with the last slope

  // Uniform bins over [0, x_last): width at most the shortest segment (capped
  // at 4096 bins), so the lookup walks at most one segment in the usual case.
  if (n == 1) {
    bins_.assign(1, 0);
    inv_bin_width_ = 0.0;
    max_bin_ = 0.0;
    return;
  }
  double min_dx = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < n; ++k) min_dx = std::min(min_dx, x_[k + 1] - x_[k]);
  const double span = x_.back();
  const double want = std::ceil(span / min_dx);
  const int nb = static_cast<int>(std::clamp(want, 1.0, 4096.0));
  const double width = span / nb;
  inv_bin_width_ = 1.0 / width;
  max_bin_ = nb - 1;
  bins_.resize(static_cast<std::size_t>(nb));
  std::size_t k = 0;
  for (int b = 0; b < nb; ++b) {
    const double s = b * width;
    while (k + 2 < n && s >= x_[k + 1]) ++k;
    bins_[static_cast<std::size_t>(b)] = static_cast<int>(k);
  }
}

double HardeningCurve::segment_end(int k) const noexcept {
  return k + 1 < static_cast<int>(x_.size()) ? x_[static_cast<std::size_t>(k) + 1]
                                             : std::numeric_limits<double>::infinity();
}

HardeningCurve HardeningCurve::load(const std::string& csv_path) {
  const CsvTable t = read_csv(csv_path);
  const char* cx = "plastic_strain";
  const char* cy = "true_stress_MPa";
  t.column(cx);  // throws a clear error naming the file if missing
  t.column(cy);
  if (t.rows.empty()) throw InputError(csv_path + ": a hardening curve needs at least one data row");
  std::vector<double> x, y;
  x.reserve(t.rows.size());
  y.reserve(t.rows.size());
  for (const auto& r : t.rows) {
    x.push_back(t.number(r, cx));
    y.push_back(t.number(r, cy));
  }
  validate(x, y, [&](std::size_t i) { return csv_path + ":" + std::to_string(t.rows[i].line); }, csv_path);
  return HardeningCurve(std::move(x), std::move(y), csv_path);
}

namespace {
template <class F>
HardeningCurve tabulate(F&& stress, const std::string& source) {
  constexpr int n = 400;
  constexpr double eps_max = 1.5;
  std::vector<double> x(n + 1), y(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double u = static_cast<double>(i) / n;
    x[i] = eps_max * u * u;
    y[i] = stress(x[i]);
  }
  return HardeningCurve(std::move(x), std::move(y), source);
}
}  // namespace

HardeningCurve HardeningCurve::voce(double sigma0, double Q, double b) {
  if (!(sigma0 > 0) || !(Q >= 0) || !(b >= 0) || !std::isfinite(sigma0 + Q + b))
    throw std::invalid_argument("Voce: need sigma0 > 0, Q >= 0, b >= 0 (finite), found sigma0 = " +
                                fmt_shortest(sigma0) + ", Q = " + fmt_shortest(Q) + ", b = " + fmt_shortest(b));
  return tabulate([&](double e) { return sigma0 + Q * (1.0 - std::exp(-b * e)); }, "Voce curve");
}

HardeningCurve HardeningCurve::swift(double K, double e0, double n) {
  if (!(K > 0) || !(e0 > 0) || !(n >= 0) || !std::isfinite(K + e0 + n))
    throw std::invalid_argument("Swift: need K > 0, e0 > 0, n >= 0 (finite), found K = " + fmt_shortest(K) +
                                ", e0 = " + fmt_shortest(e0) + ", n = " + fmt_shortest(n));
  return tabulate([&](double e) { return K * std::pow(e0 + e, n); }, "Swift curve");
}

}  // namespace drawbend::material
