// The wild generator's design, base truth, outlet forces, sizing and file
// (wild_synth.hpp).  The planted effect is drawn in wild_effects.cpp.  It
// calls nothing of the loop's model: its laws are written out here.
#include "loop/wild_synth.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include "core/csv.hpp"
#include "loop/wild_detail.hpp"

namespace drawbend::loop {

const std::vector<std::string>& wild_classes() {
  static const std::vector<std::string> c = {"level", "smooth", "interaction", "channel", "test-level", "null"};
  return c;
}

namespace wild {

const char* const kLubNames[3] = {"Castrol Iloform PN 226", "Fuchs Renoform MCO 3802", "rapeseed oil"};

namespace {
constexpr double kWildWrap = 1.5707963267948966;  // 90 deg wrap [rad]
constexpr double kWildWidth = 25.4;               // strip width [mm]
// Bending lines and back-tension ranges per pin (Table 5.3, as synth.cpp).
const Pin kPins[3] = {{12.7, 1450, 1800, -0.0625, 396.84}, {25.4, 1650, 2050, -0.0123, 129.39},
                      {42.0, 1500, 2100, -0.0118, 70.133}};
const char* const kOperators[3] = {"R. Visser", "T. Smit", "E. Mulder"};
const char* const kClean[3] = {"acetone", "IPA", "dry wipe"};
std::string two(int v) { return (v < 10 ? "0" : "") + std::to_string(v); }
}  // namespace

namespace {
// The set's factors: directions, speeds, lubricants, friction, batches (their
// Rp0.2 in s, their mean blank thickness [um] returned) and the pins' lines.
std::vector<double> draw_factors(Rng& r, Set& s) {
  const std::vector<std::vector<double>> dir_sets = {{0, 90}, {0, 45, 90}, {0, 30, 60, 90}, {0, 15, 45, 75, 90}};
  s.dirs = r.pick(dir_sets);
  s.levels = r.u() < 0.5;
  std::vector<double> lv = {5, 10, 20, 40, 80, 160};
  r.shuffle(lv);
  s.speed_levels.assign(lv.begin(), lv.begin() + 3);
  std::sort(s.speed_levels.begin(), s.speed_levels.end());
  const double ul = r.u();
  s.nlub = ul < 0.5 ? 1 : ul < 0.85 ? 2 : 3;
  s.lub_f = {1.0, r.u(0.6, 0.95), r.u(1.05, 1.3)};
  s.lev_f = {r.u(0.88, 1.12), r.u(0.88, 1.12), r.u(0.88, 1.12)};
  s.mu_rd = r.u(0.06, 0.13);
  s.mu_td = s.mu_rd * r.u(0.8, 1.1);
  s.nbatch = 2 + r.i(3), s.nfix = 2 + r.i(2), s.nop = 2 + r.i(2);
  s.prestrains = r.u() < 0.5 ? std::vector<double>{0, 2, 5} : std::vector<double>{0, 2, 5, 10};
  std::vector<double> batch_t(s.nbatch);
  for (int b = 0; b < s.nbatch; ++b) {
    s.batch_rp02.push_back(std::round(10 * (98 + 5 * r.n())) / 10);
    batch_t[b] = 1040 + 12 * r.n();
  }
  for (int p = 0; p < 3; ++p) {
    s.pins[p] = kPins[p];
    s.pins[p].b0 *= 1 + 0.05 * r.n();
    s.pins[p].b1 *= 1 + 0.05 * r.n();
    const double f = 1 + 0.05 * r.n();
    s.pins[p].lo *= f, s.pins[p].hi *= f;
  }
  return batch_t;
}

// Per pin, T fixed-pin tests over the shuffled cells (at least 2 per cell)
// and 3 rotating-pin tests; batch_t: each batch's mean blank thickness [um].
void draw_tests(Rng& r, Set& s, const std::vector<double>& batch_t) {
  const int nsp = s.levels ? 3 : 1;
  const int ncells = s.nlub * nsp * (s.dirs.size() <= 2 ? 2 : 1);
  const int T = std::max(7 + r.i(16), 2 * ncells);
  for (int p = 0; p < 3; ++p) {
    std::vector<std::array<int, 3>> combos;  // direction, lubricant, speed level
    for (size_t d = 0; d < s.dirs.size(); ++d)
      for (int l = 0; l < s.nlub; ++l)
        for (int v = 0; v < nsp; ++v) combos.push_back({static_cast<int>(d), l, v});
    r.shuffle(combos);
    for (int j = 0; j < T + 3; ++j) {
      Test x;
      x.pin = p;
      x.rotating = j >= T;
      const auto& c = combos[j % combos.size()];
      x.dir = x.rotating ? 0 : c[0];
      x.lub = x.rotating ? 0 : c[1];
      if (s.levels) x.speed_level = x.rotating ? 1 : c[2], x.speed = s.speed_levels[x.speed_level];
      else x.speed = x.rotating ? 25.4 : std::round(10 * std::exp(r.u(std::log(4.0), std::log(150.0)))) / 10;
      x.rows = 5 + r.i(16);
      x.length = r.u(120, 260);
      x.batch = r.i(s.nbatch);
      x.thick_um = std::round(batch_t[x.batch] + 8 * r.n());
      x.ra_um = std::round(100 * 0.36 * std::exp(0.3 * r.n())) / 100;
      const double seen = x.ra_um + 0.06 * r.n();  // the grade is read off by eye
      x.grade = seen < 0.28 ? 0 : seen < 0.36 ? 1 : seen < 0.46 ? 2 : 3;
      x.prestrain = r.i(static_cast<int>(s.prestrains.size()));
      x.fixture = r.i(s.nfix), x.clean = r.i(3);
      x.oil_missing = r.u() < 0.04;
      s.tests.push_back(x);
    }
  }
}

// The run order (order[k] = index of the k-th test run): run number,
// operator shift, date, id, strip, pin temperature and oil age per test.
std::vector<int> schedule(Rng& r, Set& s) {
  std::vector<int> order(s.tests.size());
  std::iota(order.begin(), order.end(), 0);
  r.shuffle(order);
  const int day0 = 2 + r.i(18), change_every = 3 + r.i(4);
  for (size_t k = 0; k < order.size(); ++k) {
    Test& x = s.tests[order[k]];
    const int day = static_cast<int>(k / 14), slot = static_cast<int>(k % 14);
    x.run = static_cast<int>(k) + 1;
    x.op = static_cast<int>(k * s.nop / order.size());
    x.date = "2026-05-" + two(day0 + day);
    x.id = "W" + two(day0 + day) + "-" + std::to_string(300 + k) + (x.rotating ? "R" : "");
    x.strip = "K" + std::to_string(7000 + 23 * k + r.i(23));
    x.temp_F = std::round(10 * (66 + 11 * slot / 13.0 + 1.2 * r.n())) / 10;
    x.oil_age = std::round(100 * ((day + day0) % change_every + slot / 14.0)) / 100;
  }
  return order;
}

// The rows in run order: back tension stepped in a shuffled order along the
// sliding distance, pin travel since the last polish, clock and load-cell temperature.
void draw_rows(Rng& r, Set& s, const std::vector<int>& order) {
  s.clock0 = 7 * 3600 + r.i(3600);
  std::vector<double> travel(3, 0.0);
  int clock = s.clock0;
  for (size_t k = 0; k < order.size(); ++k) {
    const Test& x = s.tests[order[k]];
    if (k % 14 == 0) clock = s.clock0 + r.i(1200);
    if (r.u() < 0.08) travel[x.pin] = 0;  // pin re-polished
    std::vector<int> slot(x.rows);
    std::iota(slot.begin(), slot.end(), 0);
    r.shuffle(slot);
    for (int j = 0; j < x.rows; ++j) {
      const Pin& p = s.pins[x.pin];
      RowT w;
      w.test = order[k];
      w.F = std::round(10 * (p.lo + (p.hi - p.lo) * slot[j] / (x.rows - 1))) / 10;
      w.slide = std::round(100 * (15 + x.length * j / (x.rows - 1))) / 100;
      travel[x.pin] += x.length / std::max(1, x.rows - 1) / 1000;
      w.travel_m = std::round(1000 * travel[x.pin]) / 1000;
      clock += 9 + r.i(25);
      w.clock = clock;
      w.lc_temp = std::round(100 * (19.5 + 3.0 * (clock - s.clock0) / 36000.0 + 0.15 * r.n())) / 100;
      s.rows.push_back(w);
    }
    clock += 300 + r.i(600);  // strip change
  }
}
}  // namespace

Set draw_set(Rng& r) {
  Set s;
  const std::vector<double> batch_t = draw_factors(r, s);
  draw_tests(r, s, batch_t);
  const std::vector<int> order = schedule(r, s);
  s.has_strip = r.u() < 0.7, s.has_date = r.u() < 0.7, s.has_clock = r.u() < 0.7, s.has_remark = r.u() < 0.7;
  draw_rows(r, s, order);
  s.extra_columns = {"run_no", "operator", "sheet_batch", "batch_rp02_MPa", "blank_thickness_um", "surface_grade",
                     "ra_strip_um", "pre_strain_pct", "fixture", "clean_method", "pin_temp_F", "oil_age_days",
                     "pin_travel_m", "load_cell_temp_C"};
  const std::pair<bool, const char*> optional[] = {
      {s.has_strip, "strip_id"}, {s.has_date, "date"}, {s.has_clock, "clock"}, {s.has_remark, "remark"}};
  for (const auto& [on, name] : optional)
    if (on) s.extra_columns.push_back(name);
  return s;
}

std::string cell_text(const Set& s, size_t i, const std::string& c) {
  const RowT& w = s.rows[i];
  const Test& x = s.tests[w.test];
  if (c == "run_no") return std::to_string(x.run);
  if (c == "operator") return kOperators[x.op];
  if (c == "sheet_batch") return "B" + std::to_string(31 + 7 * x.batch);
  if (c == "batch_rp02_MPa") return fmt(s.batch_rp02[x.batch], 5);
  if (c == "blank_thickness_um") return fmt(x.thick_um, 6);
  if (c == "surface_grade") return "R" + std::to_string(x.grade + 1);
  if (c == "ra_strip_um") return fmt(x.ra_um, 3);
  if (c == "pre_strain_pct") return fmt(s.prestrains[x.prestrain], 3);
  if (c == "fixture") return "K" + std::to_string(x.fixture + 1);
  if (c == "clean_method") return kClean[x.clean];
  if (c == "pin_temp_F") return fmt(x.temp_F, 4);
  if (c == "oil_age_days") return x.oil_missing ? "" : fmt(x.oil_age, 4);
  if (c == "pin_travel_m") return fmt(w.travel_m, 6);
  if (c == "load_cell_temp_C") return fmt(w.lc_temp, 4);
  if (c == "strip_id") return x.strip;
  if (c == "date") return x.date;
  if (c == "clock") return two(w.clock / 3600 % 24) + ":" + two(w.clock / 60 % 60) + ":" + two(w.clock % 60);
  if (c == "remark") {
    const int h = (x.run * 7919) % 10;
    const char* const notes[4] = {"strip edge burred, re-clamped", "oil topped up by hand before this test",
                                  "pin wiped, small pick-up visible", "load cell re-zeroed"};
    return h < 2 ? notes[(x.run + h) % 4] : "";
  }
  if (c == "test_id") return x.id;
  if (c == "pin" || c == "pin_diameter_mm") return fmt(s.pins[x.pin].d);
  if (c == "direction_deg") return fmt(s.dirs[x.dir]);
  if (c == "speed_mm_s") return fmt(x.speed);
  if (c == "lubricant") return kLubNames[x.lub];
  if (c == "back_tension_N") return fmt(w.F);
  if (c == "sliding_distance_mm") return fmt(w.slide);
  if (c == "time_s") return fmt(std::round(1000 * w.slide / x.speed) / 1000);
  throw std::logic_error("wild_synth: no column '" + c + "'");
}

double carrier_value(const Set& s, size_t i, const std::string& c) {
  const RowT& w = s.rows[i];
  const Test& x = s.tests[w.test];
  if (c == "oil_age_days") return x.oil_age;
  if (c == "pressure") return row_pressure(s, i);
  if (c == "batch_rp02_MPa") return s.batch_rp02[x.batch];
  if (c == "speed_mm_s") return x.speed;
  return std::stod(cell_text(s, i, c));
}

double row_pressure(const Set& s, size_t i) {
  const RowT& w = s.rows[i];
  return w.F / (s.pins[s.tests[w.test].pin].d / 2 * kWildWidth);
}

std::vector<std::string> aliases_of(const Set& s, const std::string& column, bool numeric) {
  if (column == "pressure") return {"avg_pressure_MPa", "pin", "pin_diameter_mm", "inv_R_per_mm", "back_tension_N"};
  std::vector<std::string> cols = s.extra_columns;
  for (const char* c : {"direction_deg", "speed_mm_s", "lubricant", "pin_diameter_mm", "sliding_distance_mm", "time_s",
                        "back_tension_N"})
    cols.push_back(c);
  std::vector<std::string> out = {column};
  const size_t N = s.rows.size();
  auto num = [](const std::string& t, double& v) {
    try {
      size_t used = 0;
      v = std::stod(t, &used);
      return used == t.size() && std::isfinite(v);
    } catch (...) {
      return false;
    }
  };
  for (const auto& o : cols) {
    if (o == column) continue;
    std::map<std::string, std::string> ab, ba;
    bool same = true;
    for (size_t i = 0; i < N && same; ++i) {
      const std::string a = cell_text(s, i, column), b = cell_text(s, i, o);
      auto [ia, newa] = ab.emplace(a, b);
      auto [ib, newb] = ba.emplace(b, a);
      same = ia->second == b && ib->second == a;
    }
    if (!same) continue;
    if (ab.size() <= 12) {
      out.push_back(o);
      continue;
    }
    if (!numeric) continue;
    std::vector<std::pair<double, double>> pairs;  // same quantity in other units: strictly monotone
    for (const auto& [a, b] : ab) {
      double va = 0, vb = 0;
      if (!num(a, va) || !num(b, vb)) {
        pairs.clear();
        break;
      }
      pairs.push_back({va, vb});
    }
    if (pairs.size() < 2) continue;
    std::sort(pairs.begin(), pairs.end());
    bool up = true, down = true;
    for (size_t k = 1; k < pairs.size(); ++k) up &= pairs[k].second > pairs[k - 1].second, down &= pairs[k].second < pairs[k - 1].second;
    if (up || down) out.push_back(o);
  }
  return out;
}

namespace {

// The outlet forces of a set for an effect of size a on e's channel, and how
// often mu hit its floor of 0.01 in the last evaluation.  The pressure and
// log-speed means over the fixed-pin rows centre the slope channels.
struct Forces {
  const Set& s;
  const Effect& e;
  double p_mean = 0, lv_mean = 0;
  int floor_hits = 0;

