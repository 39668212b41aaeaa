#pragma once
// make bench: the models it times (bench_models.cpp) and the clock it times
// them with.  Units: mm, N, MPa, s, t/mm^3.
#include <memory>
#include <string>

#include "fe/model.hpp"
#include "fe/phase_times.hpp"
#include "material/yld2004.hpp"

/// The bar's material (--bar-material): J2 isotropic (the default, the
/// reference figures), or CombinedPlasticity on the same curve and elastic
/// constants: "split" (beta = 0.3), "chaboche" (one Armstrong-Frederick term,
/// C = 5000 MPa, gamma = 40), "hill48" (Hill'48 from r = 0.65 / 0.65 / 0.72,
/// isotropic hardening), "hill48_chaboche" (both) or "yld2004" (Yld2004Plasticity with
/// bench_yld2004_set(), isotropic hardening); any of these with "_scalar" appended is the same model on
/// the element kernel's scalar path (no lane twin bound: the cost without lanes).  nullptr for an unknown name.
std::shared_ptr<const drawbend::material::Material> bar_material(const std::string& name);

/// The Yld2004-18p set of the benches: fitted to data/materials/aa6016_t4_esaform2021.csv by
/// `drawbend calibrate` (Chapter v1; c44 = c55 = 1), a = 8.
drawbend::material::Yld2004 bench_yld2004_set();

/// A structured bar of nx x ny x nz 1 mm hexahedra (J2 with linear hardening
/// unless `mat`), one end fixed, the other pulled axially at 20 m/s.
drawbend::fe::Model bar(int nx, int ny, int nz, std::shared_ptr<const drawbend::material::Material> mat = nullptr);

/// A draw-bend-sized strip with contact: 1.04 mm thick, 12.7 mm half-width,
/// drawn over a 12.7 mm pin with Coulomb friction (4,800 elements).
drawbend::fe::Model strip_on_pin();

/// Wall seconds of a solver built on a copy of `m` running `cycles` cycles of
/// its first step (set-up included); with `phases`, the cycle's phases are
/// also timed into it (fe/phase_times.hpp); with `forked_share`, the share of
/// the cycles whose element loop ran on threads (0 to 1) is stored there.
double seconds(drawbend::fe::Model m, long cycles, drawbend::fe::PhaseTimes* phases = nullptr,
               double* forked_share = nullptr);
