#pragma once
// Steps of the Chapter 6 driver that run the solver (see main.cpp).
#include "study/chapter.hpp"

namespace ch6 {
/// Sec. 6.5: block sliding with the mu(p, v) law (Tables 6.2-6.4, Figs. 6.8-6.10),
/// built by src/sim/block_case.
void block_sliding(drawbend::study::Chapter& c, bool reuse);
}  // namespace ch6

#include <string>

#include "sim/cup_case.hpp"

namespace ch6 {
using drawbend::sim::CupResult;
using drawbend::sim::force_at;
/// Sec. 6.6: the cup-drawing cases (coarse cases 1 and 9 by default; all nine, finer, with `full`).
/// `cases`: comma-separated Table 6.5 case ids to run instead (must hold case 1 and the last case).
/// `material`: as for draw_cup (the page then names it).
void cup_drawing(drawbend::study::Chapter& c, bool full, const std::string& cases = "", const std::string& material = "",
                 bool reuse = false);
}  // namespace ch6
