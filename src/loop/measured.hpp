#pragma once
// Measured draw-bend data in the drawbend sample format (README.md, data/README.md):
// one CSV row per sample.  Required columns
//   test_id, pin_diameter_mm, pin (fixed|rotating), direction_deg (0 = RD, 90 = TD),
//   speed_mm_s, lubricant, back_tension_N, outlet_force_N
// optional sliding_distance_mm, time_s, and any other columns (kept as
// candidate explanations).  Units: mm, N, mm/s, s, deg.
//
// Bad data is reported, never crashed on: every problem (missing required
// column, unparseable number, NaN, ragged row, duplicate row, impossible value)
// is collected in one pass with file, line and column; rows with a problem are
// dropped and counted, the others kept.
#include <optional>
#include <string>
#include <vector>

namespace drawbend::loop {

struct Problem {
  std::string file;
  int line = 0;          ///< 1-based file line (0: whole file)
  std::string column;    ///< column name, or empty
  std::string message;
  std::string str() const;  ///< "file:line: column 'c': message"
};

struct Sample {
  int line = 0;  ///< file line it came from
  std::string test_id;
  double pin_d_mm = 0;
  bool rotating = false;
  double direction_deg = 0;
  double speed_mm_s = 0;
  std::string lubricant;
  double back_tension_N = 0;
  double outlet_force_N = 0;
  double sliding_mm = 0;  ///< NaN when the column is absent
  double time_s = 0;      ///< NaN when the column is absent
  std::vector<std::string> extra;  ///< one cell per Dataset::extra_columns
};

struct Dataset {
  std::string path;
  std::vector<std::string> comments;       ///< '#' lines without the '#'
  std::vector<std::string> extra_columns;  ///< columns beyond the required/optional ones
  bool has_sliding = false, has_time = false;
  std::vector<Sample> rows;                ///< usable rows
  std::vector<Problem> problems;
  int rows_read = 0;     ///< data rows in the file
  int rows_dropped = 0;  ///< rows with at least one problem
  /// How the file was read when it is not plain CSV (e.g. "';' between cells,
  /// decimal commas"); empty otherwise.
  std::string format_note;

  /// Column index of an extra column, -1 if absent.
  int extra_index(const std::string& name) const;
};

extern const std::vector<std::string> kRequiredColumns;

/// Extra column `e` as numbers, NaN where a cell is empty; nullopt when a
/// cell holds anything but one finite number (the column is categorical).
/// The one rule for "numeric column" (the candidates, response_columns).
std::optional<std::vector<double>> numeric_extra(const Dataset& d, size_t e);

/// Read a data file.  Only an unreadable file throws (InputError); everything
/// else becomes a Problem.  The usable rows come in canonical order
/// (canonical_row_order), not the file's.
Dataset read_measured(const std::string& path);
/// The same from text already read (`path` names it in messages).
Dataset parse_measured(const std::string& text, const std::string& path);

/// The rows in an order set by their content alone, so that a result is the
/// same whatever order the file's rows came in (the loop's folds, its
/// permutation draws, its cells and levels and every sum follow the row
/// order): by test_id in natural order ("T2" before "T10": digit runs compared
/// as numbers), then within a test by time_s, sliding_distance_mm and
/// back_tension_N, then by the other cells.  A file already in that order
/// (a lab's tests in id order, each in time order) keeps its order.
/// Sample::line still names each row's file line; where the file's order is
/// itself information, the line is read: the run position within a test for
/// the replicate noise when the file has neither time_s nor
/// sliding_distance_mm (noise.hpp), and the lines a message names.
void canonical_row_order(Dataset& d);

/// Write rows in the same format (comments first, then header, then rows).
void write_measured(const std::string& path, const Dataset& d);

}  // namespace drawbend::loop
