// make bench: the per-phase split of a cycle (bench_phases.hpp).  The phases
// are those of fe::Solver::run_step: the element loop (of which the material
// updates are counted apart, in time-stamp-counter ticks converted with
// fe::seconds_per_tick), the node passes, contact, and the rest (tools, the
// caller's callback).  Set-up is not in any phase.
#include "bench_phases.hpp"

#include <omp.h>

#include <iostream>

#include "bench_models.hpp"

using namespace drawbend;

PhaseSplit bench_phases(const std::string& name, const fe::Model& m, long cycles, CsvWriter& w, int threads) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  fe::PhaseTimes t;
  double forked = 0;
  seconds(m, cycles, &t, &forked);
  omp_set_num_threads(before);
  const double per = 1e9 / (static_cast<double>(t.cycles) * m.mesh.num_elements());
  PhaseSplit s;
  if (threads == 1) s.material = static_cast<double>(t.material_ticks) * fe::seconds_per_tick() * per;
  s.kernel = t.kernel * per - s.material;
  s.nodes = t.nodes * per;
  s.contact = t.contact * per;
  s.other = t.other * per;
  s.total = s.kernel + s.material + s.nodes + s.contact + s.other;
  std::cout << name << ": per phase, " << threads << (threads == 1 ? " thread" : " threads")
            << ", ns per element-cycle: element kernel " << fmt(s.kernel, 3)
            << (threads == 1 ? " + material " + fmt(s.material, 3) : std::string(" (with material)"))
            << " + node passes " << fmt(s.nodes, 3) << " + contact " << fmt(s.contact, 3) << " + other "
            << fmt(s.other, 2) << " = " << fmt(s.total, 4);
  if (threads > 1) std::cout << " (element loop forked in " << fmt(100 * forked, 3) << " % of the cycles)";
  std::cout << "\n";
  const std::string ne = std::to_string(m.mesh.num_elements());
  for (const auto& [phase, ns] : {std::pair<const char*, double>{"kernel", s.kernel}, {"material", s.material},
                                  {"nodes", s.nodes}, {"contact", s.contact}, {"other", s.other}})
    if (threads == 1 || std::string(phase) != "material")
      w.row({name + "." + phase, ne, std::to_string(threads), fmt(ns, 4)});
  return s;
}
