#include "sim/fe_options.hpp"
#include "core/install_paths.hpp"

#include <string>

namespace drawbend::sim {

double mass_scaling_for_speed(double at_100, double v) { return at_100 * (100.0 / v) * (100.0 / v); }

void set_quick_mesh(DrawBendSpec& s) {
  s.element_length = 1.0;
  s.across = 2;
  s.through = 4;
  s.mass_scaling = kQuickMassScaling;
}

DrawBendSpec quick_deck_spec() {
  DrawBendSpec s;
  set_quick_mesh(s);
  s.mass_scaling = mass_scaling_for_speed(kQuickMassScaling, s.speed);
  s.hardening = drawbend::data_dir() + "/materials/aa5754_o_rd.csv";
  return s;
}

void add_fe_options(Options& o, DrawBendSpec& base, bool& run_fe, bool& reuse_runs) {
  set_quick_mesh(base);
  o.add(run_fe, "fe", "run the finite-element part");
  o.add(reuse_runs, "reuse-runs", "reuse runs whose deck is unchanged, for development only");
  o.add(base.element_length, "fe-element-length", "element length along the strip in the bend zone [mm]");
  o.add(base.across, "fe-across", "elements across the half width");
  o.add(base.through, "fe-through", "elements through the thickness");
  o.add(base.mass_scaling, "fe-mass-scaling", "mass scaling at 100 mm/s (scaled by (100/v)^2 at speed v)");
  o.add(base.bend_inlet_slides, "fe-bend-inlet-slides",
        "bend step with the inlet end sliding under the back tension (true) or clamped as before issue 51 (false, "
        "for reproduction: it pre-stretches the strip ~1.3 %)");
  // Checked as parsed: a bad value ends the chapter with exit 2 naming the option, before any run.
  o.range("fe-element-length", 0, 20, "mm", true).range("fe-across", 1, 64).range("fe-through", 1, 32);
  o.range("fe-mass-scaling", 1, 1e9);
}

}  // namespace drawbend::sim
