#pragma once
// What a figure of many rows draws.  A scatter of every row hides its own
// message above a few thousand rows: the lab-style file (50,040 rows) drew
// 10 MB of SVG per residual figure, 0.5 s of gnuplot each, 20 of them, and a
// browser opening loop.md showed a blot.  So a residual figure of a large
// data set draws bins (each bin's mean and the spread of its rows), and a
// surface figure draws each distinct point once at the figure's resolution.
// Both keep every row in the numbers they draw; tables/residuals.csv keeps
// every row as it was.
#include <cstddef>
#include <vector>

namespace drawbend::loop {

/// Rows above which a residual figure draws bins, not every row (5,000 rows
/// draw 10,000 markers, about 1 MB of SVG).
constexpr std::size_t kFigurePointRows = 5000;
/// Bins of a numeric column with more distinct values than this.
constexpr std::size_t kFigureBins = 40;
/// A categorical column (levels as index) gets one bin per level up to this
/// many levels (a coil or a lot is read level by level), else kFigureBins.
constexpr std::size_t kFigureLevels = 200;

struct ResidualBin {
  double x = 0;            ///< mean of the column over the bin's rows
  std::size_t rows = 0;    ///< rows in the bin
  double before_mean = 0;  ///< mean held-out residual of the base model (N)
  double before_sd = 0;    ///< sample standard deviation of those residuals (0 for one row)
  double after_mean = 0;   ///< the same for the final model
  double after_sd = 0;
};

/// Bins of the column x: one per distinct value when it has at most
/// max_values (kFigureBins; kFigureLevels for a categorical column), else
/// kFigureBins bins of equal row count (up to one row) in the order of x,
/// ties by row index.  Rows whose x or residuals are not finite are left out.
/// Sums run in row order within a bin.
std::vector<ResidualBin> residual_bins(const std::vector<double>& x, const std::vector<double>& before,
                                       const std::vector<double>& after, std::size_t max_values = kFigureBins);

struct PlotPoint {
  double u = 0, v = 0;   ///< the first row's values in its pixel cell
  std::size_t rows = 0;  ///< rows that fall in the same cell
};

/// The grid of distinct_points: a surface figure's plot area is at most
/// about 600 px wide and its markers (gnuplot pt 7 ps 0.5) about 4 px across,
/// so cells of 1/250 of the range (2.4 px or less) lie under one marker.  Above
/// kFigurePointRows rows the markers are 1.5 px (ps 0.2), so the surface
/// shows between them, and the points show the grid's cells where rows lie.
constexpr int kFigureCells = 250;

/// The distinct points of (u, v) at a resolution of 1/cells of each range:
/// rows whose values fall in the same cell of a cells x cells grid over the
/// points' bounding box are drawn once, at the first such row's values, with
/// their count.  In first-seen order; non-finite pairs are left out.
std::vector<PlotPoint> distinct_points(const std::vector<double>& u, const std::vector<double>& v, int cells = kFigureCells);

}  // namespace drawbend::loop
