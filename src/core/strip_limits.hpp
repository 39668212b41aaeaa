#pragma once
// Plausibility limits of measured draw-bend data, shared by every reader of
// it (`drawbend loop`'s loop/measured.cpp and `model-loop`'s
// modelloop/fb_points.cpp), so that a value one refuses the other refuses too.

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

}  // namespace drawbend
