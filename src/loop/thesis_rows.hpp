#pragma once
// The thesis's measured data in the drawbend sample format: every printed
// linear fit (Table 5.3 rotating pins; Tables 5.5-5.10 fixed pins, diluted
// lubricant) sampled at evenly spaced back tensions over its stated range, and
// the Table 5.17 friction forces (undiluted lubricant), which the thesis gives
// at an unstated back tension, placed at the Table 5.13 back tension of the
// pin (an assumption, stated in every such row's source cell).
// Outlet force = F_back + (fit value): Table 5.3 gives F_bend, Tables 5.5-5.10
// F_fric+bend (Sec. 5.5); Table 5.17 rows use F_back + F_bend(Table 5.3) + F_fric.
#include <string>

#include "loop/measured.hpp"

namespace drawbend::loop {

/// thesis_dir: data/thesis.  points: rows per fit (>= 2).
Dataset thesis_dataset(const std::string& thesis_dir, int points = 7);

}  // namespace drawbend::loop
