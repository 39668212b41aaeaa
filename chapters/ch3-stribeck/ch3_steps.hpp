#pragma once
// Steps of the Chapter 3 driver that run the solver (see main.cpp).
#include "analysis/stribeck.hpp"
#include "core/csv.hpp"
#include "sim/drawbend_case.hpp"
#include "study/chapter.hpp"

namespace ch3 {
/// Sec. 3.3: strip-draw verification (Table 3.2, Fig. 3.8), the die pressure (Fig. 3.4), the
/// update interval (Figs. 3.5-3.7) and the same draw with Coulomb friction of mu_coulomb (Fig. 3.6).
void strip_draw(drawbend::study::Chapter& c, const drawbend::analysis::StribeckParams& s31,
                const drawbend::CsvTable& t32, double mu_coulomb, bool reuse);
/// Sec. 3.5: draw-bend on three pins at 10 MPa, Coulomb / Stribeck / frictionless (Figs. 3.10-3.18).
void drawbend_pins(drawbend::study::Chapter& c, const drawbend::analysis::StribeckParams& s33,
                   const drawbend::sim::DrawBendSpec& base, bool reuse);
}  // namespace ch3
