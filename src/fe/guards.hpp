#pragma once
// Numerical guards of the explicit solver: faults that make a result
// meaningless are detected while the case runs and stop it with a message that
// names the element or node and the time, instead of letting it finish with
// garbage.  Each guard has a limit and an action: "error" stops the run
// (fe::NumericalFault, exit code 3 from `drawbend run`), "warn" prints a
// warning (once per step and guard) and carries on.
//
// | guard            | fires when                                                    | checked        |
// |------------------|---------------------------------------------------------------|----------------|
// | non-finite       | a velocity (so a force or stress) is NaN or Inf              | every cycle, fused into the velocity update |
// | inverted         | an element's volume or Jacobian is not positive               | every cycle, in the element loop |
// | dt_collapse      | time step < dt_collapse x the initial step                    | every cycle    |
// | tool travel      | a tool moves more than the smallest element in one cycle     | every cycle    |
// | penetration      | contact depth > penetration x element size normal to the face | every cycle, in the contact loop |
// | hourglass_ratio  | hourglass energy > hourglass_ratio x internal energy          | end of each step |
// | kinetic_ratio    | kinetic energy > kinetic_ratio x internal energy, in a step marked quasi_static | end of each step |
// | energy_balance   | energy balance error (Energies::balance_error) > energy_balance | end of each step |
//
// Non-finite values, inverted elements and a tool's travel are always errors:
// nothing after them can be trusted.  The defaults let every shipped deck, chapter and
// verification problem pass with a margin.
#include <stdexcept>
#include <string>

namespace drawbend::fe {

/// A numerical failure of a running analysis (the input was valid).
struct NumericalFault : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Guard {
  double limit = 0;
  bool error = true;  ///< false: warn and carry on
};

struct Guards {
  Guard dt_collapse{1e-3, true};      ///< fraction of the initial time step
  Guard penetration{0.5, true};       ///< fraction of the element size normal to the contact face
  Guard hourglass_ratio{0.5, true};   ///< hourglass / internal energy
  Guard kinetic_ratio{0.05, true};    ///< kinetic / internal energy (quasi-static steps only)
  Guard energy_balance{0.1, true};    ///< relative energy balance error
};

}  // namespace drawbend::fe
