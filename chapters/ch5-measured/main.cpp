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
#include <cmath>
#include <iostream>

#include "ch5_steps.hpp"

int main(int argc, char** argv) {
  drawbend::study::Chapter ch("ch5-measured", "Chapter 5: friction measurement on AA5754-O (measured data)");
  return drawbend::study::run_chapter(ch, argc, argv, [](drawbend::study::Chapter& c) {
    using namespace ch5;
    const Inputs in = load_inputs(c);  // 1
    rederive_pure_friction(c, in);     // 2
    rederive_table_5_14(c, in);        // 3
    conventional_mu(c, in);            // 4
    pressure_ratio_definitions(c, in); // 5
    undiluted(c, in);                  // 6
    friction_lines_and_surfaces(c, in);// 7
  });
}
