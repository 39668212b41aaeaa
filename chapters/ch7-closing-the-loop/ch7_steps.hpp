#pragma once
// Steps of the Chapter 7 driver (see main.cpp for the recipe).
#include <string>

#include "loop/loop.hpp"
#include "loop/maps.hpp"
#include "loop/measured.hpp"
#include "study/chapter.hpp"

namespace ch7 {

using drawbend::study::Chapter;

/// Held-out seeds of demonstration 5, fixed before any run: runs 11 and 12 of
/// heldout_protocol_v6.md (generators, classes, noise and scoring of
/// heldout_protocol_v2.md and heldout_protocol_v2_wild.md; the null rule of
/// v4).  Runs 3-10 used 53100000, 54200000, 57100000, 57200000, 58100000,
/// 58200000, 59100000 and 59200000, development data since.
constexpr int kHeldout2BlindSeed0 = 60300000, kHeldout2WildSeed0 = 60400000;

struct Config {
  std::string maps_dir;   ///< FE maps (empty: analytic stand-in, not FE)
  int null_seeds = 10;    ///< null data sets per noise level
  int effect_seeds = 5;   ///< data sets per hidden effect and noise level
  int permutations = 20000;  ///< cap of the sequential permutation test
  int heldout_sets = 24;     ///< held-out blind sets (heldout_protocol.md: 24 quick, 144 full)
  int heldout_seed0 = 50500000;       ///< heldout_protocol.md; dev seeds 1..999 only to debug the generator
  int heldout2_sets = 24;             ///< per generator (heldout_protocol_v2.md: 24 quick, 144 full)
  int heldout2_blind_seed0 = kHeldout2BlindSeed0;  ///< development: 52000000+
  int heldout2_wild_seed0 = kHeldout2WildSeed0;    ///< development: 55000000+
};

struct Thesis {
  drawbend::loop::Dataset data;
  drawbend::loop::MapLibrary maps;
};

Thesis load_thesis_data(Chapter& c, const Config& cfg);         // 1
void map_table(Chapter& c, const drawbend::loop::MapLibrary& m);  // 2
void thesis_loop_pressure(Chapter& c, const Thesis& t);          // 3 (demonstration 1)
void automatic_loop(Chapter& c, const Thesis& t, const Config& cfg);  // 4
void pin_42_anomaly(Chapter& c, const Thesis& t);                // 5 (demonstration 2)
void bending_vs_swift(Chapter& c, const Thesis& t, const Config& cfg);  // 6 (demonstration 2)
void rd_td_crossover(Chapter& c, const Thesis& t);               // 7 (demonstration 2)
void synthetic_detection(Chapter& c, const Config& cfg);         // 8 (demonstration 3)
void heldout_study(Chapter& c, const Config& cfg);               // 9 (demonstration 4, held out)
void heldout2_study(Chapter& c, const Config& cfg);              // 10 (demonstration 5, held out, generators 1 and 2)

}  // namespace ch7
