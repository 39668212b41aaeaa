#pragma once
// Steps of the Chapter 6 driver that run the solver (see main.cpp).
#include "study/chapter.hpp"

namespace ch6 {
/// Sec. 6.5: block sliding with the mu(p, v) law (Tables 6.2-6.4, Figs. 6.8-6.10),
/// from data/cases/block_surface.toml.
void block_sliding(drawbend::study::Chapter& c);
}  // namespace ch6

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace ch6 {
/// One cup-drawing run (ch6_cup.cpp).  Forces for the full blank [N], sizes and positions [mm].
struct CupResult {
  std::vector<std::pair<double, double>> curve;  ///< (punch displacement, punch force)
  double die_force = 0;                          ///< clamping force (lower die) at the end
  double size_rd = 0, size_td = 0;               ///< flange outer diameter along RD (x) and TD (y)
  double max_strain = 0, max_strain_r = 0, max_strain_z = 0;  ///< largest plastic strain and where
  double max_strain_angle = 0;                   ///< its angle from RD (x) about the cup axis [deg]: 0 RD, 90 TD
  /// Largest plastic strain within 15 deg of RD and of TD: mirror-image bands of the
  /// disk mesh (symmetric about 45 deg), so their difference is the friction's.
  double band_rd = 0, band_td = 0;
  double die_lift = 0;                           ///< lower-die displacement at the end
  double kinetic_ratio = 0, hourglass_ratio = 0, added_mass_ratio = 0;  ///< over internal energy; added/physical mass
  long cycles = 0;
  int elements = 0, layers = 0;                  ///< mesh of the run (after refinement)
  /// Per element at the end: centroid x, y, z [mm], equivalent plastic strain, von Mises stress [MPa].
  std::vector<std::array<double, 5>> field;
};
/// Draw a cup from `deck_path` at punch speed [mm/s] over `stroke` [mm] in `cycles`
/// cycles; optional mesh refinement factor; writes a VTU snapshot at the end when `vtu` is set.
/// `material`: the deck's [material] replaced by this choice (sim/material_spec.hpp: an inline
/// table of [material] keys or a TOML file); empty: the deck's own (isotropic J2, Table 5.1 RD).
CupResult draw_cup(const std::string& deck_path, double speed, double stroke, long cycles, const std::string& vtu,
                   int refine = 1, const std::string& material = "");
/// Punch force at displacement d by linear interpolation (NaN beyond the curve).
double force_at(const CupResult& r, double d);
/// Sec. 6.6: the cup-drawing cases (coarse cases 1 and 9 by default; all nine, finer, with `full`).
/// `cases`: comma-separated Table 6.5 case ids to run instead (must hold case 1 and the last case).
/// `material`: as for draw_cup (the page then names it).
void cup_drawing(drawbend::study::Chapter& c, bool full, const std::string& cases = "", const std::string& material = "");
}  // namespace ch6
