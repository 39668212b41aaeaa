#pragma once
// The quasi-static health of an explicit run, checked the same way in every
// chapter that runs the draw-bend model (Chapters 2-5).  The limits are the
// usual ones for explicit quasi-static forming:
//   - energy balance error < 1 % of the largest energy (fe/guards.hpp);
//   - kinetic over internal energy < 5 % at the end: inertia does not carry
//     the forces read from the run;
//   - hourglass over internal energy < 5 %: the reduced-integration elements'
//     zero-energy modes do not carry the deformation.
// Each is a Kind::health claim that can fail; none is widened per chapter.
#include <string>

#include "study/checks.hpp"

namespace drawbend::study {

/// The three ratios of a run's summary.csv (energy_balance_error,
/// kinetic_over_internal, hourglass_over_internal), as fractions.
struct RunHealth {
  double balance_error = 0;
  double kinetic_ratio = 0;
  double hourglass_ratio = 0;
};

inline constexpr double kBalanceLimit = 0.01;    ///< energy balance error, fraction
inline constexpr double kKineticLimit = 0.05;    ///< kinetic / internal energy at the end
inline constexpr double kHourglassLimit = 0.05;  ///< hourglass / internal energy

/// Claims `<id>.energy`, `<id>.quasistatic` and (with `hourglass`) `<id>.hourglass`
/// for the run called `name`.
void check_run_health(Checks& checks, const std::string& id, const std::string& name, const RunHealth& h,
                      bool hourglass = true);

}  // namespace drawbend::study
