#pragma once
// Plausibility limits of measured draw-bend data, shared by every reader of
// it (`drawbend loop`'s loop/measured.cpp and `model-loop`'s
// modelloop/fb_points.cpp), so that a value one refuses the other refuses too.
#include <string>

#include "core/csv.hpp"

namespace drawbend {

/// The largest force a strip draw-bend test can carry [N]: a 25.4 mm x
/// 1.04 mm AA5754-O strip breaks near 6.5 kN (UTS ~ 245 MPa), and even a
/// 50 mm x 5 mm steel strip at 1500 MPa only reaches 4e5 N.  Beyond 1e6 N a
/// value is a unit or typing error: one such row would dominate every
/// least-squares fit, and as a finite-element load it would tear the model
/// apart in its first cycles.
inline constexpr double kMaxStripForceN = 1e6;

/// The largest pin diameter of a draw-bend test [mm]: the thesis's pins are
/// 3.2 to 25.4 mm and the largest test rig takes 300 mm tooling; beyond 1000
/// mm (cli/option_bounds.hpp's kLengthMM) a value is a unit or typing error,
/// and as a model-loop FE run it would mesh a wrap of kilometres (a pin of
/// 1e300 mm ran past every time limit before issue 53).
inline constexpr double kMaxPinDiameterMM = 1000;

/// The largest sliding speed of a draw-bend test [mm/s]: 10 m/s, above any
/// press and any strip-draw rig (the thesis's tests run 2.5 to 101.6 mm/s;
/// cli/option_bounds.hpp's kSpeedMMs).  Beyond it a value is a unit or typing
/// error (a speed of 1e300 mm/s was read as a valid speed level before).
inline constexpr double kMaxSlidingSpeedMMs = 1e4;

/// The largest friction coefficient a deck, a Stribeck table, a nodal
/// surface or an exported friction model may hold: lubricated sheet metal runs 0.02 to 0.3, dry metal on
/// metal reaches about 1 and clean metals in vacuum a few; sticking is reached
/// well below 10.  Above it a value is a typing error (a Coulomb mu of 1e300
/// ran with exit 0 before), refused naming the file, line and key.
inline constexpr double kMaxFrictionCoefficient = 10;

/// Below this, a data set whose every force is smaller is in the wrong unit
/// [N]: a strip draw-bend test pulls a sheet near its yield stress (a
/// 25.4 mm x 1.04 mm AA5754-O strip yields near 2.6 kN; even a 10 mm x
/// 0.1 mm foil at 100 MPa carries 100 N), so a file whose largest force is
/// below 10 N holds kN (1.7 "N" for 1.7 kN), not a strip test.  Only a whole
/// data set is judged (one small row may be a typo the other checks catch).
inline constexpr double kMinLargestStripForceN = 10;

/// Below this, a data set whose every pin is smaller is in metres [mm]: the
/// thesis's measured data have 12.7 to 42 mm pins and a pin below 1 mm would bend a 1 mm
/// sheet round a radius of half its thickness (it cracks); 0.0127 is
/// 12.7 mm written in metres.
inline constexpr double kMinLargestPinDiameterMM = 1;

/// The message for a data set whose largest force is below
/// kMinLargestStripForceN (forces in kN), else "".  `columns` names the force
/// columns as the message shows them; `rows` is appended after the largest
/// value (e.g. " (40 usable rows)").
inline std::string force_unit_problem(const std::string& path, const std::string& columns, double largest_N,
                                      const std::string& rows = "") {
  if (largest_N >= kMinLargestStripForceN) return "";
  return path + ": " + columns + ": every force is below " + fmt(kMinLargestStripForceN) + " N (largest " +
         fmt(largest_N) + " N)" + rows +
         "; a strip draw-bend test carries hundreds to thousands of N: expected full-strip forces in N (kN times "
         "1000?)";
}

/// The message for a data set whose largest pin diameter is below
/// kMinLargestPinDiameterMM (pins in metres), else "".
inline std::string pin_unit_problem(const std::string& path, double largest_mm, const std::string& rows = "") {
  if (largest_mm >= kMinLargestPinDiameterMM) return "";
  return path + ": column 'pin_diameter_mm': every pin diameter is below " + fmt(kMinLargestPinDiameterMM) +
         " mm (largest " + fmt(largest_mm) + " mm)" + rows +
         "; expected diameters in mm (a draw-bend pin is a few mm to a few hundred mm; metres times 1000?)";
}

}  // namespace drawbend
