#pragma once
// Steps of the Chapter 5 driver (see main.cpp for the recipe).
#include <map>
#include <string>
#include <vector>

#include "analysis/new_method.hpp"
#include "sim/drawbend_case.hpp"

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

// ---- Steps 8-11: our own pressure maps (ch5_fe_*.cpp) ----

struct FeOptions {
  bool run = true;                    ///< run the finite-element part
  bool reuse = false;                 ///< reuse runs whose deck is unchanged (development)
  drawbend::sim::DrawBendSpec base;   ///< mesh and numerics of the baseline maps
  double fine_element_length = 0;     ///< "fine_along" variant: element length [mm]; 0 = half the base
  int fine_across = 0;                ///< "fine_across" variant: elements across; 0 = twice the base
  double stiff_penalty = 0.3;         ///< "penalty" variant: contact penalty scale
  bool map_variants = false;          ///< run the map variants penalty, td_curve, fine_along (the `full` tier does)
  bool across_variant = false;        ///< run the fine_across variant too (the `full` tier does)
};

/// The map variants of the sensitivity study; "base" is the chapter's map.
inline const char* kVariants[5] = {"base", "penalty", "td_curve", "fine_along", "fine_across"};

struct FeMaps {
  /// variant -> pin [mm] -> run (base has all three pins, variants the 12.7
  /// and 25.4 mm pins, only with FeOptions::map_variants; "fine_across" only
  /// with FeOptions::across_variant as well).
  std::map<std::string, std::map<double, drawbend::sim::DrawBendResult>> runs;
  double wall_s = 0;  ///< wall time of all runs [s]

  const drawbend::sim::DrawBendResult& run(const std::string& variant, double pin) const;
  bool has(const std::string& variant, double pin) const;
  /// The frictionless map with areas doubled: full strip, as the measured forces.
  drawbend::analysis::PressureMap full_strip_map(const std::string& variant, double pin) const;
  /// Our simulated rotating-pin bending force F_Y' - F_X' on the full strip [N].
  double full_strip_bending(const std::string& variant, double pin) const;
};

/// c definitions of the sensitivity study (full-strip forces, N):
///   printed  Tables 5.15/5.18 as printed (the chapter's default, as the thesis used);
///   eq22     Eq. (2.2) with the measured forces (Table 5.3 bending): (2F_b+F_bend+F_fric)/(2F_b+F_bend);
///   eq22sim  Eq. (2.2) with our simulated rotating-pin force in the denominator.
enum class CDef { printed, eq22, eq22sim };
double c_of(CDef d, const Inputs& in, const FeMaps& m, const std::string& variant, const std::string& dir, double v,
            double pin, bool undiluted);
/// Friction force of Table 5.14 (diluted) or 5.17 (undiluted) [N, full strip].
double ffric_of(const Inputs& in, const std::string& dir, double v, double pin, bool undiluted);

/// mu(p) by the new method from the given pins, one direction and speed.
drawbend::analysis::NewMethodResult identify(const Inputs& in, const FeMaps& m, const std::string& variant, CDef cdef,
                                             const std::string& dir, double v, const std::vector<double>& pins,
                                             int order, bool undiluted);

FeMaps run_fe_maps(Chapter& c, const Inputs& in, const FeOptions& o);  // 8
void diluted_new_method(Chapter& c, const Inputs& in, const FeMaps& m);  // 9
void undiluted_new_method(Chapter& c, const Inputs& in, const FeMaps& m);  // 10
void map_sensitivity(Chapter& c, const Inputs& in, const FeMaps& m);  // 11

}  // namespace ch5
