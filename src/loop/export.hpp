#pragma once
// Export of an identified friction model (friction_model.toml + its nine-node
// CSV, friction_model.hpp) to the decks of other solvers.  Units throughout:
// N, mm, s, MPa (pressure MPa, sliding speed mm/s); the written decks say so.
//
//  lsdyna       mu tabulated over contact pressure and sliding speed, one
//               *DEFINE_TABLE of *DEFINE_CURVEs per direction, for *CONTACT
//               with FS = -2 (FD = table ID).  RD is the contact's table; the TD
//               table is for the orthotropic pair (*DEFINE_FRICTION_ORIENTATION).
//  openradioss  /FRICTION with the generalized viscous law (Ifric = 1),
//               mu = Fric + C1 p + C2 v + C3 p v + C4 p^2 + C5 v^2, least-squares
//               fitted to the surface per direction; orthotropic Idir = 1 (the
//               first coefficient block RD, the second TD, with /FRIC_ORIENT).
//  abaqus       *FRICTION, ANISOTROPIC: data lines mu_1 (RD), mu_2 (TD), slip
//               rate, contact pressure, tabulated on the same grid.
//
// Every export states its error against our law (max |mu_export - mu_law| on a
// 4x finer grid over the domain), and tests evaluate the written numbers back.
#include <string>
#include <vector>

#include "analysis/friction_surface.hpp"

namespace drawbend::loop {

struct ExportModel {
  analysis::FrictionSurface rd, td;
  std::string source;  ///< the toml file
};

/// Read friction_model.toml ([friction] law = "surface", nodes, domain) and its
/// nodes CSV (relative to the toml's directory).  Throws InputError.
ExportModel read_friction_model(const std::string& toml_path);

struct ExportResult {
  std::string text;        ///< the deck fragment
  double max_error = 0;    ///< max |mu_export - mu_law| over the check grid
  std::string format;
};

/// Grid: n_p x n_v points over the domain (tables); fit error for Radioss.
ExportResult export_lsdyna(const ExportModel& m, int n_p = 11, int n_v = 11);
ExportResult export_openradioss(const ExportModel& m);
ExportResult export_abaqus(const ExportModel& m, int n_p = 11, int n_v = 11);

/// Radioss generalized viscous law coefficients {Fric, C1..C5} fitted to s.
std::vector<double> radioss_fit(const analysis::FrictionSurface& s);
double radioss_mu(const std::vector<double>& c, double p, double v);

}  // namespace drawbend::loop
