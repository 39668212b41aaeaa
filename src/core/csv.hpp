#pragma once
// CSV reading and writing shared by every part of drawbend.
//
// Files may start with comment lines beginning with '#' (provenance, units,
// configuration echo).  Cells are separated by commas; a cell may be quoted
// with double quotes (doubled quotes inside).  Every cell remembers its file,
// line and column so that errors can name them.
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace drawbend {

/// An error in an input file, with the location it refers to.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CsvRow {
  int line = 0;                     ///< 1-based line number in the file
  std::vector<std::string> cells;
};

struct CsvTable {
  std::string path;
  std::vector<std::string> comments;  ///< comment lines without the leading '#'
  std::vector<std::string> header;
  std::vector<CsvRow> rows;

  /// Index of a column; throws InputError naming the file if it is missing.
  int column(const std::string& name) const;
  bool has_column(const std::string& name) const;
  /// Cell text of row r, column name.
  const std::string& text(const CsvRow& r, const std::string& name) const;
  /// Cell parsed as a finite number; throws InputError naming file:line:column.
  double number(const CsvRow& r, const std::string& name) const;
  /// "file:line: column 'name'" for messages.
  std::string where(const CsvRow& r, const std::string& name) const;
};

/// Split one CSV line into cells (handles quotes).
std::vector<std::string> split_csv_line(const std::string& line);
/// The same with another separator (';' in spreadsheet exports with decimal commas).
std::vector<std::string> split_csv_line(const std::string& line, char sep);
/// What is malformed about the quotes of one CSV record, or "" when nothing:
/// a '"' may open a cell (after leading blanks) and close it, and a quote
/// inside a quoted cell is doubled (""); a quote inside an unquoted cell, text
/// after a closing quote, or a quote left open is refused, not guessed at (a
/// stray quote used to drop silently and shift the cells).
std::string csv_quote_problem(const std::string& line, char sep = ',');
/// The text without a leading UTF-8 byte-order mark.
std::string strip_bom(const std::string& text);
/// Whether a header line split at ',' is one cell holding ';' (a ';'-separated file).
bool semicolon_header(const std::vector<std::string>& cells);
/// The message for a ';'-separated file where ',' is expected.
std::string semicolon_message();
/// Read a CSV file; throws InputError if it cannot be read or rows are ragged.
CsvTable read_csv(const std::string& path);
/// The same from text already read (`path` names it in messages); every
/// ragged row and bad header cell is reported in one InputError.
CsvTable parse_csv(const std::string& text, const std::string& path);
/// Quote a cell if it contains a comma, quote or newline.
std::string csv_quote(const std::string& cell);

/// Writes a CSV file atomically (temporary file, then rename) with a comment
/// header that echoes provenance and configuration.
class CsvWriter {
 public:
  explicit CsvWriter(std::vector<std::string> header);
  void comment(const std::string& line);
  void row(const std::vector<std::string>& cells);
  void save(const std::string& path) const;
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }

 private:
  std::vector<std::string> comments_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

/// Whether `text` is written in hexadecimal (0x10, 0x1p3): std::stod and
/// std::strtod read it (0x10 as 16), but no data file or option means it, so
/// every reader of a decimal number refuses it as "not a number".
bool hex_number(const std::string& text);

/// Format a number with a fixed count of significant digits (no trailing noise).
std::string fmt(double v, int significant = 6);
/// The shortest text that reads back as the same double (for messages: 0.1, not 0.10000000000000001).
std::string fmt_shortest(double v);
/// Format with a fixed count of decimals.
std::string fmt_fixed(double v, int decimals);

/// Create the folder `dir` (and its parents) and test-write a file in it, so
/// that a command fails before any work, not after it.  Throws InputError
/// "<what> 'dir': ..." naming the reason (a file in the way, permission denied).
void ensure_writable_dir(const std::string& dir, const std::string& what);

/// Write text to a file atomically: core/file_gate.hpp's write_output (only a
/// regular file is replaced; nothing left behind on failure).
void write_file_atomic(const std::string& path, const std::string& text);
/// Read a whole file: core/file_gate.hpp's read_input (only a regular file,
/// at most kMaxInputBytes, the message naming the path and its option).
std::string read_file(const std::string& path);

}  // namespace drawbend
