// The loop's design: per-row quantities (cell, direction, map pressure,
// lubricant number, ...) computed once from the data and the pressure maps,
// and the bending force of pins without rotating-pin rows.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "analysis/rope.hpp"
#include "analysis/stribeck.hpp"
#include "core/csv.hpp"
#include "loop/model.hpp"

namespace drawbend::loop {

namespace {
constexpr double kEtaPaS = 1.2;  // Table 3.3 (Ter Haar); enters L only as a constant factor
bool close(double a, double b) { return std::abs(a - b) < 1e-9 * std::max(1.0, std::abs(a)); }
}  // namespace

void set_direction(Row& r, double phi) {
  r.phi = phi;
  r.cos_phi = std::cos(phi);
  r.sin_phi = std::sin(phi);
  r.sin2 = std::pow(std::sin(2 * phi), 2);
  r.four2 = 0.5 * (std::cos(2 * phi) - std::cos(6 * phi));
}

BendingSource bending_source(const std::string& b) {
  if (b == "linear" || b == "constant" || b == "rotating") return BendingSource::rotating;
  if (b == "swift") return BendingSource::swift;
  if (b == "fe") return BendingSource::fe;
  if (b == "none") return BendingSource::none;
  throw std::invalid_argument("--bending: expected linear, constant, swift, fe or none, found '" + b + "'");
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

std::vector<int> Design::levels(const std::string& column, std::vector<std::string>* names) const {
  std::vector<int> out(rows.size(), 0);
  std::map<std::string, int> ix;
  std::vector<std::string> nm;
  const int k = data->extra_index(column);
  if (k < 0 && column != "pin" && column != "direction_deg")
    throw InputError("no categorical column '" + column + "' for a group factor");
  const bool text = column != "pin" && column != "direction_deg";
  // A text column's values by reference, a run of equal values (a test's rows)
  // without a look-up: the same numbering by first appearance.
  const std::string* last = nullptr;
  int last_ix = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const Sample& s = data->rows[i];
    if (text && last && s.extra[k] == *last) {
      out[i] = last_ix;
      continue;
    }
    const std::string v = !text ? (column == "pin" ? fmt(s.pin_d_mm) : fmt(s.direction_deg)) : s.extra[k];
    auto [it, fresh] = ix.emplace(v, static_cast<int>(nm.size()));
    if (fresh) nm.push_back(v);
    out[i] = it->second;
    if (text) last = &s.extra[k], last_ix = it->second;
  }
  if (names) *names = nm;
  return out;
}

void zscore_in_place(std::vector<double>& x) {
  double m = 0, q = 0;
  for (double v : x) m += v;
  m /= x.size();
  for (double v : x) q += (v - m) * (v - m);
  const double sd = std::sqrt(q / std::max<size_t>(1, x.size() - 1));
  for (double& v : x) v = sd > 0 ? (v - m) / sd : 0.0;
}

std::vector<double> Design::zscore(const std::string& column) const {
  std::vector<double> x = values(column);
  zscore_in_place(x);
  return x;
}

std::vector<int> Design::groups(const std::string& by, int* n) const {
  std::vector<int> g(rows.size(), 0);
  if (by == "pin") {
    for (size_t i = 0; i < rows.size(); ++i) g[i] = rows[i].pin;
    *n = static_cast<int>(pins.size());
    return g;
  }
  if (by == "lubricant") {
    std::map<std::string, int> ix;
    for (size_t i = 0; i < rows.size(); ++i)
      g[i] = ix.emplace(data->rows[i].lubricant, static_cast<int>(ix.size())).first->second;
    *n = static_cast<int>(ix.size());
    return g;
  }
  const size_t split = by.find(">=");
  if (split != std::string::npos) {  // "input>=t": two groups, below t and at or above it
    const std::string input = by.substr(0, split);
    if (input != "speed_mm_s" && input != "direction_deg") throw InputError("no model input '" + input + "' to split");
    const double t = std::stod(by.substr(split + 2));
    for (size_t i = 0; i < rows.size(); ++i)
      g[i] = (input == "speed_mm_s" ? data->rows[i].speed_mm_s : data->rows[i].direction_deg) >= t ? 1 : 0;
    *n = 2;
    return g;
  }
  if (by != "speed_mm_s" && by != "direction_deg") throw InputError("no model input '" + by + "' to group by");
  std::vector<double> v(rows.size());
  std::set<double> distinct;
  for (size_t i = 0; i < rows.size(); ++i) {
    v[i] = by == "speed_mm_s" ? data->rows[i].speed_mm_s : data->rows[i].direction_deg;
    if (!rows[i].rotating) distinct.insert(v[i]);
  }
  std::vector<double> cut(distinct.begin(), distinct.end());
  if (cut.size() > 6) {  // tertiles of the distinct values
    const std::vector<double> all = cut;
    cut = {all[all.size() / 3], all[2 * all.size() / 3]};
    for (size_t i = 0; i < rows.size(); ++i) g[i] = static_cast<int>(std::upper_bound(cut.begin(), cut.end(), v[i]) - cut.begin());
    *n = 3;
    return g;
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto it = std::lower_bound(cut.begin(), cut.end(), v[i] - 1e-9);
    g[i] = std::min(static_cast<int>(it - cut.begin()), std::max(0, static_cast<int>(cut.size()) - 1));
  }
  *n = std::max<int>(1, static_cast<int>(cut.size()));
  return g;
}

std::vector<double> Design::values(const std::string& column) const {
  // A pair of columns "a*b" (screen_pairs.cpp): the product of the centred
  // columns (an empty cell at its column's mean, so the product 0 there).
  if (const size_t star = column.find('*'); star != std::string::npos && data->extra_index(column) < 0) {
    std::vector<double> a = values(column.substr(0, star)), b = values(column.substr(star + 1));
    double ma = 0, mb = 0;
    for (size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
    ma /= std::max<size_t>(1, a.size()), mb /= std::max<size_t>(1, b.size());
    for (size_t i = 0; i < a.size(); ++i) a[i] = (a[i] - ma) * (b[i] - mb);
    return a;
  }
  std::vector<double> x(rows.size(), 0.0);
  // Which column, decided once (not per row).
  // nominal_pressure_MPa: Eq. 2.2 at the back tension (F_x = F_y, no friction),
  // fixed by the test's design, not by the measured force; ln_speed_mm_s: the
  // log of the speed (the products of forms.cpp's FormPlans::products).
  enum class C { time, sliding, back, speed, direction, pin_d, inv_r, nominal_p, ln_speed, extra };
  const C c = column == "time_s" ? C::time : column == "sliding_distance_mm" ? C::sliding
            : column == "back_tension_N" ? C::back : column == "speed_mm_s" ? C::speed
            : column == "direction_deg" ? C::direction : column == "pin_diameter_mm" ? C::pin_d
            : column == "inv_R_per_mm" ? C::inv_r : column == kNominalPressure ? C::nominal_p
            : column == kLnSpeed ? C::ln_speed : C::extra;
  const int k = c == C::extra ? data->extra_index(column) : -1;
  if (c == C::extra && k < 0 && !rows.empty()) throw InputError("no numeric column '" + column + "' for a linear term");
  std::vector<size_t> empty;  // rows with an empty cell in the column (missing values)
  for (size_t i = 0; i < rows.size(); ++i) {
    const Sample& s = data->rows[i];
    double v;
    switch (c) {
      case C::time: v = s.time_s; break;
      case C::sliding: v = s.sliding_mm; break;
      case C::back: v = s.back_tension_N; break;
      case C::speed: v = s.speed_mm_s; break;
      case C::direction: v = s.direction_deg; break;
      case C::pin_d: v = s.pin_d_mm; break;
      case C::inv_r: v = 2 / s.pin_d_mm; break;
      case C::nominal_p:
        v = analysis::average_pressure(s.back_tension_N, s.back_tension_N, s.pin_d_mm / 2, kStripWidthMm,
                                       analysis::ForceBasis::full_strip);
        break;
      case C::ln_speed:
        if (!(s.speed_mm_s > 0)) throw InputError("column 'speed_mm_s' is not positive: no log-speed term");
        v = std::log(s.speed_mm_s);
        break;
      default:
        if (s.extra[k].empty()) {
          empty.push_back(i);
          continue;
        }
        try {
          v = std::stod(s.extra[k]);
        } catch (const std::exception&) {
          throw InputError("column '" + column + "' is not numeric: no linear term");
        }
    }
    x[i] = v;
  }
  // Missing values (as the screen reads them: make_candidates) take the mean of
  // the column's values, so an effect's term there is its value at the centre
  // and the rows with a value carry its fit; a column with no value has none.
  if (!empty.empty()) {
    if (empty.size() == rows.size()) throw InputError("column '" + column + "' has no value: no linear term");
    double m = 0;
    size_t j = 0;
    for (size_t i = 0; i < rows.size(); ++i)
      if (j < empty.size() && empty[j] == i) ++j;
      else m += x[i];
    m /= static_cast<double>(rows.size() - empty.size());
    for (size_t i : empty) x[i] = m;
  }
  return x;
}

namespace {

// The pins, the fixed-pin directions and speeds, and whether direction and
// speed are cell levels.
void design_levels(Design& d, const Dataset& data) {
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
}

// A fixed-pin row: its cell, map, direction and lubricant number (Eq. 3.1; not yet centred).
void fixed_pin_row(Design& d, const MapLibrary& maps, double Ra_sheet_um, int ra,
                   std::map<std::string, int>& cell_index, const Sample& s, Row& r) {
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
  const double p_avg = analysis::average_pressure(s.back_tension_N, s.back_tension_N, s.pin_d_mm / 2, kStripWidthMm,
                                                  analysis::ForceBasis::full_strip);  // MPa, F_x = F_y
  double ra_pin = 0.1;  // Table 5.2
  if (ra >= 0) {
    try {
      ra_pin = std::stod(s.extra[ra]);
    } catch (...) {
    }
  }
  analysis::StribeckParams lub;  // Eq. 3.1's inputs: the combined roughness and the viscosity
  lub.Ra_um = std::hypot(Ra_sheet_um, ra_pin);
  lub.eta_Pa_s = kEtaPaS;
  r.lgL = std::log10(analysis::lubricant_number(std::max(s.speed_mm_s, 1e-6), p_avg, lub));
}

// The bending force of pin p without rotating-pin rows, from the chosen source.
double fallback_bending_force(const Design& d, const MapLibrary& maps, BendingSource bending, size_t p) {
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
  return fb;
}

// Each pin's bending force: a line fitted to its rotating-pin rows, or (none)
// the fallback, said in the notes; no fallback for --bending rotating is an error.
void bending_fallback(Design& d, const Dataset& data, const MapLibrary& maps, BendingSource bending) {
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
    const double fb = fallback_bending_force(d, maps, bending, p);
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
}

}  // namespace

Design make_design(const Dataset& data, const MapLibrary& maps, double Ra_sheet_um, BendingSource bending) {
  Design d;
  d.data = &data;
  d.maps = &maps;
  design_levels(d, data);
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
    set_direction(r, s.direction_deg * M_PI / 180.0);
    r.sliding = std::isnan(s.sliding_mm) ? 0.0 : s.sliding_mm;
    if (!s.rotating) {
      fixed_pin_row(d, maps, Ra_sheet_um, ra, cell_index, s, r);
      lg_sum += r.lgL;
      ++n_fixed;
    }
    d.rows.push_back(r);
  }
  for (auto& r : d.rows)
    if (!r.rotating) r.lgL -= lg_sum / std::max(1, n_fixed);
  bending_fallback(d, data, maps, bending);
  d.notes.push_back("pressure maps: " + maps.label());
  return d;
}

}  // namespace drawbend::loop
