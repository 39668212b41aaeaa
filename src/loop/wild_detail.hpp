#pragma once
// Internals of the wild generator (wild_synth.hpp), shared by its design part
// (wild_synth.cpp) and its effect part (wild_effects.cpp).  Not an API.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "loop/blind_synth.hpp"

namespace drawbend::loop::wild {

/// Own draws on mt19937_64 (the standard's distributions differ between
/// libraries; these do not).
struct Rng {
  std::mt19937_64 g;
  double u(double a = 0, double b = 1) { return a + (b - a) * static_cast<double>(g() >> 11) * 0x1.0p-53; }
  double n() {
    const double u1 = 1 - u(), u2 = u();
    return std::sqrt(-2 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }
  int i(int n) { return static_cast<int>(g() % static_cast<std::uint64_t>(n)); }
  template <class T>
  const T& pick(const std::vector<T>& v) { return v[i(static_cast<int>(v.size()))]; }
  template <class T>
  void shuffle(std::vector<T>& v) {
    for (size_t j = v.size(); j > 1; --j) std::swap(v[j - 1], v[i(static_cast<int>(j))]);
  }
};

struct Pin {
  double d, lo, hi, b1, b0;  ///< mm; back-tension range N; bending line F_B = b0 + b1 F
};

struct Test {
  int pin = 0, lub = 0, speed_level = -1, dir = 0, rows = 0, run = 0;
  bool rotating = false;
  double speed = 25.4, length = 200, thick_um = 1040, ra_um = 0.4, temp_F = 70, oil_age = 3;
  bool oil_missing = false;
  int batch = 0, grade = 0, prestrain = 0, fixture = 0, clean = 0, op = 0;
  std::string id, strip, date;
};

struct RowT {
  int test = 0;
  double F = 0, slide = 0, travel_m = 0, lc_temp = 20;
  int clock = 0;  ///< s since midnight
};

/// A drawn design and base truth.
struct Set {
  std::vector<double> dirs, speed_levels, prestrains, batch_rp02;
  bool levels = true;  ///< speeds are 3 levels
  int nlub = 1, nbatch = 2, nfix = 2, nop = 2;
  std::vector<double> lub_f, lev_f;
  double mu_rd = 0.1, mu_td = 0.09;
  Pin pins[3];
  std::vector<Test> tests;
  std::vector<RowT> rows;  ///< run order
  std::vector<std::string> extra_columns;
  bool has_strip = false, has_date = false, has_clock = false, has_remark = false;
  int clock0 = 0;
};

extern const char* const kLubNames[3];

Set draw_set(Rng& r);
/// Cells of every extra column and of the standard columns (test_id, pin,
/// pin_diameter_mm, direction_deg, speed_mm_s, lubricant, back_tension_N,
/// sliding_distance_mm, time_s) of row i, as written.
std::string cell_text(const Set& s, size_t i, const std::string& column);
/// A numeric carrier's true value on row i (oil_age_days also where missing).
double carrier_value(const Set& s, size_t i, const std::string& column);
/// Columns the design confounds exactly with `column` (wild_synth.hpp: Aliases).
std::vector<std::string> aliases_of(const Set& s, const std::string& column, bool numeric);
/// Mean contact pressure of row i, F / (R w) [MPa] (w = 25.4 mm).
double row_pressure(const Set& s, size_t i);

/// The planted effect: g per row (0 where it does not act) and its channel.
struct Effect {
  std::string channel;
  std::vector<double> g;
};
Effect draw_effect(Rng& r, const Set& s, const std::string& cls, BlindTruth& t);

}  // namespace drawbend::loop::wild
