// Chapter 5, measured-data part: the new method applied to friction tests on
// mill-finished AA5754-O (thesis Sections 5.4-5.9).  This driver needs no
// finite-element solver: it re-derives every table the thesis derives from
// other tables, evaluates the conventional method (Eq. 5.1), tests which
// definition of the pressure ratio c reproduces Tables 5.15 and 5.18, and draws
// the mu(p) lines and surfaces of Table 5.16.  Forces are full-strip measured
// forces in N; pressures in MPa; speeds in mm/s.
//
// Recipe:
//   1. Load the printed fits (Tables 5.3, 5.5-5.12) and cases (5.13-5.18).
//   2. Re-derive Tables 5.11/5.12 = Tables 5.5-5.10 - Table 5.3.
//   3. Re-derive Table 5.14 = Tables 5.11/5.12 at the Table 5.13 back tensions.
//   4. Conventional mu at F_back = 1700 N (Figs. 5.19/5.20) and the text's claims.
//   5. The pressure ratio c (Tables 5.15, 5.18): which definition reproduces it.
//   6. Undiluted lubricant: conventional mu (Fig. 5.30).
//   7. mu(p) lines and surfaces from the printed Table 5.16 (Figs. 5.26-5.29).
//   8. Our frictionless pressure maps for the three pins (Sec. 5.7.1, Figs. 5.23-5.25).
//   9. Diluted lubricant: the new method on our maps (Table 5.16 ours, Figs. 5.26-5.29 ours).
//  10. Undiluted lubricant: second-order mu(p) from three pins (Figs. 5.31, 5.32).
//  11. Sensitivity of a0, a1 to the map (mesh, penalty, hardening) and to c.
// Steps 8-11 run our finite-element solver (--fe false skips them).
//
// Sample runs (from the source folder after `make`; the binaries are in build/chapters/):
//   chapter_ch5_measured --out build/chapters/ch5-measured
//       (the quick tier, as `ctest -R chapter.ch5-measured` runs it)
//   chapter_ch5_measured --tier full --fe-map-variants true --fe-across-variant true
//       (the full tier with the map and mesh variants (`make test-full`))
//   chapter_ch5_measured --fe false
//       (the measured-data part only, no FE run)
#include <cmath>
#include <iostream>

#include "ch5_steps.hpp"
#include "sim/fe_options.hpp"

int main(int argc, char** argv) {
  drawbend::study::Chapter ch("ch5-measured", "Chapter 5: friction measurement on AA5754-O (measured data)");
  ch5::FeOptions fe;  // the chapter's options
  auto& o = ch.options();
  drawbend::sim::add_fe_options(o, fe.base, fe.run, fe.reuse);
  o.add(fe.fine_element_length, "fe-fine-element-length", "finer-map variant along the strip: element length [mm] (0: half the base)");
  o.add(fe.fine_across, "fe-fine-across", "finer-map variant across: elements across the half width (0: twice the base)");
  o.add(fe.stiff_penalty, "fe-stiff-penalty", "penalty variant: contact penalty scale (base 0.1)");
  o.add(fe.map_variants, "fe-map-variants",
        "run the map variants of the sensitivity study (stiffer penalty, TD curve, finer along; 6 runs)");
  o.add(fe.across_variant, "fe-across-variant", "with --fe-map-variants true: the finer-across-the-width variant too");
  o.range("fe-fine-element-length", 0, 20, "mm", true, false, true).range("fe-fine-across", 1, 128, "", false, false, true);
  o.range("fe-stiff-penalty", 0, 1000, "", true);
  return drawbend::study::run_chapter(ch, argc, argv, [&fe](drawbend::study::Chapter& c) {
    using namespace ch5;
    const Inputs in = load_inputs(c);  // 1
    rederive_pure_friction(c, in);     // 2
    rederive_table_5_14(c, in);        // 3
    conventional_mu(c, in);            // 4
    pressure_ratio_definitions(c, in); // 5
    undiluted(c, in);                  // 6
    friction_lines_and_surfaces(c, in);// 7
    c.value("fe_ran", fe.run ? "yes" : "no");
    if (!fe.run) return;
    const FeMaps maps = run_fe_maps(c, in, fe);  // 8
    diluted_new_method(c, in, maps);            // 9
    undiluted_new_method(c, in, maps);          // 10
    map_sensitivity(c, in, maps);           // 11
  });
}
