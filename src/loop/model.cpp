// The loop's force model: design, prediction and Levenberg-Marquardt fit.
#include "loop/model.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <functional>
#include <set>

#include "analysis/rope.hpp"
#include <stdexcept>
#include "core/csv.hpp"

namespace drawbend::loop {

namespace {
constexpr double kEtaPaS = 1.2;  // Table 3.3 (Ter Haar); enters L only as a constant factor
bool close(double a, double b) { return std::abs(a - b) < 1e-9 * std::max(1.0, std::abs(a)); }
}  // namespace

double ellipse(double a, double b, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  const double den = std::sqrt(b * b * c * c + a * a * s * s);
  if (den < 1e-12) return a * c * c + b * s * s;
  return a * b / den;
}

BendingSource bending_source(const std::string& b) {
  if (b == "linear" || b == "constant" || b == "rotating") return BendingSource::rotating;
  if (b == "swift") return BendingSource::swift;
  if (b == "fe") return BendingSource::fe;
  if (b == "none") return BendingSource::none;
  throw std::invalid_argument("--bending must be linear, constant, swift, fe or none, not '" + b + "'");
}

std::string bending_source_name(BendingSource b) {
  switch (b) {
    case BendingSource::rotating: return "rotating-pin rows";
    case BendingSource::swift: return "Swift Eq. 2.1 (sigma_y 99.71 MPa, t 1.04 mm, w 25.4 mm, 90 deg)";
    case BendingSource::fe: return "FE rotating-pin run (map file's bending_force_N)";
    case BendingSource::none: return "none (F_B = 0: mu absorbs the bending force, an upper bound)";
  }
  return "?";
}

double map_pressure(const Row& r, double FB, double Ff, double FB_ref) {
  return r.pw_ref * (2 * r.fback + FB + Ff) / (2 * r.fref + FB_ref);
}

std::vector<int> Design::levels(const std::string& column, std::vector<std::string>* names) const {
  std::vector<int> out(rows.size(), 0);
  std::map<std::string, int> ix;
  std::vector<std::string> nm;
  const int k = data->extra_index(column);
  if (k < 0 && column != "pin" && column != "direction_deg")
    throw InputError("no categorical column '" + column + "' for a group factor");
  for (size_t i = 0; i < rows.size(); ++i) {
    const Sample& s = data->rows[i];
    const std::string v = column == "pin" ? fmt(s.pin_d_mm) : column == "direction_deg" ? fmt(s.direction_deg)
                                                                                         : s.extra[k];
    auto [it, fresh] = ix.emplace(v, static_cast<int>(nm.size()));
    if (fresh) nm.push_back(v);
    out[i] = it->second;
  }
  if (names) *names = nm;
  return out;
}

std::vector<double> Design::zscore(const std::string& column) const {
  std::vector<double> x(rows.size(), 0.0);
  for (size_t i = 0; i < rows.size(); ++i) {
    const Sample& s = data->rows[i];
    double v;
    if (column == "time_s") v = s.time_s;
    else if (column == "sliding_distance_mm") v = s.sliding_mm;
    else if (column == "back_tension_N") v = s.back_tension_N;
    else if (column == "speed_mm_s") v = s.speed_mm_s;
    else if (column == "direction_deg") v = s.direction_deg;
    else if (column == "pin_diameter_mm") v = s.pin_d_mm;
    else if (column == "inv_R_per_mm") v = 2 / s.pin_d_mm;
    else {
      const int k = data->extra_index(column);
      if (k < 0) throw InputError("no numeric column '" + column + "' for a linear term");
      try {
        v = std::stod(s.extra[k]);
      } catch (const std::exception&) {
        throw InputError("column '" + column + "' is not numeric: no linear term");
      }
    }
    x[i] = v;
  }
  double m = 0, q = 0;
  for (double v : x) m += v;
  m /= x.size();
  for (double v : x) q += (v - m) * (v - m);
  const double sd = std::sqrt(q / std::max<size_t>(1, x.size() - 1));
  for (double& v : x) v = sd > 0 ? (v - m) / sd : 0.0;
  return x;
}

Design make_design(const Dataset& data, const MapLibrary& maps, double Ra_sheet_um, BendingSource bending) {
  Design d;
  d.data = &data;
  d.maps = &maps;
  std::set<double> pins, speeds, dirs;
  for (const auto& s : data.rows) {
    pins.insert(s.pin_d_mm);
    if (!s.rotating) speeds.insert(s.speed_mm_s), dirs.insert(s.direction_deg);
  }
  d.fixed_directions.assign(dirs.begin(), dirs.end());
  for (double a : d.fixed_directions)
    d.dir_param.push_back(std::abs(a) < 1e-9 || std::abs(a - 90) < 1e-9 ? -1 : d.n_dir_params++);
  d.direction_is_level = dirs.size() <= 2;
  d.notes.push_back(d.direction_is_level ? "direction is a cell level (at most 2 directions: one mu per direction)"
                                         : "directions vary (" + std::to_string(dirs.size()) +
                                               " distinct): mu_RD and mu_TD joined by the anisotropic ellipse");
  d.pins.assign(pins.begin(), pins.end());
  d.speed_is_level = speeds.size() <= 3;
  d.notes.push_back(d.speed_is_level ? "speed is a cell level (" + std::to_string(speeds.size()) + " distinct speeds)"
                                     : "speed varies continuously (" + std::to_string(speeds.size()) +
                                           " distinct speeds): not a cell level, a candidate");
  const int ra = data.extra_index("pin_Ra_um");
  std::map<std::string, int> cell_index;
  double lg_sum = 0;
  int n_fixed = 0;
  for (const auto& s : data.rows) {
    Row r;
    r.pin = static_cast<int>(std::find_if(d.pins.begin(), d.pins.end(), [&](double p) { return close(p, s.pin_d_mm); }) -
                             d.pins.begin());
    r.rotating = s.rotating;
    r.fback = s.back_tension_N;
    r.y = s.outlet_force_N;
    r.phi = s.direction_deg * M_PI / 180.0;
    r.sin2 = std::pow(std::sin(2 * r.phi), 2);
    r.four2 = 0.5 * (std::cos(2 * r.phi) - std::cos(6 * r.phi));
    r.sliding = std::isnan(s.sliding_mm) ? 0.0 : s.sliding_mm;
    if (!s.rotating) {
      std::string cell = s.lubricant + (d.speed_is_level ? " | " + fmt(s.speed_mm_s) + " mm/s" : "");
      if (d.direction_is_level) cell += s.direction_deg < 45 ? " | RD" : " | TD";
      auto [it, fresh] = cell_index.emplace(cell, static_cast<int>(d.cells.size()));
      if (fresh) {
        d.cells.push_back(cell);
        d.cell_rd.push_back(0);
        d.cell_td.push_back(0);
      }
      r.cell = it->second;
      (s.direction_deg < 45 ? d.cell_rd : d.cell_td)[r.cell] = 1;
      const PinMap& m = maps.at(s.pin_d_mm);
      r.pw_ref = m.S2 / m.S1;
      r.fref = m.fref_N;
      r.dir = static_cast<int>(std::find_if(d.fixed_directions.begin(), d.fixed_directions.end(),
                                            [&](double a) { return close(a, s.direction_deg); }) -
                               d.fixed_directions.begin());
      // Lubricant number (Eq. 3.1) at the frictionless average pressure (Eq. 2.2), SI units.
      const double p_avg = 2 * s.back_tension_N / (s.pin_d_mm * kStripWidthMm);  // MPa, F_x = F_y
      double ra_pin = 0.1;  // Table 5.2
      if (ra >= 0) {
        try {
          ra_pin = std::stod(s.extra[ra]);
        } catch (...) {
        }
      }
      const double ra_comb = std::hypot(Ra_sheet_um, ra_pin) * 1e-6;
      r.lgL = std::log10(kEtaPaS * std::max(s.speed_mm_s, 1e-6) * 1e-3 / (p_avg * 1e6 * ra_comb));
      lg_sum += r.lgL;
      ++n_fixed;
    }
    d.rows.push_back(r);
  }
  for (auto& r : d.rows)
    if (!r.rotating) r.lgL -= lg_sum / std::max(1, n_fixed);
  d.bend_fallback.assign(d.pins.size(), std::nan(""));
  std::string missing, label;
  for (size_t p = 0; p < d.pins.size(); ++p) {
    bool rot = false, fixed = false;
    for (const auto& r : d.rows)
      if (r.pin == static_cast<int>(p)) (r.rotating ? rot : fixed) = true;
    const std::string pin = fmt(d.pins[p]) + " mm";
    if (rot) {
      label += (label.empty() ? "" : "; ") + pin + ": line fitted to its rotating-pin rows";
      continue;
    }
    if (!fixed) continue;
    d.missing_rotating = true;
    missing += (missing.empty() ? "" : ", ") + pin;
    double fb = std::nan("");
    if (bending == BendingSource::swift)
      fb = analysis::swift_bending_force(99.71, 1.04, kStripWidthMm, d.pins[p] / 2, kWrapRad,
                                         analysis::ForceBasis::full_strip);
    else if (bending == BendingSource::none)
      fb = 0;
    else if (bending == BendingSource::fe) {
      const PinMap& m = maps.at(d.pins[p]);
      if (!(m.fbend_N >= 0))
        throw InputError(m.provenance + ": --bending fe needs a '# bending_force_N: <N>' line in the map file "
                         "(the frictionless FE run's F_Y - F_X, full strip)");
      fb = m.fbend_N;
    }
    d.bend_fallback[p] = fb;
    if (bending != BendingSource::rotating)
      label += (label.empty() ? "" : "; ") + pin + ": NO rotating-pin rows, F_B = " + fmt(fb, 4) + " N from " +
               bending_source_name(bending);
  }
  if (d.missing_rotating && bending == BendingSource::rotating)
    throw InputError(data.path + ": no rotating-pin rows for the " + missing +
                     " pin(s), so the bending force is unknown; choose a bending model with --bending swift (Eq. 2.1), "
                     "--bending fe (FE maps with a bending_force_N line) or --bending none (mu absorbs F_B)");
  d.bending_label = label;
  if (d.missing_rotating) d.notes.insert(d.notes.begin(), "NO ROTATING-PIN ROWS for the " + missing + " pin(s): bending force from " +
                                                               bending_source_name(bending) + " (every output says so)");
  d.notes.push_back("bending force: " + label);
  d.notes.push_back("pressure maps: " + maps.label());
  return d;
}

bool ModelSpec::has(EffectKind k) const {
  for (const auto& e : effects)
    if (e.kind == k) return true;
  return false;
}

std::string ModelSpec::describe() const {
  std::string s = bending_linear ? "base (linear bending)" : "base (constant bending)";
  for (const auto& e : effects) s += " + " + effect_name(e.kind) + (e.variable.empty() ? "" : "(" + e.variable + ")");
  return s;
}

namespace {

struct Layout {
  std::vector<int> mu_rd, mu_td;  // per cell, -1 absent
  std::vector<int> eff_start;     // per effect
  int n = 0;
};

Layout layout(const Design& d, const ModelSpec& spec) {
  Layout L;
  for (size_t c = 0; c < d.cells.size(); ++c) {
    L.mu_rd.push_back(d.cell_rd[c] ? L.n++ : -1);
    L.mu_td.push_back(d.cell_td[c] ? L.n++ : -1);
  }
  for (const auto& e : spec.effects) {
    L.eff_start.push_back(L.n);
    switch (e.kind) {
      case EffectKind::pressure_mu: L.n += static_cast<int>(d.cells.size()); break;
      case EffectKind::pin_surface: L.n += static_cast<int>(d.pins.size()) - 1; break;
      case EffectKind::bending_tension: break;
      case EffectKind::categorical: L.n += std::max(0, e.n_levels - 1); break;
      case EffectKind::direction_level: L.n += d.n_dir_params; break;
      case EffectKind::direction_fourier: L.n += 2; break;
      default: L.n += 1;
    }
  }
  return L;
}

double predict_row(const Design& d, const Fit& f, const Layout& L, const Eigen::VectorXd& th, int i, double* mu_out,
                   const Row* override_row = nullptr, double* p_out = nullptr) {
  const Row& r = override_row ? *override_row : d.rows[i];
  const double bend = f.b0[r.pin] + f.b1[r.pin] * r.fback;
  if (std::isnan(bend)) return std::nan("");
  if (r.rotating) return r.fback + bend;
  const int ir = L.mu_rd[r.cell], it = L.mu_td[r.cell];
  double mu0;
  if (ir >= 0 && it >= 0) mu0 = ellipse(th[ir], th[it], r.phi);
  else mu0 = th[ir >= 0 ? ir : it];
  if (!f.seen.empty() && ((ir >= 0 && !f.seen[ir]) || (it >= 0 && !f.seen[it]))) return std::nan("");
  double a1 = 0, factor = 1, pinf = 1;
  for (size_t k = 0; k < f.spec.effects.size(); ++k) {
    const Effect& e = f.spec.effects[k];
    const int s = L.eff_start[k];
    switch (e.kind) {
      case EffectKind::pressure_mu: a1 = th[s + r.cell]; break;
      case EffectKind::stribeck: factor += th[s] * r.lgL; break;
      case EffectKind::depletion: factor -= th[s] * (1 - std::exp(-r.sliding / e.lambda_mm)); break;
      case EffectKind::direction_harmonic: factor += th[s] * r.sin2; break;
      case EffectKind::drift:
      case EffectKind::generic_linear: factor += th[s] * f.drift_z[k][i]; break;
      case EffectKind::generic_saturating: factor += th[s] * std::tanh(f.drift_z[k][i]); break;
      case EffectKind::categorical:
        if (f.level[k][i] > 0) factor += th[s + f.level[k][i] - 1];
        break;
      case EffectKind::direction_level:
        if (r.dir >= 0 && d.dir_param[r.dir] >= 0) factor += th[s + d.dir_param[r.dir]];
        break;
      case EffectKind::direction_fourier: factor += th[s] * r.sin2 + th[s + 1] * r.four2; break;
      case EffectKind::pin_surface:
        if (r.pin > 0) pinf += th[s + r.pin - 1];
        break;
      case EffectKind::bending_tension: break;
    }
  }
  double ff = 0, mu = 0;
  const int iters = a1 != 0 ? 4 : 1;
  const double bend_ref = f.b0[r.pin] + f.b1[r.pin] * r.fref;
  for (int k = 0; k < iters; ++k) {  // the map follows the mean tension (Eq. 2.2), friction included
    mu = (mu0 + a1 * map_pressure(r, bend, ff, bend_ref)) * factor * pinf;
    ff = r.fback * (std::exp(mu * kWrapRad) - 1);
  }
  if (mu_out) *mu_out = mu;
  if (p_out) *p_out = map_pressure(r, bend, ff, bend_ref);
  return r.fback + bend + ff;
}

// Per-pin least-squares bending line on the training rotating rows.
void fit_bending(const Design& d, const std::vector<int>& train, bool linear, Fit& f) {
  const size_t np = d.pins.size();
  f.b0.assign(np, std::nan(""));
  f.b1.assign(np, 0.0);
  for (size_t p = 0; p < np; ++p) {
    std::vector<double> x, y;
    for (int i : train)
      if (d.rows[i].rotating && d.rows[i].pin == static_cast<int>(p)) {
        x.push_back(d.rows[i].fback);
        y.push_back(d.rows[i].y - d.rows[i].fback);
      }
    if (x.empty()) {
      f.b0[p] = p < d.bend_fallback.size() ? d.bend_fallback[p] : std::nan("");
      continue;
    }
    const double n = x.size();
    double mx = 0, my = 0;
    for (size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
    double sxx = 0, sxy = 0;
    for (size_t k = 0; k < x.size(); ++k) sxx += (x[k] - mx) * (x[k] - mx), sxy += (x[k] - mx) * (y[k] - my);
    const bool line = linear && x.size() >= 3 && sxx > 1e-9;
    const double b1 = line ? sxy / sxx : 0.0, b0 = my - b1 * mx;
    double rss = 0;
    for (size_t k = 0; k < x.size(); ++k) rss += std::pow(y[k] - b0 - b1 * x[k], 2);
    const double dof = n - (line ? 2 : 1);
    const double s2 = dof > 0 ? rss / dof : 0;
    f.b0[p] = b0;
    f.b1[p] = b1;
    const std::string pin = fmt(d.pins[p]) + " mm";
    if (line) {
      f.params.push_back({"bending b1 " + pin, b1, std::sqrt(s2 / sxx), "-"});
      f.params.push_back({"bending b0 " + pin, b0, std::sqrt(s2 * (1 / n + mx * mx / sxx)), "N"});
    } else {
      f.params.push_back({"bending F_B " + pin, b0, std::sqrt(s2 / n), "N"});
    }
  }
}

std::vector<std::string> friction_names(const Design& d, const ModelSpec& spec, const Layout& L,
                                        const std::vector<std::vector<std::string>>& level_names) {
  std::vector<std::string> n(L.n);
  for (size_t c = 0; c < d.cells.size(); ++c) {
    if (L.mu_rd[c] >= 0) n[L.mu_rd[c]] = "mu_RD [" + d.cells[c] + "]";
    if (L.mu_td[c] >= 0) n[L.mu_td[c]] = "mu_TD [" + d.cells[c] + "]";
  }
  for (size_t k = 0; k < spec.effects.size(); ++k) {
    const Effect& e = spec.effects[k];
    const int s = L.eff_start[k];
    switch (e.kind) {
      case EffectKind::pressure_mu:
        for (size_t c = 0; c < d.cells.size(); ++c) n[s + c] = "a1 [" + d.cells[c] + "] (1/MPa)";
        break;
      case EffectKind::pin_surface:
        for (size_t p = 1; p < d.pins.size(); ++p) n[s + p - 1] = "s_pin " + fmt(d.pins[p]) + " mm";
        break;
      case EffectKind::depletion: n[s] = "beta depletion (lambda = " + fmt(e.lambda_mm) + " mm)"; break;
      case EffectKind::stribeck: n[s] = "beta per decade of L"; break;
      case EffectKind::direction_harmonic: n[s] = "beta sin^2(2 phi)"; break;
      case EffectKind::drift:
      case EffectKind::generic_linear: n[s] = "beta per SD of " + e.variable; break;
      case EffectKind::generic_saturating: n[s] = "beta tanh(z) of " + e.variable; break;
      case EffectKind::categorical:
        for (int l = 1; l < e.n_levels; ++l) n[s + l - 1] = "g [" + e.variable + " = " + level_names[k][l] + "]";
        break;
      case EffectKind::direction_level:
        for (size_t a = 0; a < d.fixed_directions.size(); ++a)
          if (d.dir_param[a] >= 0) n[s + d.dir_param[a]] = "g [direction " + fmt(d.fixed_directions[a]) + " deg]";
        break;
      case EffectKind::direction_fourier:
        n[s] = "c1 sin^2(2 phi)";
        n[s + 1] = "c2 (cos 2phi - cos 6phi)/2";
        break;
      case EffectKind::bending_tension: break;
    }
  }
  return n;
}

// Levenberg-Marquardt on residual function r(theta) (numerical Jacobian of the
// prediction); returns the final SSE and leaves J at the solution.
double levenberg_marquardt(Eigen::VectorXd& th, const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& resid,
                           Eigen::MatrixXd& J, bool& converged) {
  const int p = static_cast<int>(th.size());
  Eigen::VectorXd r = resid(th);
  double sse = r.squaredNorm(), lambda = 1e-3;
  J.resize(r.size(), p);
  auto jacobian = [&]() {
    for (int j = 0; j < p; ++j) {
      Eigen::VectorXd t2 = th;
      const double h = 1e-7 * std::max(1.0, std::abs(th[j]));
      t2[j] += h;
      J.col(j) = (r - resid(t2)) / h;  // d(prediction)/d(theta)
    }
  };
  converged = false;
  for (int it = 0; it < 100; ++it) {
    jacobian();
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 20; ++tries) {
      Eigen::MatrixXd Ad = A;
      for (int j = 0; j < p; ++j) Ad(j, j) += lambda * std::max(A(j, j), 1e-12);
      const Eigen::VectorXd t2 = th + Ad.ldlt().solve(g);
      const Eigen::VectorXd r2 = resid(t2);
      const double s2 = r2.squaredNorm();
      if (std::isfinite(s2) && s2 < sse) {
        const double rel = (sse - s2) / std::max(sse, 1e-300);
        th = t2;
        r = r2;
        sse = s2;
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
        if (rel < 1e-12) converged = true;
        break;
      }
      lambda *= 10;
    }
    if (!improved || converged) {
      converged = true;
      break;
    }
  }
  jacobian();
  return sse;
}

}  // namespace

Fit fit_model(const Design& d, const ModelSpec& spec, const std::vector<int>& train_in) {
  std::vector<int> train = train_in;
  if (train.empty())
    for (size_t i = 0; i < d.rows.size(); ++i) train.push_back(static_cast<int>(i));
  Fit f;
  f.spec = spec;
  fit_bending(d, train, spec.bending_linear || spec.has(EffectKind::bending_tension), f);
  const Layout L = layout(d, spec);
  f.drift_z.assign(spec.effects.size(), {});
  f.level.assign(spec.effects.size(), {});
  f.level_names.assign(spec.effects.size(), {});
  for (size_t k = 0; k < spec.effects.size(); ++k) {
    const EffectKind kk = spec.effects[k].kind;
    if (kk == EffectKind::drift || kk == EffectKind::generic_linear || kk == EffectKind::generic_saturating)
      f.drift_z[k] = d.zscore(spec.effects[k].variable);
    if (kk == EffectKind::categorical) f.level[k] = d.levels(spec.effects[k].variable, &f.level_names[k]);
  }
  std::vector<int> rows;
  for (int i : train)
    if (!d.rows[i].rotating && !std::isnan(f.b0[d.rows[i].pin])) rows.push_back(i);
  // Initial mu per cell and direction from Eq. (5.1) row by row.
  Eigen::VectorXd th = Eigen::VectorXd::Zero(L.n);
  std::vector<double> sum(L.n, 0.0), cnt(L.n, 0.0);
  for (int i : rows) {
    const Row& r = d.rows[i];
    const double ffric = r.y - r.fback - (f.b0[r.pin] + f.b1[r.pin] * r.fback);
    const double mu = ffric > 0 ? analysis::mu_from_friction(ffric, r.fback, kWrapRad) : 0.0;
    const int k = (r.phi < M_PI / 4 ? L.mu_rd : L.mu_td)[r.cell];
    sum[k] += mu;
    cnt[k] += 1;
  }
  for (size_t c = 0; c < d.cells.size(); ++c)
    for (int k : {L.mu_rd[c], L.mu_td[c]})
      if (k >= 0) th[k] = cnt[k] > 0 ? sum[k] / cnt[k] : 0.1;
  f.seen.assign(L.n, 1);
  for (size_t c = 0; c < d.cells.size(); ++c)
    for (int k : {L.mu_rd[c], L.mu_td[c]})
      if (k >= 0 && cnt[k] == 0) f.seen[k] = 0;
  const int n = static_cast<int>(rows.size()), p = L.n;
  auto resid = [&](const Eigen::VectorXd& t) {
    Eigen::VectorXd r(n);
    for (int k = 0; k < n; ++k) r[k] = d.rows[rows[k]].y - predict_row(d, f, L, t, rows[k], nullptr);
    return r;
  };
  Eigen::MatrixXd J;
  double sse = 0;
  if (n > 0) sse = levenberg_marquardt(th, resid, J, f.converged);
  f.theta = th;
  f.rss = sse;
  f.n_fixed = n;
  f.n_friction_params = p;
  // Standard errors: s^2 (J^T J)^-1 at the solution.
  if (n > 0 && p > 0) {
    const double s2 = n > p ? sse / (n - p) : 0.0;
    const Eigen::MatrixXd cov = (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse() * s2;
    const auto names = friction_names(d, spec, L, f.level_names);
    for (int j = 0; j < p; ++j) f.params.push_back({names[j], th[j], std::sqrt(std::max(0.0, cov(j, j))), "-"});
  }
  return f;
}

JointFit fit_joint(const Design& d, const ModelSpec& spec) {
  Fit f = fit_model(d, spec);
  const Layout L = layout(d, spec);
  const bool linear = spec.bending_linear || spec.has(EffectKind::bending_tension);
  std::vector<int> pins;  // pins with a bending line
  for (size_t p = 0; p < d.pins.size(); ++p)
    if (!std::isnan(f.b0[p])) pins.push_back(static_cast<int>(p));
  const int nb = static_cast<int>(pins.size()) * (linear ? 2 : 1);
  Eigen::VectorXd th(nb + L.n);
  for (size_t k = 0; k < pins.size(); ++k) {
    th[k] = f.b0[pins[k]];
    if (linear) th[pins.size() + k] = f.b1[pins[k]];
  }
  th.tail(L.n) = f.theta;
  std::vector<int> rows;
  for (size_t i = 0; i < d.rows.size(); ++i)
    if (!std::isnan(f.b0[d.rows[i].pin])) rows.push_back(static_cast<int>(i));
  auto resid = [&](const Eigen::VectorXd& t) {
    Fit g = f;
    for (size_t k = 0; k < pins.size(); ++k) {
      g.b0[pins[k]] = t[k];
      if (linear) g.b1[pins[k]] = t[pins.size() + k];
    }
    const Eigen::VectorXd tf = t.tail(L.n);
    Eigen::VectorXd r(rows.size());
    for (size_t k = 0; k < rows.size(); ++k) r[k] = d.rows[rows[k]].y - predict_row(d, g, L, tf, rows[k], nullptr);
    return r;
  };
  Eigen::MatrixXd J;
  bool conv = false;
  JointFit j;
  j.rss = levenberg_marquardt(th, resid, J, conv);
  j.n = static_cast<int>(rows.size());
  j.p = static_cast<int>(th.size());
  return j;
}

double predict(const Design& d, const Fit& f, int i) {
  const Layout L = layout(d, f.spec);
  return predict_row(d, f, L, f.theta, i, nullptr);
}

double predict_mu(const Design& d, const Fit& f, int i) {
  const Layout L = layout(d, f.spec);
  double mu = std::nan("");
  predict_row(d, f, L, f.theta, i, &mu);
  return mu;
}

double predict_mu_at(const Design& d, const Fit& f, int i, double phi_rad, double* p_out) {
  const Layout L = layout(d, f.spec);
  Row r = d.rows[i];
  r.phi = phi_rad;
  r.sin2 = std::pow(std::sin(2 * phi_rad), 2);
  r.four2 = 0.5 * (std::cos(2 * phi_rad) - std::cos(6 * phi_rad));
  r.dir = -1;  // RD and TD carry no direction-level factor
  double mu = std::nan("");
  predict_row(d, f, L, f.theta, i, &mu, &r, p_out);
  return mu;
}

}  // namespace drawbend::loop
