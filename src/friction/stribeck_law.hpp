#pragma once
// The Stribeck friction law in the solver (thesis Sec. 3.3, Eqs. 3.1-3.2).
//
// mu = mu(L), L = v eta / (p R_a), from the node's contact pressure p and
// sliding speed v.  Updating mu from the instantaneous nodal speed every cycle
// makes an explicit model unstable: mu rises when a node slows, which slows it
// further (thesis Figs. 3.5-3.7).  The thesis's cure, reproduced here: keep mu
// fixed over an interval of `interval` cycles and update it from the sliding
// speed averaged over that interval (100 cycles in the thesis).  interval = 1
// is the per-cycle update.  Before the first interval completes, mu is
// evaluated from the current state.  Per-node state: current mu, speed sum,
// count.  Units: MPa, mm/s.
#include "analysis/stribeck.hpp"
#include "friction/friction_law.hpp"

namespace drawbend::friction {

class Stribeck final : public FrictionLaw {
 public:
  Stribeck(const analysis::StribeckParams& p, int interval);
  Limit limit(const ContactState& s) const override;
  int state_size() const override { return 3; }
  std::string describe() const override;
  const analysis::StribeckParams& params() const { return p_; }

 private:
  analysis::StribeckParams p_;
  int interval_;
};

}  // namespace drawbend::friction
