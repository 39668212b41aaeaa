#pragma once
// Small helpers of the case builders (sim/*_case.cpp), which return typed decks (io/case_spec.hpp).
#include <cmath>
#include <string>

#include "core/csv.hpp"
#include "core/toml_read.hpp"
#include "io/case_spec.hpp"

namespace drawbend::sim {

/// A TOML float that reads back to the same double (shortest round trip),
/// always with a '.' or an exponent so TOML reads a float.
inline std::string toml_float(double v) {
  std::string t = fmt_shortest(v);
  if (t.find_first_of(".eE") == std::string::npos && t.find_first_of("in") == std::string::npos) t += ".0";
  return t;
}

/// `t` made an inline table (a row of a list such as a step's fixed or force, or a history).
inline toml::table inline_table(toml::table t) {
  t.is_inline(true);
  return t;
}

/// The history that ramps linearly from 0 at t = 0 to `v` at `t` [s], then holds:
/// { t = [0.0, t], v = [0.0, v] } (inline).
inline toml::table ramp_history(double t, double v) {
  return inline_table(toml::table{{"t", toml::array{0.0, t}}, {"v", toml::array{0.0, v}}});
}

/// Throws InputError "<what> must be > 0" unless v is a finite number > 0.
inline void require_positive(double v, const std::string& what) {
  if (!(v > 0) || !std::isfinite(v)) throw InputError(what + " must be a number > 0, found " + fmt(v));
}

}  // namespace drawbend::sim
