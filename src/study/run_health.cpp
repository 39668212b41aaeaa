#include "study/run_health.hpp"

#include "core/csv.hpp"

namespace drawbend::study {

void check_run_health(Checks& checks, const std::string& id, const std::string& name, const RunHealth& h,
                      bool hourglass) {
  checks.claim(Kind::health, id + ".energy", "energy balance error < 1 %, " + name, h.balance_error < kBalanceLimit,
               "balance error " + fmt(h.balance_error, 3) + "; 1 %: the usual explicit-dynamics limit");
  checks.claim(Kind::health, id + ".quasistatic", "kinetic/internal energy < 5 % at the end (quasi-static), " + name,
               h.kinetic_ratio < kKineticLimit, "KE/IE " + fmt(h.kinetic_ratio, 3) + "; 5 %: the usual quasi-static limit");
  if (hourglass)
    checks.claim(Kind::health, id + ".hourglass", "hourglass/internal energy < 5 %, " + name,
                 h.hourglass_ratio < kHourglassLimit,
                 "HG/IE " + fmt(h.hourglass_ratio, 3) + "; 5 %: the usual limit for reduced integration");
}

}  // namespace drawbend::study
