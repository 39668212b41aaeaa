#pragma once
// The block-sliding model of Chapter 6 (Sec. 6.5, Fig. 6.7): a builder that
// makes the case deck (a typed io::CaseSpec) from a few physical parameters,
// and a runner that slides the block and reduces the run to the retrieved
// friction coefficients.
// `drawbend block-deck` writes the same deck for `drawbend run`.
//
// The model: a cube of edge `size` pressed on a rigid floor (the plane z = 0)
// by a pressure load on its top face, then slid by velocities given to all its
// nodes in the floor plane, at `direction_deg` from RD (global x).  The normal
// motion stays free, so the pressure stays uniform (no tipping moment to
// carry).  Two steps:
//   1. "press": the load ramps to p x size^2 over `press_ramp`, with damping;
//   2. "slide": the load held, the speed ramped to `speed` over `speed_ramp`.
// The friction of the floor is the nine-node mu(p, v) surface of Table 6.1
// (RD along x, TD along y, elliptical limit of Eq. 6.3b) unless `friction`
// names another law.  Units: mm, N, MPa, s, t/mm^3.
#include <string>
#include <vector>

#include "io/case_spec.hpp"
#include "io/deck.hpp"

namespace drawbend::sim {

struct BlockSpec {
  std::string name = "block_surface";  ///< the case name (and its run folder's name)
  double size = 1.0;            ///< edge of the cube [mm]
  int elements = 4;             ///< elements along each edge
  double pressure = 10.0;       ///< normal pressure on the top face [MPa]
  double speed = 50.0;          ///< sliding speed [mm/s]
  double direction_deg = 0.0;   ///< sliding direction from RD (x) towards TD (y) [deg]
  double mass_scaling = 100.0;  ///< uniform density factor
  double penalty = 0.1;         ///< contact penalty scale
  std::string hardening;        ///< hardening-curve CSV (plastic strain, true stress [MPa])
  std::string surface_nodes;    ///< the nine nodal values of Table 6.1 (CSV), for the default law
  int interval = 100;           ///< speed-averaging interval of the surface law [cycles]
  /// Friction of the floor, e.g. io::coulomb_friction(0.1) (io/case_spec.hpp);
  /// none: the surface law on `surface_nodes` with `interval`.
  std::optional<io::FrictionSpec> friction;
  double press_time = 2e-3;     ///< duration of step 1 [s]
  double press_ramp = 1e-3;     ///< load ramp of step 1 [s]
  double press_damping = 2e4;   ///< mass-proportional damping of step 1 [1/s]
  double slide_time = 3e-3;     ///< duration of step 2 [s]
  double speed_ramp = 5e-4;     ///< speed ramp of step 2 [s]
};

/// The spec with the data files of this tree (DRAWBEND_DATA_DIR): the RD
/// hardening curve of AA5754-O and Table 6.1's nodes.
BlockSpec default_block_spec(const std::string& data_dir);

/// The case deck for the spec, typed (io/case_spec.hpp); throws InputError naming a bad field.
io::CaseSpec block_case(const BlockSpec& s);
/// The deck's text: io::to_toml(block_case(s)).
std::string block_deck_text(const BlockSpec& s);
/// The deck parsed (file names in it are absolute).
io::Deck block_deck(const BlockSpec& s);

/// One slide, reduced.  Forces are those on the floor.
struct BlockResult {
  double mu_x = 0, mu_y = 0;    ///< mean F_x/F_N, F_y/F_N over the last third of the slide
  double p_min = 0, p_max = 0;  ///< nodal contact pressures at the end [MPa]
  double v_mean = 0;            ///< mean nodal slip speed at the end [mm/s]
  long cycles = 0;
};

/// Build the deck and slide the block in memory (no files written), with the
/// reduction a run folder keeps (io/case_reduction.hpp, kind block_slide): the
/// same bits as run_block_job.
BlockResult run_block(const BlockSpec& s);
/// The result of a finished run folder (its reduction.csv); InputError naming the file if absent.
BlockResult read_block_run(const std::string& dir);
/// The case as a file-level job (sim/deck_job.hpp): deck.toml in `dir`, `drawbend
/// run` through the executor (reused with `reuse` if the deck is unchanged), then read_block_run.
BlockResult run_block_job(const BlockSpec& s, const std::string& dir, bool reuse = false);
/// run_block_job for every spec through the case pool (sim/case_pool.hpp), in
/// spec order, each in `runs`/<its name> (names must differ).
std::vector<BlockResult> run_blocks(const std::vector<BlockSpec>& specs, const std::string& runs, bool reuse = false);

}  // namespace drawbend::sim
