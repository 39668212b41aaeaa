// `drawbend drawbend-deck [options] [--run DIR]`: write the draw-bend case deck
// of the chapters' builder (src/sim/drawbend_case.hpp) for any pin, back
// tension, friction law and mesh, to standard output or, with --run, run it
// into DIR.  Units: mm, N, MPa, s.
#include <iostream>

#include "core/csv.hpp"
#include "core/options.hpp"
#include "sim/drawbend_case.hpp"

namespace drawbend::cli {

int drawbend_deck_command(int argc, char** argv) {
  sim::DrawBendSpec s;
  s.hardening = std::string(DRAWBEND_DATA_DIR) + "/materials/aa5754_o_rd.csv";
  std::string run_dir;
  Options opt("drawbend drawbend-deck", "Write (or run) a draw-bend case deck from the builder.");
  opt.add(s.name, "name", "case name");
  opt.add(s.pin_diameter, "pin-diameter", "pin diameter D [mm]");
  opt.add(s.thickness, "thickness", "strip thickness [mm]");
  opt.add(s.width, "width", "modelled half width [mm]");
  opt.add(s.back_tension, "back-tension", "back tension on the half model [N]");
  opt.add(s.speed, "speed", "outlet speed in the draw step [mm/s]");
  opt.add(s.draw_length, "draw-length", "slide in the draw step [mm] (0: 1.5 wrap lengths + 6 mm)");
  opt.add(s.friction, "friction", "pin friction as a TOML inline table (empty: frictionless), e.g. '{ law = \"coulomb\", mu = 0.1 }'");
  opt.add(s.element_length, "element-length", "element length along the strip in the bend zone [mm]");
  opt.add(s.across, "across", "elements across the half width");
  opt.add(s.through, "through", "elements through the thickness");
  opt.add(s.mass_scaling, "mass-scaling", "uniform mass scaling factor");
  opt.add(s.penalty, "penalty", "contact penalty scale");
  opt.add(s.hardening, "hardening", "hardening curve CSV (plastic strain, true stress [MPa])");
  opt.add(s.material, "material",
          "material: empty = isotropic J2 on --hardening; a TOML inline table of [material] keys, e.g. "
          "'{ type = \"j2_combined\", kinematic = { beta = 0.5 } }', or a TOML file with a [material] table "
          "(data/materials/*.toml)");
  opt.add(s.strip_direction, "strip-direction", "the strip's axis is the rolling direction (rd) or the transverse one (td)");
  opt.add(run_dir, "run", "run the deck into this directory instead of printing it");
  if (!opt.parse(argc, argv)) return 0;
  if (run_dir.empty()) {
    std::cout << sim::deck_text(s);
    return 0;
  }
  const sim::DrawBendResult r = sim::run_drawbend(s, run_dir, false, false);
  std::cout << "F_X = " << fmt(r.F_back, 6) << " N, F_Y = " << fmt(r.F_out, 6) << " N (last third; std "
            << fmt(r.F_out_std, 3) << " N), F_Y - F_X = " << fmt(r.tension_rise(), 5) << " N, mean contact pressure "
            << fmt(r.mean_pressure(), 4) << " MPa (half model)\n";
  return 0;
}

}  // namespace drawbend::cli
