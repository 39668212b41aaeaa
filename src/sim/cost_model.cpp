#include "sim/cost_model.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>

namespace drawbend::sim {

double ns_per_element_cycle(const std::string& kind) {
  // Measured 2026-12-02 (docs/cluster.md): 250 ns / median(predicted / measured) per kind.
  if (kind.empty()) return 130;
  if (kind == "strip_draw") return 160;
  if (kind == "block_slide") return 190;
  if (kind == "cup_draw") return 210;
  if (kind == "earing_cup") return 210;  // von Mises cup's; was 310, the median of four materials
  return 310;
}

double material_factor(const std::string& material) {
  // Measured 2026-12-02 (docs/cluster.md): within a kind, median ns per element-cycle against j2's.
  if (material == "j2") return 1.0;
  if (material == "elastic") return 1.0;     // not measured: taken as j2's (a cheaper update)
  if (material == "j2_combined") return 1.6;  // Chapter 8's combined-hardening draw-bend runs against its j2 runs
  if (material == "hill48") return 1.6;      // Chapter v1's two Hill'48 cups against its von Mises cup
  if (material == "yld2004") return 12;      // Chapter v1's Yld2004-18p cup against its von Mises cup
  return 12;
}

const std::vector<std::string>& costed_materials() {
  static const std::vector<std::string> m = {"elastic", "j2", "j2_combined", "hill48", "yld2004"};
  return m;
}

CasePrediction predict_case(const io::Deck& d) {
  CasePrediction p;
  p.name = d.model.name;
  p.kind = d.output.reduce.kind;
  p.material = d.cost.material;
  p.elements = d.model.mesh.num_elements();
  p.cycles = d.cost.cycles;
  p.cpu_seconds = p.elements * p.cycles * ns_per_element_cycle(p.kind) * material_factor(p.material) * 1e-9;
  p.memory_mb = d.cost.memory_mb;
  return p;
}

JobNeeds job_needs(const CasePrediction& p, int cores) {
  JobNeeds n;
  n.cores = std::max(1, cores);
  n.memory_mb = kFixedMemoryMb + 2 * p.memory_mb;
  n.minutes = std::max(kMinMinutes, kTimeFactor * p.cpu_seconds / 60.0);
  return n;
}

double makespan_seconds(std::vector<double> cpu, int nodes, int cores, double eff) {
  std::sort(cpu.begin(), cpu.end(), std::greater<double>());
  const double speedup = cores <= 1 ? 1.0 : std::max(1.0, cores * eff);
  std::priority_queue<double, std::vector<double>, std::greater<double>> free_at;  // each node's finish time
  for (int k = 0; k < std::max(1, nodes); ++k) free_at.push(0);
  double end = 0;
  for (double c : cpu) {
    const double t = free_at.top() + c / speedup;
    free_at.pop();
    free_at.push(t);
    end = std::max(end, t);
  }
  return end;
}

}  // namespace drawbend::sim
