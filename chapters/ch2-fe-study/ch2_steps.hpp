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

/// Figs. 2.8, 2.15 and 2.16 and the inlet/outlet strain claim, from the last
/// snapshots of the mu = 0.1 runs on the chapter mesh (`fr`) and the finer one (`gr`).
void field_figures(drawbend::study::Chapter& c, const drawbend::sim::DrawBendResult& fr,
                   const drawbend::sim::DrawBendResult& gr);

}  // namespace ch2
