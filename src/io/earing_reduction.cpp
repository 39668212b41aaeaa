// The earing cup's reduction (kind earing_cup), kept by the run: what chapter
// v1-earing-benchmark measures on its cups.  See case_reduction.hpp.
#include <algorithm>
#include <cmath>

#include "core/csv.hpp"
#include "fe/mesh.hpp"
#include "io/case_reduction.hpp"

namespace drawbend::io {

namespace {

ReducedValue scalar(const std::string& q, double v) { return {q, NAN, NAN, v}; }

/// Energy stored in the hourglass springs of every element [mJ], by mode group
/// (in-plane xi*eta, twist xi*eta, xi*eta*zeta): 32 Q^2 / K per mode (Q += dt
/// K/64 q, power Q q), with K of the element kernel (fe/element_kernel.hpp) on
/// the element's current volume and half-lengths along its natural axes.
std::vector<std::array<double, 3>> hourglass_stored(const fe::Solver& s, double E, double nu) {
  const fe::Mesh& mesh = s.model().mesh;
  const double G = E / (2 * (1 + nu));
  const auto& q = s.hourglass_forces();
  std::vector<std::array<double, 3>> out(mesh.hex.size());
  for (std::size_t e = 0; e < mesh.hex.size(); ++e) {
    double ex[8], ey[8], ez[8];
    for (int a = 0; a < 8; ++a) ex[a] = s.x()[mesh.hex[e][a]], ey[a] = s.y()[mesh.hex[e][a]], ez[a] = s.z()[mesh.hex[e][a]];
    const double V = fe::hex_volume(ex, ey, ez);
    // half-lengths: half the mean length of the 4 edges along xi (0-1), eta (0-3), zeta (0-4)
    const int edges[3][4][2] = {{{0, 1}, {3, 2}, {4, 5}, {7, 6}}, {{0, 3}, {1, 2}, {4, 7}, {5, 6}}, {{0, 4}, {1, 5}, {2, 6}, {3, 7}}};
    double ih2[3];
    for (int d = 0; d < 3; ++d) {
      double len = 0;
      for (const auto& ed : edges[d])
        len += 0.25 * std::sqrt(std::pow(ex[ed[1]] - ex[ed[0]], 2) + std::pow(ey[ed[1]] - ey[ed[0]], 2) +
                                std::pow(ez[ed[1]] - ez[ed[0]], 2));
      ih2[d] = 4.0 / (len * len);
    }
    const double K2[3] = {E * V * ih2[0] / 3, E * V * ih2[1] / 3, G * V * (ih2[0] + ih2[1]) / 3};
    for (int i = 0; i < 3; ++i) {
      const double w2 = 32 * q[6 * e + i] * q[6 * e + i] / K2[i];
      const double w3 = 32 * q[6 * e + 3 + i] * q[6 * e + 3 + i] / (E * V * ih2[i] / 9);
      out[e][i < 2 ? 0 : 1] += w2;
      out[e][2] += w3;
    }
  }
  return out;
}

/// The earing cup (chapter v1), a quarter model: punch curve, hourglass
/// snapshots each tenth of the stroke, the sheet's nodes at the end.
class EaringCup : public CaseReduction {
 public:
  EaringCup(const ReductionSpec& r, const fe::Model& m) : r_(r), w_(reduction_place(r, m)), work_(m.mesh.hex.size(), 0.0) {
    if (!(r.stroke > 0)) throw InputError("output.reduce.stroke: earing_cup needs the punch stroke [mm], > 0");
    if (!m.material) throw InputError("output.reduce: earing_cup needs the sheet's material");
  }
  void cycle(const fe::Solver& s, const fe::Progress& p) override {
    if (p.step_index < w_.step) {  // the punch's start as the step will begin
      z0_ = s.tool_offset(r_.tool)[2];
      return;
    }
    if (p.step_index != w_.step) return;
    const auto& inc = s.hourglass_increments();
    for (std::size_t e = 0; e < work_.size(); ++e) work_[e] += inc[e];
    const auto& e = s.energies();
    const double travel = s.tool_offset(r_.tool)[2] - z0_;  // [mm]
    if (e.internal > 0 && travel > 0.1 * r_.stroke) max_kinetic_ = std::max(max_kinetic_, e.kinetic / e.internal);
    const int tenths = static_cast<int>(10.0 * travel / r_.stroke + 1e-9);
    if (tenths > reported_) {
      reported_ = tenths;
      snapshot(s, travel, snapshots_);
    }
    if (p.cycle % r_.every) return;
    curve_.push_back({"curve", travel, NAN, -4.0 * s.tool_force(r_.tool)[2]});  // full blank: 4 quarters
  }
  std::vector<ReducedValue> finish(const fe::Solver& s) const override {
    const auto& e = s.energies();
    std::vector<ReducedValue> out{scalar("cycles", static_cast<double>(s.cycles())),
                                  scalar("kinetic_ratio", e.internal > 0 ? e.kinetic / e.internal : 0),
                                  scalar("max_kinetic_ratio", max_kinetic_),
                                  scalar("hourglass_ratio", e.internal > 0 ? e.hourglass / e.internal : 0),
                                  scalar("balance_error", e.balance_error()),
                                  scalar("added_mass_ratio", s.added_mass() / s.physical_mass())};
    out.insert(out.end(), curve_.begin(), curve_.end());
    out.insert(out.end(), snapshots_.begin(), snapshots_.end());
    // The end, when the last cycle fell short of the last tenth.
    if (reported_ < 10) snapshot(s, s.tool_offset(r_.tool)[2] - z0_, out);
    const fe::Mesh& mesh = s.model().mesh;
    for (int i = 0; i < mesh.num_nodes(); ++i) out.push_back({"node", s.x()[i], s.y()[i], s.z()[i]});
    return out;
  }

 private:
  /// Rows `hourglass` (x = punch travel [mm], value = the snapshot's number),
  /// then per element `hg_work` (x, y = radius and z of the element's centre
  /// [mm], value = hourglass work done so far [mJ]) and `hg_stored` (x, y,
  /// value = the stored energy by mode group [mJ]).
  void snapshot(const fe::Solver& s, double travel, std::vector<ReducedValue>& out) const {
    const fe::Mesh& mesh = s.model().mesh;
    const auto stored = hourglass_stored(s, s.model().material->youngs_modulus(), s.model().material->poisson_ratio());
    out.push_back({"hourglass", travel, NAN, static_cast<double>(reported_)});
    for (std::size_t e = 0; e < mesh.hex.size(); ++e) {
      double cx = 0, cy = 0, cz = 0;
      for (int a = 0; a < 8; ++a) cx += s.x()[mesh.hex[e][a]] / 8, cy += s.y()[mesh.hex[e][a]] / 8, cz += s.z()[mesh.hex[e][a]] / 8;
      out.push_back({"hg_work", std::hypot(cx, cy), cz, work_[e]});
      out.push_back({"hg_stored", stored[e][0], stored[e][1], stored[e][2]});
    }
  }

  ReductionSpec r_;
  ReductionPlace w_;
  std::vector<double> work_;
  double z0_ = 0, max_kinetic_ = 0;
  int reported_ = 0;
  std::vector<ReducedValue> curve_, snapshots_;
};

}  // namespace

std::unique_ptr<CaseReduction> make_earing_reduction(const ReductionSpec& r, const fe::Model& m) {
  return std::make_unique<EaringCup>(r, m);
}

}  // namespace drawbend::io
