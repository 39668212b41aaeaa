#pragma once
// make bench: the CalculiX (ccx) input deck of a bench bar and the numbers
// read back from its outputs (bench_ccx_deck.cpp; the run: bench_calculix.cpp).
// Units as ours: mm, N, MPa, s, t/mm^3.
#include <optional>
#include <string>

#include "core/vec3.hpp"
#include "fe/model.hpp"

/// The bar of bench_models.hpp's bar() as a ccx deck: the same nodes
/// (ccx node n+1 is our node n) and hexahedra as C3D8R (one integration point,
/// ccx's own hourglass control), the same J2 material with linear hardening
/// (*PLASTIC points from the J2Isotropic curve), xmin held in x, y, z, xmax
/// held in y, z and pulled in x at the model's velocity (initial velocity plus
/// a linear displacement amplitude), one *DYNAMIC, EXPLICIT step of
/// `duration` seconds with NLGEOM at ccx's own stable increment.  The only
/// output, at the last increment: the total reaction on XMIN and the
/// displacement of node `probe` (set PROBE) in the .dat, and the
/// displacement of PROBE in the .frd (its record names the increment).
/// Throws std::invalid_argument if `m` is not such a bar (another material,
/// other loads).
std::string ccx_bar_deck(const drawbend::fe::Model& m, double duration, int probe);

/// What a finished ccx run reports, read from its files in `dir` for job `job`.
struct CcxOutput {
  long increments = 0;     ///< the last .frd record's increment number
  double dt = 0;           ///< "SELECTED time increment" from ccx's log [s]
  drawbend::Vec3 reaction{0, 0, 0};  ///< total RF on XMIN at the end [N]
  drawbend::Vec3 probe_u{0, 0, 0};   ///< displacement of PROBE at the end [mm]
  std::string version;     ///< "2.20" from the log's "CalculiX Version 2.20"
};

/// Reads the log (stdout and stderr of ccx), JOB.dat and JOB.frd; nullopt
/// with `why` set when a number is missing.
std::optional<CcxOutput> read_ccx_output(const std::string& dir, const std::string& job, const std::string& log,
                                         std::string& why);
