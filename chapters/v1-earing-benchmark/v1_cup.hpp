#pragma once
// One ESAFORM 2021 cup (chapter v1-earing-benchmark): draw a quarter blank
// with a material variant and measure the cup.  Units: mm, N, MPa, s.
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace v1 {

/// A material variant of data/benchmarks/esaform2021.csv.
struct Variant {
  std::string id, type, label;
  double r0 = 0, r45 = 0, r90 = 0;  ///< r-values (hill48 from r-values), or 0
  double s45 = 0, s90 = 0, sb = 0;  ///< yield-stress ratios to RD (hill48 from stresses), or 0
  /// Yld2004-18p (type yld2004): exponent and C', C'' (c12, c13, c21, c23, c31, c32, c44, c55, c66), set by the
  /// chapter from its own calibration on the published tests.
  double a = 0;
  std::array<double, 9> c1{}, c2{};
};

/// Mesh and loading of a run.
struct RunSpec {
  double stroke = 45.0;  ///< punch travel [mm]
  long cycles = 60000;   ///< cycles over the stroke (sets the mass scaling: dt = stroke / speed / cycles)
  double ramp = 0.0;     ///< punch travel over which the punch accelerates uniformly from rest [mm] (0: 2 % of the cycles)
  double speed = 100.0;  ///< punch speed [mm/s] (rate-independent material and Coulomb friction: only dt x speed matters)
  int core = 8, ring = 14, through = 3;  ///< quarter_disk element counts
  double polar_radius = -1;  ///< quarter_disk rows are circles from this radius out [mm]; 0: none; < 0: the deck's
  // Process alternatives for the diagnostic runs (defaults: the deck as published).
  double gap = 0;           ///< holder-die gap [mm] (0: the deck's 1.04 mm); the die moves, the holder stays at z = 0
  double holder_force = 0;  ///< > 0: holder force [N, quarter blank]; < 0: holder held fixed; 0: the deck's holder
  double mu = -1;           ///< >= 0: Coulomb mu on every contact (< 0: the deck's)
  bool voce = false;        ///< the published Voce curve instead of Swift
  /// > 0: punch-die clearance [mm] (die opening radius minus the punch's 30 mm; 0: the deck's 1.2 mm); the die's
  /// opening, shoulder and face move out radially together, the holder stays.
  double clearance = 0;
};

struct CupResult {
  std::vector<std::pair<double, double>> curve;  ///< (punch travel [mm], punch force of the full blank [N])
  /// Per rim column: angle from RD [deg] (reference), cup height [mm] = outer bottom (top face at the centre)
  /// minus the rim column's mean z.
  std::vector<std::pair<double, double>> height;
  /// Per rim column: angle from RD [deg] (reference), the column's mean radius [mm] (the flange outline while
  /// the flange is under the holder: the larger the radius, the more sheet is left to draw, the higher the wall).
  std::vector<std::pair<double, double>> outline;
  /// Thickness lines at the end: angle (0, 45, 90), initial radius [mm], current radius [mm], current z [mm],
  /// thickness [mm] (distance of the top node from the bottom node of the column).
  std::vector<std::array<double, 5>> thickness;
  /// Where the hourglass energy is, at each tenth of the stroke: punch travel [mm], region (index into
  /// kRegions, by the element centre's current position), hourglass work done so far in the region's current
  /// elements [mJ, quarter blank], and the energy stored in the hourglass springs by mode [mJ]: xi*eta in plane
  /// (the element's in-plane bending), xi*eta out of plane (twist), xi*eta*zeta.
  std::vector<std::array<double, 6>> hourglass_regions;
  double volume_ratio = 0;  ///< current volume / initial volume of the sheet
  double kinetic_ratio = 0, max_kinetic_ratio = 0, hourglass_ratio = 0, balance_error = 0;
  double added_mass_ratio = 0;
  double rim_r_max = 0;  ///< largest radius of a rim node at the end [mm] (< kFlangeOutRadius: the flange has left the holder)
  double rim_z_min = 0;  ///< lowest rim node at the end [mm]
  long cycles = 0;
  int elements = 0, layers = 0;
  /// The material's event counts over the run, by name (the run's summary.csv rows material_<name>:
  /// Yld2004-18p's plastic_updates, split_updates, fallback_updates; none for the other models).
  std::map<std::string, long> material_counts;
};

/// Where the die shoulder ends and the flat die face under the holder begins [mm]: the die opening radius
/// (31.2 mm) plus the shoulder radius (10 mm), as in the deck.  A rim node inside it has left the holder.
inline constexpr double kFlangeOutRadius = 31.2 + 10.0;

/// Regions of the cup by the current position of an element's centre (radius r, height z; tools as in the
/// deck): punch face r < 25, punch nose 25 <= r < 30, wall r < kFlangeOutRadius above the die shoulder
/// (z >= 11.04), die shoulder and free span below it, flange r >= kFlangeOutRadius (under the holder).  Units: mm.
inline constexpr const char* kRegions[5] = {"punch face", "punch nose", "wall", "die shoulder", "flange"};
int region_of(double r, double z);

/// The deck of a run (TOML, runnable by `drawbend run`): `deck` with the variant's material, the mesh, the
/// process alternatives, the mass scaling and punch ramp of `spec` as deck keys, and the reduction the chapter
/// reads (io/case_reduction.hpp, kind earing_cup).
std::string deck_text(const std::string& deck, const Variant& variant, const RunSpec& spec);
/// The measurements of a finished run folder of deck_text (its reduction.csv and deck.toml).
CupResult read_run(const std::string& dir, const RunSpec& spec);
/// Draw the cup from `deck` with `variant` as a file-level job (sim/deck_job.hpp) in the run folder `dir`
/// (kept; with `reuse`, a folder holding the same deck and a finished run is read, not rerun), then read_run;
/// copies the run's end-of-stroke fields to `vtu` when set.
CupResult draw(const std::string& deck, const Variant& variant, const RunSpec& spec, const std::string& vtu,
               const std::string& dir, bool reuse = false);

/// Ears (local maxima) and troughs (local minima) of a profile h(theta) on 0..90 deg mirrored about 0 and
/// 90 deg (orthotropic symmetry): (angle, height) each.
struct Extrema {
  std::vector<std::pair<double, double>> ears, troughs;
};
Extrema extrema(const std::vector<std::pair<double, double>>& h);

/// Relative departure of the quarter-disk mesh from polar symmetry: the largest |w_k / mean(w) - 1| of the
/// angular widths w_k of the ring elements at reference radius r (before any run).
/// Radius from which the quarter disk's rows are circles [mm] (mesh.polar_radius rounded down to a row of the
/// 0-degree line, src/fe/disk.hpp); 0 when the deck and spec set none.
double polar_start(const std::string& deck, const RunSpec& spec);

double mesh_angular_error(const std::string& deck, const RunSpec& spec, double r);

}  // namespace v1
