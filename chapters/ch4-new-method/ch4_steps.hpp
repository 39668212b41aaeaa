#pragma once
// Chapter 4 steps shared between main.cpp and the finite-element part.
#include "sim/drawbend_case.hpp"
#include "study/chapter.hpp"

namespace ch4 {

struct FeOptions {
  bool run = true;              ///< run the finite-element part
  bool reuse = false;           ///< reuse runs whose deck is unchanged (development)
  drawbend::sim::DrawBendSpec base;  ///< mesh and numerics; pin, tension, speed set per run
};

/// Steps 6-10 of the chapter: our draw-bend runs and the new method on them.
void fe_study(drawbend::study::Chapter& c, const FeOptions& o);

}  // namespace ch4
