// Chapter 8 step 4 (full tier only): numerical effects before physics.
//  - mass scaling on every pin: the quick tier's factor, 1/4 and 1/16 of it
//    (isotropic model, Table 5.13 back tensions);
//  - elements across the half width: 2, 4, 8 on the 25.4 and 42 mm pins
//    (F_B, peak and mean contact pressure of the end-of-draw map).
// Forces full strip [N], pressures MPa.
#include <cmath>

#include "ch8_steps.hpp"

namespace ch8 {

using namespace drawbend;

void numerical_convergence(Chapter& c, const Inputs& in, const Config& cfg) {
  const double ms0 = in.base.mass_scaling;
  const std::vector<double> ms = {ms0, ms0 / 4, ms0 / 16};
  const std::vector<int> across = {2, 4, 8};
  std::vector<sim::DrawBendSpec> specs;
  for (std::size_t k = 0; k < in.pins.size(); ++k)
    for (double m : ms) {
      auto s = sim::spec_for_point(in.base, {in.pins[k], in.fback[k], 0, ""});
      s.mass_scaling = m;
      specs.push_back(s);
    }
  const std::size_t n_ms = specs.size();
  std::vector<std::size_t> across_pin;
  for (std::size_t k = 0; k < in.pins.size(); ++k) {
    if (in.pins[k] < 25.4 - 1e-9) continue;
    for (int a : across) {
      auto s = sim::spec_for_point(in.base, {in.pins[k], in.fback[k], 0, ""});
      s.across = a;
      specs.push_back(s);
      across_pin.push_back(k);
    }
  }
  const auto runs = sim::run_cached(specs, c.out("runs"), cfg.reuse_runs != 0);

  auto t1 = c.table({"pin_mm", "mass_scaling", "F_B_N", "change_vs_finest_pct", "KE_IE", "wall_s"},
                    "mass-scaling convergence of F_B (isotropic model, full strip, N); change against the smallest "
                    "mass scaling on the same pin");
  for (std::size_t k = 0; k < in.pins.size(); ++k) {
    const double finest = 2 * runs[k * ms.size() + ms.size() - 1].tension_rise();
    for (std::size_t j = 0; j < ms.size(); ++j) {
      const auto& r = runs[k * ms.size() + j];
      const double fb = 2 * r.tension_rise();
      t1.row({fmt(in.pins[k]), fmt(ms[j]), fmt_fixed(fb, 1), fmt_fixed(100 * (fb / finest - 1), 1),
              fmt(r.kinetic_ratio, 3), fmt_fixed(r.wall_seconds, 0)});
      if (j == 0) c.value("ms_change_d" + fmt(in.pins[k]), fmt_fixed(100 * (fb / finest - 1), 1), "%");
    }
  }
  c.save(t1, "mass_scaling");
  auto t2 = c.table({"pin_mm", "across", "F_B_N", "change_vs_finest_pct", "p_max_MPa", "p_mean_MPa", "wall_s"},
                    "width discretisation: elements across the half width (isotropic model, full strip F_B [N], "
                    "end-of-draw contact map, half model)");
  for (std::size_t i = 0; i < across_pin.size(); ++i) {
    const auto& r = runs[n_ms + i];
    const auto& finest = runs[n_ms + (i / across.size()) * across.size() + across.size() - 1];
    double pmax = 0;
    for (const auto& m : r.map) pmax = std::max(pmax, m.pressure);
    const double fb = 2 * r.tension_rise();
    t2.row({fmt(in.pins[across_pin[i]]), std::to_string(across[i % across.size()]), fmt_fixed(fb, 1),
            fmt_fixed(100 * (fb / (2 * finest.tension_rise()) - 1), 1), fmt_fixed(pmax, 1),
            fmt_fixed(r.mean_pressure(), 2), fmt_fixed(r.wall_seconds, 0)});
  }
  c.save(t2, "width_convergence");
}

}  // namespace ch8
