#pragma once
// Helpers shared by the friction-model writers (export.cpp, export_radioss.cpp);
// not part of the module's contract (export.hpp).
#include <string>
#include <vector>

#include "analysis/friction_surface.hpp"
#include "loop/export.hpp"

namespace drawbend::loop::detail {

std::string num(double v, int prec);
/// Right-aligned in `width` characters (one blank at least), the most digits
/// that fit, at most max_digits significant; throws when nothing fits.
std::string field(double v, int width, int max_digits = 15);
std::string ifield(long v, int width);
/// The value a reader gets back from field(v, width, max_digits).
double as_printed(double v, int width, int max_digits);

/// mu of the law (clamped) on an n x n grid over the domain, every number as
/// printed; max_error: max |bilinear - law| on a grid 4x finer.
struct Table {
  std::vector<double> ps, vs;
  std::vector<std::vector<double>> mu;  ///< mu[i][j] at ps[i], vs[j]
  double max_error = 0;
};
Table make_table_n(const analysis::FrictionSurface& s, int width, int n);
/// The coarsest grid (11, 21, ... 201 points) within tol.
Table make_table(const analysis::FrictionSurface& s, int width, double tol);
double bilinear(const std::vector<double>& xs, const std::vector<double>& ys, const std::vector<std::vector<double>>& f,
                double x, double y);

std::string range_text(const analysis::FrictionSurface& s);
/// The header lines common to every export (source, units, range, the law, TD copied), each starting with c.
std::string provenance(const ExportModel& m, const std::string& c, const std::string& direction);

}  // namespace drawbend::loop::detail
