#pragma once
// Small helpers of the case builders that write TOML decks (sim/*_case.cpp).
#include <cmath>
#include <string>

#include "core/csv.hpp"

namespace drawbend::sim {

/// A TOML float that reads back to the same double (shortest round trip),
/// always with a '.' or an exponent so TOML reads a float.
inline std::string toml_float(double v) {
  std::string t = fmt_shortest(v);
  if (t.find_first_of(".eE") == std::string::npos && t.find_first_of("in") == std::string::npos) t += ".0";
  return t;
}

/// A TOML history that ramps linearly from 0 at t = 0 to `v` at `t` [s], then holds.
inline std::string toml_ramp(double t, double v) {
  return "{ t = [0.0, " + toml_float(t) + "], v = [0.0, " + toml_float(v) + "] }";
}

/// The [numerics] line of a spec's `threads` field: "threads = N  # ..." for N > 0
/// (the OpenMP threads `drawbend run` uses for the deck; the deck writers'
/// --threads sets the field), nothing for 0 (the default: none written).
inline std::string numerics_threads_line(int threads) {
  if (threads <= 0) return {};
  return "threads = " + std::to_string(threads) + "  # OpenMP threads of `drawbend run` (--threads)\n";
}

/// Throws InputError "<what> must be > 0" unless v is a finite number > 0.
inline void require_positive(double v, const std::string& what) {
  if (!(v > 0) || !std::isfinite(v)) throw InputError(what + " must be a number > 0, found " + fmt(v));
}

}  // namespace drawbend::sim
