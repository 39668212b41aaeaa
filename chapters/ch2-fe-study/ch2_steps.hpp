#pragma once
// Chapter 2 steps shared between main.cpp and the finite-element part.
#include "sim/drawbend_case.hpp"
#include "study/chapter.hpp"

namespace ch2 {

struct FeOptions {
  bool reuse = false;                 ///< reuse runs whose deck is unchanged (development)
  drawbend::sim::DrawBendSpec base;   ///< mesh and numerics of the chapter's runs
  double low_mass_scaling = 2500;     ///< the comparison run's mass scaling
  double fine_element_length = 0.5;   ///< the convergence run's element length [mm]
};

/// Steps 4-8: our draw-bend runs of the 12.7 mm pin.
void fe_study(drawbend::study::Chapter& c, const FeOptions& o);

}  // namespace ch2
