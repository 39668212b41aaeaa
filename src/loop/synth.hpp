#pragma once
// Synthetic draw-bend data with an undeclared effect, for testing the loop.
//
// Design (the same for every hidden law, so the design gives nothing away):
// pins 12.7, 25.4 and 42 mm; per pin `tests_per_pin` fixed-pin tests and 3
// rotating-pin tests, `rows_per_test` rows each.  Every fixed test has its own
// direction (0, 22.5, 45, 67.5, 90 deg in turn) and its own speed (log-spaced
// 6.35-101.6 mm/s, decorrelated from direction); the back tension steps over
// the pin's range in a shuffled order along the sliding distance (20-200 mm),
// so back tension and sliding distance are not confounded.  Extra columns:
// test_order (random run order), pin_Ra_um (per pin: 0.10, 0.12, 0.30 um),
// temperature_C (per test, 19.5-22.5 C), coil (A/B/C per test), humidity_pct
// (per row, 40-60 %): decoys unless the hidden law uses them.
//
// Truth: bending F_B = Table 5.3 line per pin; friction by the rope formula
// (Eq. 5.1) with mu = ellipse(0.09 RD, 0.075 TD) times the hidden law, or for
// the "pressure" law mu(p) = mu0 + a1 p over the pressure maps (same map
// source as the loop); Gaussian noise of sd noise_N on every outlet force.
#include <cstdint>
#include <string>
#include <vector>

#include "loop/maps.hpp"
#include "loop/measured.hpp"

namespace drawbend::loop {

struct SynthOptions {
  std::string effect = "none";
  double noise_N = 5;
  std::uint64_t seed = 1;
  int tests_per_pin = 12;
  int rows_per_test = 8;
  double amplitude = -1;  ///< < 0: the law's default
};

struct SynthTruth {
  std::string effect, variable, law, maps;
  std::vector<std::string> aliases;  ///< candidate names that identify the variable
  double amplitude = 0, noise_N = 0;
  std::uint64_t seed = 0;
};

/// none, depletion, pin_surface, speed, drift, direction, pressure, curvature, batch, temperature.
/// The generator writes its laws out itself and calls nothing of the loop's
/// model (no shared code path through which the loop could recognise it).
const std::vector<std::string>& synth_effects();

Dataset synthesize(const SynthOptions& o, const MapLibrary& maps, SynthTruth& truth);
std::string truth_json(const SynthTruth& t);

}  // namespace drawbend::loop