  Forces(const Set& set, const Effect& effect) : s(set), e(effect) {
    int nfixed = 0;
    for (size_t i = 0; i < s.rows.size(); ++i)
      if (!s.tests[s.rows[i].test].rotating)
        p_mean += row_pressure(s, i), lv_mean += std::log(s.tests[s.rows[i].test].speed), nfixed++;
    p_mean /= std::max(1, nfixed), lv_mean /= std::max(1, nfixed);
  }
  std::vector<double> operator()(double a) {
    const std::string& ch = e.channel;
    const size_t N = s.rows.size();
    std::vector<double> y(N);
    floor_hits = 0;
    for (size_t i = 0; i < N; ++i) {
      const RowT& w = s.rows[i];
      const Test& x = s.tests[w.test];
      const Pin& p = s.pins[x.pin];
      const double g = e.g[i];
      const double F = ch == "bt_gain" ? w.F * (1 + 0.1 * a * g) : w.F;  // the tension the strip really had
      double bend = p.b0 + p.b1 * F;
      if (ch == "bend") bend *= 1 + a * g;
      double out = F + bend;
      if (!x.rotating) {
        const double phi = s.dirs[x.dir] * M_PI / 180, c = std::cos(phi), sn = std::sin(phi);
        double mu = s.mu_rd * s.mu_td / std::sqrt(s.mu_td * s.mu_td * c * c + s.mu_rd * s.mu_rd * sn * sn);
        mu *= s.lub_f[x.lub] * (x.speed_level >= 0 ? s.lev_f[x.speed_level] : 1.0);
        if (ch == "mu_mult") mu *= 1 + a * g;
        if (ch == "mu_add") mu += 0.1 * a * g;
        if (ch == "mu_pslope") mu *= 1 + a * g * (row_pressure(s, i) / p_mean - 1);
        if (ch == "mu_vslope") mu *= 1 + a * g * (std::log(x.speed) - lv_mean);
        if (mu < 0.01) mu = 0.01, floor_hits++;
        out += F * (std::exp(mu * kWildWrap) - 1);
      }
      if (ch == "offset") out += 100 * a * g;
      y[i] = out;
    }
    return y;
  }
};

// Draws the class's effect into e (and its truth into t) with its size a:
// RMS k noise sd on the outlet force, k drawn; drawn again (at most 20 times)
// when neither sign is feasible.  Returns a (0 for a null set).
double plant(Rng& r, const Set& s, const std::string& cls, const WildOptions& o, Effect& e, Forces& forces,
             BlindTruth& t) {
  const size_t N = s.rows.size();
  const std::vector<double> y0 = forces(0);
  auto rms_of = [&](double a) {
    const std::vector<double> y = forces(a);
    double q = 0;
    for (size_t i = 0; i < N; ++i) q += (y[i] - y0[i]) * (y[i] - y0[i]);
    return std::sqrt(q / N);
  };
  // Rows an effect of size a makes impossible: friction below 0.01, or an
  // outlet force within 6 noise sd of the back tension where the base was not
  // (the file reader rejects an outlet force below the back tension).
  auto infeasible = [&](double a) {
    const std::vector<double> y = forces(a);
    int n = forces.floor_hits;
    for (size_t i = 0; i < N; ++i)
      n += y[i] - s.rows[i].F < std::min(y0[i] - s.rows[i].F, 6 * o.noise_N);
    return n;
  };
  double a = 0;
  for (int attempt = 0; cls != "null"; ++attempt) {
    if (attempt == 20) throw std::logic_error("wild_synth: no feasible effect in 20 draws (seed " + std::to_string(o.seed) + ")");
    BlindTruth d = t;
    e = draw_effect(r, s, cls, d);
    d.k = r.u(2.5, 6);
    const double target = d.k * o.noise_N;
    double sgn = r.u() < 0.5 ? -1 : 1;
    if (!(rms_of(1) > 0)) throw std::logic_error("wild_synth: a planted effect of size 0 (seed " + std::to_string(o.seed) + ")");
    bool ok = false;
    for (int pass = 0; pass < 2 && !ok; ++pass, sgn = -sgn) {  // infeasible one way: the other way
      a = target > 0 ? sgn : 0;
      for (int it = 0; it < 40 && target > 0; ++it) a *= target / rms_of(a);
      ok = infeasible(a) == 0;
    }
    if (!ok) continue;  // neither way: draw the effect again
    t = d;
    t.effect_rms_N = rms_of(a);
    std::vector<int> test_of_row(N);
    for (size_t i = 0; i < N; ++i) test_of_row[i] = s.rows[i].test;
    t.support_tests = effect_support(forces(a), y0, test_of_row);
    break;
  }
  return a;
}

// The truth's law in words for an effect of size a on channel ch (t.law holds
// draw_effect's own addendum).
std::string wild_law(const std::string& cls, const std::string& ch, const BlindTruth& t, double a) {
  const std::string chan_text = ch == "mu_mult" ? "mu (1 + a g)" : ch == "mu_add" ? "mu + 0.1 a g"
                                : ch == "offset" ? "outlet force + 100 a g N" : ch == "bend" ? "F_B (1 + a g)"
                                : ch == "bt_gain" ? "true back tension = recorded (1 + 0.1 a g)"
                                : ch == "mu_pslope" ? "mu (1 + a g (p / p_mean - 1)), p = F / (R w)"
                                : ch == "mu_vslope" ? "mu (1 + a g ln(v / v_geo))" : "";
  return cls == "null" ? "no planted effect"
                       : chan_text + ", g = " + t.shape + " of " + t.variable +
                             (t.cell.empty() ? "" : " in the cell " + t.cell) + " (centred), a = " + fmt(a, 4) + t.law;
}

// The data set: the set's rows with the outlet forces y plus noise, and its extra columns.
Dataset wild_dataset(Rng& r, const Set& s, const WildOptions& o, const std::vector<double>& y) {
  Dataset d;
  d.path = "synthetic-wild";
  d.has_sliding = d.has_time = true;
  d.extra_columns = s.extra_columns;
  d.comments = {" draw-bend tests, wild synthetic set (drawbend synth --generator wild), seed " + std::to_string(o.seed) +
                    ", noise sd " + fmt(o.noise_N) + " N; the truth is in truth.json",
                " units: mm, N, mm/s, s, deg; blank_thickness_um in micrometres, pin_temp_F in Fahrenheit"};
  for (size_t i = 0; i < s.rows.size(); ++i) {
    const RowT& w = s.rows[i];
    const Test& x = s.tests[w.test];
    Sample sm;
    sm.test_id = x.id;
    sm.pin_d_mm = s.pins[x.pin].d;
    sm.rotating = x.rotating;
    sm.direction_deg = s.dirs[x.dir];
    sm.speed_mm_s = x.speed;
    sm.lubricant = kLubNames[x.lub];
    sm.back_tension_N = w.F;
    sm.sliding_mm = w.slide;
    sm.time_s = std::round(1000 * w.slide / x.speed) / 1000;
    sm.outlet_force_N = y[i] + o.noise_N * r.n();
    for (const auto& c : s.extra_columns) sm.extra.push_back(cell_text(s, i, c));
    d.rows.push_back(sm);
  }
  d.rows_read = static_cast<int>(s.rows.size());
  return d;
}

}  // namespace
}  // namespace wild

Dataset synthesize_wild(const WildOptions& o, BlindTruth& t) {
  using namespace wild;
  const auto& classes = wild_classes();
  Rng r{std::mt19937_64(o.seed * 0xD1B54A32D192ED03ULL + 0x77)};
  std::string cls = o.cls;
  if (cls == "random") cls = r.pick(classes);
  if (std::find(classes.begin(), classes.end(), cls) == classes.end())
    throw std::invalid_argument("unknown wild class '" + o.cls + "' (level, smooth, interaction, channel, test-level, null, random)");
  t = {};
  t.cls = cls, t.noise_N = o.noise_N, t.seed = o.seed;
  const Set s = draw_set(r);
  wild::Effect e{"", std::vector<double>(s.rows.size(), 0.0)};  // null: nothing planted
  Forces forces(s, e);
  const double a = plant(r, s, cls, o, e, forces, t);
  const std::vector<double> y = forces(a);
  t.law = wild_law(cls, e.channel, t, a);
  return wild_dataset(r, s, o, y);
}

std::string wild_truth_json(const BlindTruth& t) {
  std::string j = blind_truth_json(t);
  const std::string from = "\"generator\": \"blind\"";
  const size_t at = j.find(from);
  if (at != std::string::npos) j.replace(at, from.size(), "\"generator\": \"wild\"");
  return j;
}

}  // namespace drawbend::loop
