// The wild generator's planted effect (wild_synth.hpp): carrier, shape or
// level pattern, channel and cell, drawn per set from the seed.  Written
// without opening the loop's effect library or generator 1's effect drawing.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

#include "core/csv.hpp"
#include "loop/wild_detail.hpp"

namespace drawbend::loop::wild {

namespace {

constexpr double kTwoPi = 6.283185307179586;

struct Carrier {
  std::string name;
  bool numeric = true;   ///< values through carrier_value (else levels of its text)
  bool ordinal = false;  ///< levels have an order (numeric few-level or graded codes)
  bool log_x = false;    ///< shapes act on log(value) (speed)
};

// Shapes on x in [0, 1], parameters drawn once per set.
struct Shape {
  std::string name;
  std::function<double(double)> f;
};
Shape draw_shape(Rng& r, const std::vector<std::string>& allowed = {}) {
  static const std::vector<std::string> all = {"linear", "log",  "power", "exp-saturation", "exp-decay", "step",
                                               "hinge",  "plateau", "bump", "U",            "sinusoid"};
  const std::string k = r.pick(allowed.empty() ? all : allowed);
  if (k == "linear") return {k, [](double x) { return x; }};
  if (k == "log") {
    const double c = std::exp(r.u(std::log(3.0), std::log(100.0)));
    return {"log(1 + " + fmt(c, 3) + " x)", [c](double x) { return std::log1p(c * x) / std::log1p(c); }};
  }
  if (k == "power") {
    const double q = r.u() < 0.5 ? r.u(0.25, 0.6) : r.u(1.8, 3.5);
    return {"x^" + fmt(q, 3), [q](double x) { return std::pow(std::max(x, 0.0), q); }};
  }
  if (k == "exp-saturation") {
    const double tau = r.u(0.04, 0.3);
    return {"1 - exp(-x / " + fmt(tau, 3) + ")", [tau](double x) { return 1 - std::exp(-x / tau); }};
  }
  if (k == "exp-decay") {
    const double tau = r.u(0.04, 0.3);
    return {"exp(-x / " + fmt(tau, 3) + ")", [tau](double x) { return std::exp(-x / tau); }};
  }
  if (k == "step") {
    const double x0 = r.u(0.25, 0.75);
    return {"step at x = " + fmt(x0, 3), [x0](double x) { return x >= x0 ? 1.0 : 0.0; }};
  }
  if (k == "hinge") {
    const double x0 = r.u(0.2, 0.7);
    return {"max(0, x - " + fmt(x0, 3) + ")", [x0](double x) { return std::max(0.0, x - x0); }};
  }
  if (k == "plateau") {
    const double x0 = r.u(0.2, 0.6);
    return {"min(x / " + fmt(x0, 3) + ", 1)", [x0](double x) { return std::min(x / x0, 1.0); }};
  }
  if (k == "bump") {
    const double c = r.u(0.25, 0.75), w = r.u(0.08, 0.25);
    return {"bump at x = " + fmt(c, 3) + " width " + fmt(w, 3), [c, w](double x) { return std::exp(-(x - c) * (x - c) / (w * w)); }};
  }
  if (k == "U") {
    const double c = r.u(0.3, 0.7);
    return {"(x - " + fmt(c, 3) + ")^2", [c](double x) { return (x - c) * (x - c); }};
  }
  const double f = r.u(0.8, 2.5), ph = r.u(0, kTwoPi);
  return {"sin(2 pi " + fmt(f, 3) + " x + " + fmt(ph, 3) + ")", [f, ph](double x) { return std::sin(kTwoPi * f * x + ph); }};
}

// Per-level pattern over n levels (sorted order for ordinal carriers).
std::vector<double> draw_pattern(Rng& r, int n, bool ordinal, std::string& name) {
  std::vector<std::string> kinds = {"random levels", "one level apart"};
  if (ordinal && n >= 3) kinds.insert(kinds.end(), {"mid-level peak", "monotone then flat", "U over levels"});
  name = r.pick(kinds);
  std::vector<double> v(n, 0.0);
  if (name == "random levels") {
    for (double& x : v) x = r.n();
  } else if (name == "one level apart") {
    v[r.i(n)] = 1;
  } else if (name == "mid-level peak") {
    const int m = 1 + r.i(n - 2);
    v[m] = 1;
    if (m - 1 >= 0) v[m - 1] = r.u(0, 0.4);
    if (m + 1 < n) v[m + 1] = r.u(0, 0.4);
  } else if (name == "monotone then flat") {
    const int m = 1 + r.i(n - 2);
    for (int j = 0; j < n; ++j) v[j] = std::min(j, m) / static_cast<double>(m);
  } else {
    const double c = r.u(0.5, n - 1.5);
    for (int j = 0; j < n; ++j) v[j] = (j - c) * (j - c);
  }
  std::string vals;
  for (double x : v) vals += (vals.empty() ? "" : ", ") + fmt(x, 3);
  name += " [" + vals + "]";
  return v;
}

bool friction(const std::string& ch) { return ch.rfind("mu_", 0) == 0; }

struct Drawn {
  std::vector<double> g;
  std::string shape;
};

// g of `c` on the rows `act`, centred over them; empty when it does not vary there.
Drawn carrier_g(Rng& r, const Set& s, const Carrier& c, const std::vector<char>& act,
                const std::vector<std::string>& shapes = {}) {
  const size_t N = s.rows.size();
  Drawn d;
  d.g.assign(N, 0.0);
  std::vector<double> v(N, 0.0);
  std::map<std::string, int> lev;  // level text -> index
  std::map<double, std::string> by_value;
  for (size_t i = 0; i < N; ++i) {
    if (!act[i]) continue;
    if (c.numeric) v[i] = c.log_x ? std::log(carrier_value(s, i, c.name)) : carrier_value(s, i, c.name);
    else lev.emplace(cell_text(s, i, c.name), 0);
  }
  const bool few = c.numeric && c.ordinal;
  if (few) {  // few-level numeric: levels in value order
    for (size_t i = 0; i < N; ++i)
      if (act[i]) by_value.emplace(v[i], cell_text(s, i, c.name));
    int k = 0;
    for (const auto& [val, txt] : by_value) lev[txt] = k++;
  } else if (!c.numeric) {
    int k = 0;
    for (auto& [txt, idx] : lev) idx = k++;  // text order: R1 < R2 ... for graded codes
  }
  if (!c.numeric || few) {
    if (lev.size() < 2) return {};
    const std::vector<double> pat = draw_pattern(r, static_cast<int>(lev.size()), c.ordinal, d.shape);
    for (size_t i = 0; i < N; ++i)
      if (act[i]) d.g[i] = pat[lev.at(cell_text(s, i, c.name))];
  } else {
    double lo = 1e300, hi = -1e300;
    for (size_t i = 0; i < N; ++i)
      if (act[i]) lo = std::min(lo, v[i]), hi = std::max(hi, v[i]);
    if (!(hi > lo)) return {};
    const Shape sh = draw_shape(r, shapes);
    d.shape = sh.name + (c.log_x ? ", x = log(value) scaled to [0, 1]" : ", x = value scaled to [0, 1]");
    for (size_t i = 0; i < N; ++i)
      if (act[i]) d.g[i] = sh.f((v[i] - lo) / (hi - lo));
  }
  double m = 0, n = 0;
  for (size_t i = 0; i < N; ++i)
    if (act[i]) m += d.g[i], n++;
  m /= n;
  double var = 0;
  for (size_t i = 0; i < N; ++i)
    if (act[i]) d.g[i] -= m, var += d.g[i] * d.g[i];
  if (!(var / n > 1e-10)) return {};
  return d;
}

std::string pick_channel(Rng& r, const std::vector<std::pair<const char*, double>>& w) {
  double u = r.u(), acc = 0;
  for (const auto& [name, p] : w)
    if (u < (acc += p)) return name;
  return w.back().first;
}

}  // namespace

Effect draw_effect(Rng& r, const Set& s, const std::string& cls, BlindTruth& t) {
  const size_t N = s.rows.size();
  const Carrier batch{"sheet_batch", false}, grade{"surface_grade", false, true}, pre{"pre_strain_pct", true, true},
      fixture{"fixture", false}, clean{"clean_method", false}, op{"operator", false};
  const Carrier slide{"sliding_distance_mm"}, travel{"pin_travel_m"}, lct{"load_cell_temp_C"},
      speed{"speed_mm_s", true, false, true}, thick{"blank_thickness_um"}, ra{"ra_strip_um"}, tempF{"pin_temp_F"},
      oil{"oil_age_days"}, run{"run_no"}, rp02{"batch_rp02_MPa"}, pressure{"pressure"};
  const std::vector<std::pair<const char*, double>> usual = {
      {"mu_mult", 0.45}, {"mu_add", 0.2}, {"offset", 0.15}, {"bend", 0.1}, {"bt_gain", 0.1}};
  for (int attempt = 0; attempt < 200; ++attempt) {
    Carrier c;
    std::string channel, cell, kind;
    std::vector<std::string> shapes;
    std::vector<char> in_cell(N, 1);
    if (cls == "level") {
      c = r.pick(std::vector<Carrier>{batch, grade, pre, fixture, clean, op});
      channel = pick_channel(r, usual);
    } else if (cls == "smooth") {
      std::vector<Carrier> cs = {slide, travel, lct};
      if (!s.levels) cs.push_back(speed);
      c = r.pick(cs);
      channel = pick_channel(r, usual);
    } else if (cls == "test-level") {
      c = r.pick(std::vector<Carrier>{thick, ra, tempF, oil, run, rp02});
      channel = pick_channel(r, {{"mu_mult", 0.5}, {"mu_add", 0.3}, {"offset", 0.2}});
    } else if (cls == "interaction") {
      c = r.pick(std::vector<Carrier>{slide, travel, lct, thick, ra, tempF, batch, grade, fixture, pre, clean});
      channel = pick_channel(r, {{"mu_mult", 0.5}, {"mu_add", 0.2}, {"offset", 0.15}, {"bend", 0.15}});
      std::vector<std::string> kinds = {"pin", "direction"};
      if (s.nlub >= 2) kinds.push_back("lubricant");
      kinds.push_back("speed");
      const std::string k = r.pick(kinds);
      const int pin = r.i(3), dir = r.i(static_cast<int>(s.dirs.size())), lub = r.i(s.nlub), lev = r.i(3);
      std::vector<double> sp;
      for (const auto& x : s.tests)
        if (!x.rotating) sp.push_back(x.speed);
      std::sort(sp.begin(), sp.end());
      const double vmed = sp[sp.size() / 2];
      const bool upper = r.u() < 0.5;
      for (size_t i = 0; i < N; ++i) {
        const Test& x = s.tests[s.rows[i].test];
        in_cell[i] = k == "pin" ? x.pin == pin
                     : k == "direction" ? x.dir == dir && !x.rotating
                     : k == "lubricant" ? x.lub == lub && !x.rotating
                     : s.levels ? x.speed_level == lev && !x.rotating
                                : !x.rotating && (upper ? x.speed >= vmed : x.speed < vmed);
      }
      cell = k == "pin" ? "pin_diameter_mm = " + fmt(s.pins[pin].d)
             : k == "direction" ? "direction_deg = " + fmt(s.dirs[dir])
             : k == "lubricant" ? std::string("lubricant = ") + kLubNames[lub]
             : s.levels ? "speed_mm_s = " + fmt(s.speed_levels[lev])
                        : std::string("speed_mm_s ") + (upper ? ">= " : "< ") + fmt(vmed);
    } else if (cls == "channel") {
      std::vector<std::string> kinds = {"bend-thickness", "bend-rp02", "bend-prestrain", "offset-temperature",
                                        "offset-fixture", "bt-gain", "pressure-law", "pslope", "vslope"};
      if (!s.levels) kinds.push_back("speed-law");
      kind = r.pick(kinds);
      if (kind == "bend-thickness") c = thick, channel = "bend", shapes = {"power", "linear"};
      if (kind == "bend-rp02") c = rp02, channel = "bend", shapes = {"linear"};
      if (kind == "bend-prestrain") c = pre, c.ordinal = false, channel = "bend", shapes = {"exp-saturation", "log"};
      if (kind == "offset-temperature") c = lct, channel = "offset", shapes = {"linear", "exp-saturation", "hinge"};
      if (kind == "offset-fixture") c = fixture, channel = "offset";
      if (kind == "bt-gain") c = r.pick(std::vector<Carrier>{fixture, lct, op}), channel = "bt_gain";
      if (kind == "pressure-law") c = pressure, channel = "mu_mult", shapes = {"power", "log", "exp-saturation", "linear"};
      if (kind == "speed-law") c = speed, channel = "mu_mult", shapes = {"U", "log", "exp-decay", "linear"};
      if (kind == "pslope" || kind == "vslope") {
        c = r.pick(std::vector<Carrier>{thick, ra, tempF, batch, grade, lct});
        channel = kind == "pslope" ? "mu_pslope" : "mu_vslope";
        shapes = {"linear", "log", "step", "exp-saturation"};
      }
    } else {
      throw std::invalid_argument("wild_synth: no effect for class '" + cls + "'");
    }
    if (c.name == "pre_strain_pct" && cls != "channel") c.ordinal = true;  // few numeric levels: a pattern
    std::vector<char> act(N);
    for (size_t i = 0; i < N; ++i)
      act[i] = in_cell[i] && (!friction(channel) || !s.tests[s.rows[i].test].rotating);
    Drawn d = carrier_g(r, s, c, act, shapes);
    if (d.g.empty()) continue;  // the carrier does not vary where it acts: draw again
    t.variable = c.name == "pressure" ? "avg_pressure_MPa" : c.name;
    t.aliases = aliases_of(s, c.name, c.numeric);
    t.shape = d.shape;
    t.channel = channel + (kind.empty() ? "" : " (" + kind + ")");
    t.cell = cell;
    t.law = c.name == "pressure" ? "; p = back tension / (pin radius x strip width), MPa" : "";
    return {channel, d.g};
  }
  throw std::logic_error("wild_synth: no varying carrier after 200 draws");
}

}  // namespace drawbend::loop::wild
