#pragma once
// Export of an identified friction model (friction_model.toml + its nine-node
// CSV, friction_model.hpp) to the decks of other solvers.  Units throughout:
// N, mm, s, MPa (pressure MPa, sliding speed mm/s); the written decks say so.
//
// The law exported is the solver's (friction/surface_law.hpp): the nine-node
// surface mu(p, v) per direction, with p and v CLAMPED to the data's domain
// [p_min, p_max] x [v_min, v_max] and mu floored at 0.  Tables reproduce that
// clamp (flat end points); the OpenRadioss polynomial cannot, and says so.
//
//  openradioss  /FRICTION (layout of OpenRadioss's reader,
//               hm_cfg_files/config/CFG/radioss2020/FRICTION/friction.cfg:
//               ints in 10-character fields, reals in 20-character fields, the
//               pair card "%10d%10d%10d%10d          %10d" with Idir in columns
//               51-60), generalized viscous law Ifric = 1,
//                 mu = Fric + C1 p + C2 v + C3 p v + C4 p^2 + C5 v^2,
//               Iform = 2 (stiffness, incremental).  Direction: an isotropic
//               pair law for one direction (rd, td, or their mean); `ortho`
//               writes Idir = 1 (RD block, TD block) with a note of what is known
//               about it.  The fit minimises the largest relative error over the
//               domain (Lawson's iteratively reweighted least squares); when one
//               quadratic exceeds max_rel_error the speed range is split into
//               bands, one /FRICTION per band (the header says which is which).
//               /FRIC_ORIENT for the sheet part with the rolling direction.
//               Part IDs are required (an all-zero pair is dropped silently by
//               the starter).
//  lsdyna       isotropic (rd|td|mean): *CONTACT_ONE_WAY_SURFACE_TO_SURFACE with
//               FS = 2, FD = the *DEFINE_TABLE of mu(p, v) (values: contact
//               pressure; curves: mu against relative sliding speed: the
//               manual's FS/FD text, cited in export.cpp); `ortho`:
//               *CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE_ORTHO_FRICTION with
//               LC1 (RD) and LC2 (TD) tables (values: sliding speed; curves: mu
//               against pressure, one per speed) on the four cards after card 3,
//               OACS_S = 1 (the sliding sheet node's directions), LCFS/LCPS blank.
//  abaqus       standard: *FRICTION, ANISOTROPIC, DEPENDENCIES = 0 with data
//               lines mu_1 (RD), mu_2 (TD), slip rate, contact pressure;
//               explicit: *FRICTION isotropic (mu, slip rate, pressure) for one
//               direction (anisotropic friction in Abaqus/Explicit needs a user
//               subroutine, which is not written).
//
// Every export's header says: the model file and the data it came from, the
// p and v range it holds, what happens outside it, the stated error against
// the law (tables: max |mu - law| on a grid 4x finer than the table and on the
// flat extension; polynomial: max relative error inside the domain and max
// |error| on an extended box), and when TD was copied from RD.
#include <array>
#include <string>
#include <vector>

#include "analysis/friction_surface.hpp"

namespace drawbend::loop {

struct ExportModel {
  analysis::FrictionSurface rd, td;
  std::string source;          ///< the toml file
  std::string data, lubricant; ///< [model] of the toml (empty when absent)
  bool td_copied = false;      ///< TD nodes are RD's: the data had no TD rows
  bool rd_copied = false;      ///< RD nodes are TD's: the data had no RD rows
};

/// Read friction_model.toml ([friction] law = "surface", nodes, domain; the
/// optional [model] table) and its nodes CSV (relative to the toml's
/// directory).  Throws InputError.
ExportModel read_friction_model(const std::string& toml_path);

struct ExportOptions {
  std::string direction = "rd";       ///< rd, td, mean or ortho
  int sheet_part = 0, tool_part = 0;  ///< part IDs (required by openradioss; lsdyna: SSID/MSID)
  bool parts_placeholder = false;     ///< the part IDs are `drawbend loop`'s defaults, not the user's: said in the header
  int friction_id = 1;                ///< /FRICTION and /FRIC_ORIENT ID (bands: ID, ID+1, ...)
  std::array<double, 3> rd_vector{1, 0, 0};  ///< rolling direction in the deck's axes
  double max_rel_error = 0.05;        ///< OpenRadioss fit bound per band
  double band_v_min = 0, band_v_max = 0;  ///< speed band of the fit (0, 0: the data's range)
  std::string abaqus_product = "standard";  ///< standard or explicit
  int contact_id = 1;                 ///< LS-DYNA contact / table IDs base
  /// Throws std::invalid_argument naming the option ("--parts", ...).
  void validate(const std::string& format) const;
};

/// The list-valued options as typed: --parts SHEET,TOOL (empty: unchanged),
/// --rd-vector X,Y,Z, --speed-band MIN,MAX (empty: the data's range).  Throws
/// std::invalid_argument naming the option.
void set_list_options(ExportOptions& o, const std::string& parts, const std::string& rd_vector,
                      const std::string& speed_band);

struct ExportResult {
  std::string text;            ///< the deck fragment
  std::string format;
  double max_error = 0;        ///< tables: max |mu - law|; polynomial: max relative error inside
  double max_error_outside = 0;  ///< max |mu - law| on the extended box (p 0..2 p_max, v 0..5 v_max)
  int bands = 1;               ///< OpenRadioss speed bands
};

ExportResult export_lsdyna(const ExportModel& m, const ExportOptions& o);
ExportResult export_openradioss(const ExportModel& m, const ExportOptions& o);
ExportResult export_abaqus(const ExportModel& m, const ExportOptions& o);
ExportResult export_to(const std::string& format, const ExportModel& m, const ExportOptions& o);

/// The solver's law: clamped to the domain, floored at 0 (surface_law.hpp).
double law_mu(const analysis::FrictionSurface& s, double p, double v);

/// One direction's law for the isotropic exports: rd, td or the mean of both.
analysis::FrictionSurface direction_surface(const ExportModel& m, const std::string& direction);

/// Generalized viscous law coefficients {Fric, C1..C5} fitted to f over
/// p in [p0, p1], v in [v0, v1] minimising the largest relative error.
std::vector<double> radioss_fit(const analysis::FrictionSurface& s, double v0, double v1);
double radioss_mu(const std::vector<double>& c, double p, double v);

/// Default output name next to the model: friction_model[_X].toml ->
/// friction_<format>[_X].k|.rad|.inp.
std::string export_path(const std::string& toml_path, const std::string& format);

/// The exports `drawbend loop` writes (formats "lsdyna,openradioss,abaqus" or
/// "none") for every friction_model*.toml listed; returns the loop.md section.
std::string write_exports(const std::vector<std::string>& tomls, const std::string& formats, const ExportOptions& o);

}  // namespace drawbend::loop
