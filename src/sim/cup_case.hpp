#pragma once
// The cup-drawing builder (thesis Sec. 6.6): the quarter-model deck
// data/cases/cup_draw.toml with the choices a study varies, run in memory.
// Chapter 6 draws the Table 6.5 cases with it; Chapter 8's cup loop varies the
// assumed tool radii, the material and the friction with it; `drawbend
// cup-deck` writes the same deck for `drawbend run`.
//
// Per run the builder sets the punch speed and the time step: the stroke takes
// `cycles` cycles, so the mass scaling is dt ~ 1/v and the inertia forces
// (~ m v^2 ~ (dt v)^2) are the same for every speed while the sliding speeds,
// which the friction law sees, are the real ones.  The force-driven lower die
// (the 20 kN blank holder) gets a rigid mass for omega dt = 0.5 on its contact
// springs.
//
// Units: mm, N, MPa, s.  Forces in CupResult are for the full blank (4 x the quarter).
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "io/case_spec.hpp"

namespace drawbend::sim {

struct CupSpec {
  std::string deck;            ///< base deck (data/cases/cup_draw.toml)
  double speed = 6.4;          ///< punch speed [mm/s] (Table 6.5 case 1)
  double stroke = 17;          ///< punch travel [mm]
  long cycles = 30000;         ///< cycles per stroke (sets dt and so the mass scaling)
  int refine = 1;              ///< the deck's element counts (in-plane and through) times this
  std::string material;        ///< sim/material_choice.hpp choice; empty: the deck's (isotropic J2, Table 5.1 RD)
  double punch_radius = NAN;   ///< punch corner radius [mm]; NaN: the deck's (ASSUMED 5 mm)
  double die_radius = NAN;     ///< upper-die corner radius [mm]; NaN: the deck's (ASSUMED 5 mm)
  /// Friction on every contact: empty = the deck's (Table 6.1 mu(p, v), RD along x);
  /// "none" = frictionless; otherwise the path of a Table 6.1-format nodes CSV.
  std::string friction;
  std::string vtu;             ///< write the end-of-stroke fields here when set
  /// OpenMP threads of `drawbend run` in the deck's [numerics] (0: the base
  /// deck's, if any; cup-deck's --threads).
  int threads = 0;
};

/// One cup-drawing run.  Forces for the full blank [N], sizes and positions [mm].
struct CupResult {
  std::vector<std::pair<double, double>> curve;  ///< (punch displacement, punch force)
  double die_force = 0;                          ///< clamping force (lower die) at the end
  double size_rd = 0, size_td = 0;               ///< flange outer diameter along RD (x) and TD (y)
  double max_strain = 0, max_strain_r = 0, max_strain_z = 0;  ///< largest plastic strain and where
  double max_strain_angle = 0;                   ///< its angle from RD (x) about the cup axis [deg]: 0 RD, 90 TD
  /// Largest plastic strain within 15 deg of RD and of TD: mirror-image bands of the
  /// disk mesh (symmetric about 45 deg), so with isotropic friction and material they are equal.
  double band_rd = 0, band_td = 0;
  double die_lift = 0;                           ///< lower-die displacement at the end
  double kinetic_ratio = 0, hourglass_ratio = 0, added_mass_ratio = 0;  ///< over internal energy; added/physical mass
  double wall_seconds = 0;
  long cycles = 0;
  int elements = 0, layers = 0;                  ///< mesh of the run (after refinement)
  /// Per element at the end: centroid x, y, z [mm], equivalent plastic strain, von Mises stress [MPa].
  std::vector<std::array<double, 5>> field;
};

/// The case of a spec (io/case_spec.hpp): the base deck read into a typed
/// io::CaseSpec with the mesh refined, the radii, material and friction
/// replaced (paths absolute), and the speed, time step, step durations, the
/// force-driven tools' masses and the reduction set as described above.
io::CaseSpec cup_case(const CupSpec& s);
/// The deck text of a spec (TOML, runnable by `drawbend run`): a comment
/// header and io::to_toml(cup_case(s)).
std::string cup_deck_text(const CupSpec& s);
/// Build and run a spec (progress: one line per 10 % of the stroke on stderr).
CupResult draw_cup(const CupSpec& s);
/// The case as a file-level job (sim/deck_job.hpp): cup_deck_text in `dir`,
/// `drawbend run` through the executor (reused with `reuse` if the deck is
/// unchanged), then read_cup_run: the same bits as draw_cup but for
/// wall_seconds (the run's own) and no progress lines.
CupResult draw_cup_job(const CupSpec& s, const std::string& dir, bool reuse = false);
/// The result of a finished run folder of `s` (its reduction.csv); with s.vtu
/// set, the run's last field snapshot is copied there.
CupResult read_cup_run(const CupSpec& s, const std::string& dir);
/// Punch force at displacement d by linear interpolation (NaN beyond the curve).
double force_at(const CupResult& r, double d);
/// A Table 6.1-format nodes CSV whose RD and TD columns both hold the mean of
/// the two: isotropic friction at the same level, for attribution studies.
void write_isotropic_nodes(const std::string& table_6_1, const std::string& out_csv);

}  // namespace drawbend::sim
