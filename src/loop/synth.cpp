// Synthetic data with a hidden law; see synth.hpp.
#include "loop/synth.hpp"

#include <cmath>
#include <algorithm>
#include <map>
#include <random>
#include <sstream>

#include "core/csv.hpp"

namespace drawbend::loop {

const std::vector<std::string>& synth_effects() {
  static const std::vector<std::string> e = {"none",      "depletion", "pin_surface", "speed",   "drift",
                                             "direction", "pressure",  "curvature",   "batch",   "temperature"};
  return e;
}

namespace {
struct PinSpec {
  double d, lo, hi, b1, b0, ra;
};
// Bending lines: Table 5.3; back-tension ranges: Table 5.3.
const PinSpec kPins[3] = {{12.7, 1450, 1800, -0.0625, 396.84, 0.10},
                          {25.4, 1650, 2050, -0.0123, 129.39, 0.12},
                          {42.0, 1500, 2100, -0.0118, 70.133, 0.30}};
const double kMuRD = 0.09, kMuTD = 0.075, kWrap = 1.5707963267948966;

// The truth's own anisotropy (Eq. 6.3 written out here on purpose: the
// generator shares no code path with the loop's model).
double truth_ellipse(double a, double b, double phi) {
  const double c = std::cos(phi), s = std::sin(phi);
  return a * b / std::sqrt(b * b * c * c + a * a * s * s);
}

// Each hidden law: its effect name, the law in words, the variable it acts
// through and the columns that carry it (the truth's aliases).
struct HiddenLaw {
  const char* effect;
  const char* law;
  const char* variable;
  std::vector<std::string> aliases;
};
const std::vector<HiddenLaw>& hidden_laws() {
  static const std::vector<HiddenLaw> laws = {
      {"none", "no hidden effect", "", {}},
      {"depletion", "mu (1 - A (1 - exp(-s/60 mm))), s = sliding distance", "sliding_distance_mm",
       {"sliding_distance_mm", "time_s"}},
      {"pin_surface", "mu (1 + A) on the 42 mm pin only", "pin", {"pin", "pin_diameter_mm", "inv_R_per_mm", "pin_Ra_um"}},
      {"speed", "mu (1 - A log10(v / 25.4 mm/s))", "speed_mm_s", {"speed_mm_s"}},
      {"drift", "mu (1 + A (order - mean) / N), order = test_order", "test_order", {"test_order"}},
      {"direction",
       "mu (1 + A exp(-((phi - 45 deg)/20 deg)^2)) on top of the RD/TD ellipse (a bump at 45 deg, not "
       "elliptical, not sin^2 2phi)",
       "direction_deg", {"direction_deg"}},
      {"curvature", "mu(p) = 0.8 mu + A p^2 at the map's weighted pressure p (scaled with the mean tension)",
       "avg_pressure_MPa", {"avg_pressure_MPa", "pin", "pin_diameter_mm", "inv_R_per_mm", "back_tension_N"}},
      {"batch", "mu (1 + A) on the tests of coil C (coils A, B, C drawn at random per test)", "coil", {"coil"}},
      {"temperature", "mu (1 + A (T - 21 C) / 1.5 C), T = temperature_C (19.5-22.5 C per test)", "temperature_C",
       {"temperature_C"}},
      {"pressure", "mu(p) = mu0 + A p over the pressure map (mu0 = 0.7 mu)", "avg_pressure_MPa",
       {"avg_pressure_MPa", "pin", "pin_diameter_mm", "inv_R_per_mm", "back_tension_N"}}};
  return laws;
}

// The truth of a set: the effect, its amplitude (the law's default when
// negative) and the law, variable and aliases of hidden_laws().
void describe_truth(const SynthOptions& o, const MapLibrary& maps, SynthTruth& t) {
  t = {};
  t.effect = o.effect;
  t.noise_N = o.noise_N;
  t.seed = o.seed;
  t.maps = maps.label();
  const std::map<std::string, double> defaults = {
      {"none", 0},         {"depletion", 0.25},  {"pin_surface", 0.2}, {"speed", 0.1},  {"drift", 0.15},
      {"direction", 0.2},  {"pressure", 0.002},  {"curvature", 1e-4},  {"batch", 0.2},  {"temperature", 0.1}};
  t.amplitude = o.amplitude >= 0 ? o.amplitude : defaults.at(o.effect);
  for (const HiddenLaw& h : hidden_laws())
    if (o.effect == h.effect) t.law = h.law, t.variable = h.variable, t.aliases = h.aliases;
}

struct TestSpec {
  int pin;
  bool rotating;
  double dir, speed;
};

// Per pin, T fixed-pin tests over five directions and log-spaced speeds
// (6.35 to 101.6 mm/s), then 3 rotating-pin tests.
std::vector<TestSpec> design_tests(int T) {
  std::vector<TestSpec> tests;
  for (int p = 0; p < 3; ++p) {
    for (int j = 0; j < T; ++j) {
      const double dir = 22.5 * (j % 5);
      const double frac = T > 1 ? static_cast<double>((j * 5 + p) % T) / (T - 1) : 0.5;
      tests.push_back({p, false, dir, 6.35 * std::pow(16.0, frac)});
    }
    for (int j = 0; j < 3; ++j) tests.push_back({p, true, 0.0, 25.4});
  }
  return tests;
}

// The friction force F (exp(mu pi/2) - 1) of a fixed-pin row under the hidden
// law of amplitude A: s the row, order the test's run order of N tests, temp
// and coil the test's; the pressure laws iterate on the map's pressure.
double hidden_friction(const SynthOptions& o, double A, const MapLibrary& maps, const TestSpec& ts, const Sample& s,
                       int order, double N, double temp, char coil) {
  const PinSpec& ps = kPins[ts.pin];
  const double F = s.back_tension_N, bend = ps.b0 + ps.b1 * F;
  const double phi = ts.dir * M_PI / 180;
  double mu = truth_ellipse(kMuRD, kMuTD, phi);
  if (o.effect == "depletion") mu *= 1 - A * (1 - std::exp(-s.sliding_mm / 60));
  if (o.effect == "pin_surface" && ts.pin == 2) mu *= 1 + A;
  if (o.effect == "speed") mu *= 1 - A * std::log10(s.speed_mm_s / 25.4);
  if (o.effect == "drift") mu *= 1 + A * (order - (N + 1) / 2) / N;
  if (o.effect == "direction") mu *= 1 + A * std::exp(-std::pow((ts.dir - 45) / 20, 2));
  if (o.effect == "batch" && coil == 'C') mu *= 1 + A;
  if (o.effect == "temperature") mu *= 1 + A * (temp - 21) / 1.5;
  double ff = F * (std::exp(mu * kWrap) - 1);
  if (o.effect == "pressure" || o.effect == "curvature") {
    // The truth's pressure: the map's weighted pressure scaled with the
    // mean strip tension (F_x + F_y)/2 (Eq. 2.2), friction included.
    const PinMap& m = maps.at(ps.d);
    const double mean_ref = 2 * m.fref_N + ps.b0 + ps.b1 * m.fref_N;
    for (int it = 0; it < 8; ++it) {
      const double pw = m.S2 / m.S1 * (2 * F + bend + ff) / mean_ref;
      const double mu_p = o.effect == "pressure" ? 0.7 * mu + A * pw : 0.8 * mu + A * pw * pw;
      ff = F * (std::exp(mu_p * kWrap) - 1);
    }
  }
  return ff;
}

}  // namespace

Dataset synthesize(const SynthOptions& o, const MapLibrary& maps, SynthTruth& t) {
  const auto& names = synth_effects();
  if (std::find(names.begin(), names.end(), o.effect) == names.end())
    throw std::invalid_argument("unknown hidden effect '" + o.effect + "'");
  std::mt19937_64 rng(o.seed);
  std::normal_distribution<double> noise(0.0, o.noise_N);
  std::uniform_real_distribution<double> unif(0.0, 1.0);
  describe_truth(o, maps, t);
  const double A = t.amplitude;

  Dataset d;
  d.path = "synthetic";
  d.has_sliding = d.has_time = true;
  d.extra_columns = {"test_order", "pin_Ra_um", "temperature_C", "coil", "humidity_pct"};
  d.comments = {" synthetic draw-bend data (drawbend synth), seed " + std::to_string(o.seed) + ", noise sd " +
                    fmt(o.noise_N) + " N; the hidden law is in truth.json, not here",
                " pressure maps: " + maps.label(),
                " units: mm, N, mm/s, s, deg, um, C"};
  const int n = o.rows_per_test;
  const std::vector<TestSpec> tests = design_tests(o.tests_per_pin);
  std::vector<int> order(tests.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i) + 1;
  for (size_t j = order.size(); j > 1; --j) std::swap(order[j - 1], order[rng() % j]);
  const double N = static_cast<double>(tests.size());
  for (size_t ti = 0; ti < tests.size(); ++ti) {
    const TestSpec& ts = tests[ti];
    const PinSpec& ps = kPins[ts.pin];
    const std::string id = std::string(ts.rotating ? "rot" : "fix") + "-d" + fmt(ps.d) + "-" + std::to_string(ti);
    const double temp = 19.5 + 3 * unif(rng);
    const char coil = "ABC"[rng() % 3];
    std::vector<int> slot(n);
    for (int k = 0; k < n; ++k) slot[k] = k;
    for (int j = n; j > 1; --j) std::swap(slot[j - 1], slot[rng() % j]);
    for (int k = 0; k < n; ++k) {
      Sample s;
      s.test_id = id;
      s.pin_d_mm = ps.d;
      s.rotating = ts.rotating;
      s.direction_deg = ts.dir;
      s.speed_mm_s = std::round(ts.speed * 100) / 100;
      s.lubricant = "MP404";
      s.back_tension_N = ps.lo + (ps.hi - ps.lo) * slot[k] / std::max(1, n - 1);
      s.sliding_mm = 20 + 180.0 * k / std::max(1, n - 1);
      s.time_s = s.sliding_mm / s.speed_mm_s;
      const double F = s.back_tension_N, bend = ps.b0 + ps.b1 * F;
      double y = F + bend;
      if (!ts.rotating) y += hidden_friction(o, A, maps, ts, s, order[ti], N, temp, coil);
      s.outlet_force_N = y + noise(rng);
      s.extra = {std::to_string(order[ti]), fmt(ps.ra), fmt(temp, 4), std::string(1, coil),
                 fmt(40 + 20 * unif(rng), 4)};
      d.rows.push_back(s);
    }
  }
  return d;
}

std::string truth_json(const SynthTruth& t) {
  std::ostringstream o;
  o << "{\n  \"effect\": \"" << t.effect << "\",\n  \"variable\": \"" << t.variable << "\",\n  \"aliases\": [";
  for (size_t i = 0; i < t.aliases.size(); ++i) o << (i ? ", " : "") << "\"" << t.aliases[i] << "\"";
  o << "],\n  \"law\": \"" << t.law << "\",\n  \"amplitude\": " << fmt(t.amplitude) << ",\n  \"noise_N\": "
    << fmt(t.noise_N) << ",\n  \"seed\": " << t.seed << ",\n  \"maps\": \"" << t.maps << "\"\n}\n";
  return o.str();
}

}  // namespace drawbend::loop
