#pragma once
// The identified friction model handed back to the user, always written:
//  * mu0 and a1 +- SE per lubricant x speed x direction (the model's cells;
//    a1 = 0 "not identified" when the loop added no pressure effect), plus
//    the multiplicative factors of every added effect (effects table);
//  * the bending line per pin (or the assumed bending force, labelled);
//  * the Chapter 6 nine-node surface mu(p, v) (analysis::FrictionSurface,
//    Eqs. 6.1-6.3) fitted by least squares to the model's mu at every fixed
//    row, per direction (RD, TD) and lubricant, on the data's domain: p over
//    the rows' force-weighted map pressures, v over their speeds.  With fewer
//    than 3 speeds the surface is constant in v (speed dependence not
//    identified), said in the output;
//  * friction_model.toml: a [friction] table in the deck format of
//    data/cases/README.md (law = "surface", nodes CSV, domain), usable as a
//    [[contact]] friction of a `drawbend run` deck; its [model] table names
//    the data file, the lubricant and a direction copied for lack of rows.
// Units: MPa, mm/s, N.
#include <string>
#include <vector>

#include "analysis/friction_surface.hpp"
#include "loop/loop.hpp"

namespace drawbend::loop {

struct FrictionCellRow {
  std::string lubricant, speed, direction;
  double mu0 = 0, mu0_se = 0, a1 = 0, a1_se = 0;
  bool a1_identified = false;
};

struct FittedSurface {
  std::string lubricant;
  analysis::FrictionSurface rd, td;  ///< same domain
  double rms_rd = 0, rms_td = 0;      ///< fit error of the nodes against the model's mu
  int rows = 0, speeds = 0;
  bool rd_copied = false, td_copied = false;  ///< a direction without rows took the other's nodes
  std::string note;
};

struct FrictionModel {
  std::vector<FrictionCellRow> cells;
  std::vector<Param> bending;
  std::vector<FittedSurface> surfaces;  ///< one per lubricant
};

/// File-name tag of a lubricant (non-alphanumerics as '_').
std::string lubricant_tag(const std::string& lubricant);

FrictionModel identify_friction(const Design& d, const LoopResult& r);

/// Writes tables/friction_model.csv, tables/bending_lines.csv,
/// friction_surface_nodes[_<lubricant>].csv, tables/surface_<lub>_<dir>.dat
/// (grids for the plots) and friction_model.toml; returns the loop.md section.
std::string write_friction_outputs(const Design& d, const LoopResult& r, const FrictionModel& m,
                                   const std::string& out);

}  // namespace drawbend::loop
