#pragma once
// Steps of the Chapter 5 driver (see main.cpp for the recipe).
#include <string>
#include <vector>

#include "study/chapter.hpp"
#include "study/thesis_data.hpp"

namespace ch5 {

using drawbend::study::CaseValue;
using drawbend::study::Chapter;
using drawbend::study::FitEntry;
using drawbend::study::Printed;

inline const double kSpeeds[3] = {6.35, 25.4, 101.6};  // mm/s, Table 5.4
inline const double kPins[3] = {12.7, 25.4, 42.0};     // mm
inline const char* kDirs[2] = {"RD", "TD"};

/// Tolerance reason of table re-derivations: the thesis evidently computed its
/// derived tables from its own printed inputs (e.g. 188.78 - 70.133 = 118.647,
/// printed 118.65), so only the rounding of the printed result is allowed.
inline const char* kFromPrinted = "thesis computed from its printed inputs: half a unit in the last printed place";

struct Line516 {
  std::string direction;
  double speed_mm_s;
  Printed a0, a1;
};

struct Inputs {
  std::vector<FitEntry> bending;    ///< Table 5.3 (rotating pins, RD)
  std::vector<FitEntry> fric_bend;  ///< Tables 5.5-5.10
  std::vector<FitEntry> pure;       ///< Tables 5.11 + 5.12 as printed
  std::vector<std::pair<double, Printed>> fback;  ///< Table 5.13: pin -> F_back [N]
  std::vector<CaseValue> ffric_diluted, c_diluted;    ///< Tables 5.14, 5.15
  std::vector<CaseValue> ffric_undiluted, c_undiluted;  ///< Tables 5.17, 5.18
  std::vector<Line516> lines;  ///< Table 5.16
  Printed fback_conventional;  ///< 1700 N (Sec. 5.6)
  double theta = 0;            ///< wrap angle, rad

  double back_tension(double pin) const;
};

Inputs load_inputs(Chapter& c);
void rederive_pure_friction(Chapter& c, const Inputs& in);
void rederive_table_5_14(Chapter& c, const Inputs& in);
void conventional_mu(Chapter& c, const Inputs& in);
void pressure_ratio_definitions(Chapter& c, const Inputs& in);
void undiluted(Chapter& c, const Inputs& in);
void friction_lines_and_surfaces(Chapter& c, const Inputs& in);

/// "RD.v6.35.d12.7" — the key part of check ids.
std::string key(const std::string& dir, double v, double pin);

}  // namespace ch5
