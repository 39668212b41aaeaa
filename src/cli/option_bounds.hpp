#pragma once
// The bounds every command's numeric options are range-checked against as
// they are parsed (Options::range, issue 53), with their reasons: a command
// refuses an absurd number before any work, naming the option, instead of
// writing a deck that `drawbend run` refuses or running for hours.  They
// bound laboratory strip, block and cup tests generously; the deck reader's
// own checks and [limits] (cost) still apply to what is written.
#include <stdexcept>
#include <string>

#include "core/csv.hpp"

namespace drawbend::cli::bounds {

inline constexpr double kLengthMM = 1000;    ///< tool and strip dimensions [mm] (the largest test rig: 300 mm)
inline constexpr double kThicknessMM = 20;   ///< sheet thickness [mm] (sheet metal ends near 6 mm)
inline constexpr double kSpeedMMs = 1e4;     ///< sliding or punch speed [mm/s] (10 m/s, above any press)
inline constexpr double kPressureMPa = 1e4;  ///< contact pressure [MPa] (ten times the hardest tool steel's yield)
inline constexpr double kTimeS = 1e3;        ///< step duration [s] (explicit runs of quasi-static tests: ms to s)
inline constexpr double kForceN = 1e6;       ///< a strip force [N] (core/strip_limits.hpp's kMaxStripForceN)
inline constexpr double kElements = 1000;    ///< elements along one edge or direction
inline constexpr double kMassScaling = 1e9;  ///< [limits] max_mass_factor's default
inline constexpr double kPenalty = 1e6;      ///< contact penalty scale (dimensionless, 0.1 by default)
inline constexpr double kIntervalCycles = 1e6;  ///< a friction law's update interval [cycles]

// The smallest values (issue 53: a pin of 1e-300 mm or a die radius of
// 1e-300 mm was written into a deck with exit 0, and a sheet of 1e-300 mm
// was refused only by a line of the generated deck).  Below them a value is a
// unit error (m for mm, Pa for MPa), not a laboratory test.
inline constexpr double kMinLengthMM = 0.01;     ///< [mm] 10 um: thinner than any foil, finer than any FE mesh of a sheet
inline constexpr double kMinThicknessMM = 0.01;  ///< [mm] the same (aluminium foil is 0.006 to 0.2 mm)
inline constexpr double kMinSpeedMMs = 1e-3;     ///< [mm/s] 1 um/s (the thesis's slowest test: 2.5 mm/s)
inline constexpr double kMinPressureMPa = 1e-3;  ///< [MPa] 1 kPa (less than a die's own weight on the strip)

}  // namespace drawbend::cli::bounds

namespace drawbend::cli {

/// A ramp option against its step's duration, checked after parsing (each is
/// range-checked alone as it is parsed): std::invalid_argument "--ramp:
/// expected a ramp shorter than --step (T s), found R s" (`strict`: shorter;
/// else not longer), so the message names the options, not the builder's spec.
inline void ramp_within(const std::string& ramp, double r, const std::string& step, double t, bool strict) {
  if (strict ? r < t : r <= t) return;
  throw std::invalid_argument("--" + ramp + ": expected a ramp " + (strict ? "shorter than" : "no longer than") +
                              " --" + step + " (" + fmt(t) + " s), found " + fmt(r) + " s");
}

}  // namespace drawbend::cli
