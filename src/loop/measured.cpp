// Reading and writing the measured-data format; see measured.hpp.
#include "loop/measured.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/csv.hpp"
#include "core/csv_dialect.hpp"
#include "core/strip_limits.hpp"

namespace drawbend::loop {

const std::vector<std::string> kRequiredColumns = {"test_id",   "pin_diameter_mm", "pin",
                                                   "direction_deg", "speed_mm_s", "lubricant",
                                                   "back_tension_N", "outlet_force_N"};

std::string Problem::str() const {
  std::string s = file;
  if (line > 0) s += ":" + std::to_string(line);
  s += ": ";
  if (!column.empty()) s += "column '" + column + "': ";
  return s + message;
}

int Dataset::extra_index(const std::string& name) const {
  for (size_t i = 0; i < extra_columns.size(); ++i)
    if (extra_columns[i] == name) return static_cast<int>(i);
  return -1;
}

std::optional<std::vector<double>> numeric_extra(const Dataset& d, size_t e) {
  std::vector<double> x(d.rows.size(), std::nan(""));
  for (size_t i = 0; i < d.rows.size(); ++i) {
    const std::string& v = d.rows[i].extra[e];
    if (v.empty()) continue;
    char* end = nullptr;
    x[i] = std::strtod(v.c_str(), &end);  // as std::stod, without a throw per text cell
    if (end != v.c_str() + v.size() || hex_number(v) || !std::isfinite(x[i])) return std::nullopt;
  }
  return x;
}

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// Parse a finite number; false (with a reason) otherwise.
bool parse_number(const std::string& text, double& v, std::string& why) {
  const std::string t = trim(text);
  if (t.empty()) {
    why = "empty value";
    return false;
  }
  try {
    size_t used = 0;
    v = std::stod(t, &used);
    if (used != t.size() || hex_number(t)) {
      why = "'" + t + "' is not a number";
      return false;
    }
  } catch (const std::exception&) {
    why = "'" + t + "' is not a number";
    return false;
  }
  if (!std::isfinite(v)) {
    why = "'" + t + "' is not a finite number (NaN or infinity)";
    return false;
  }
  return true;
}

// A spreadsheet's decimal comma ("12,5") as a decimal point; other text as it is.
std::string decimal_point(const std::string& cell) {
  const auto c = cell.find(',');
  if (c == std::string::npos || cell.find(',', c + 1) != std::string::npos || cell.find('.') != std::string::npos)
    return cell;
  std::string t = cell;
  t[c] = '.';
  double v = 0;
  std::string why;
  return parse_number(t, v, why) ? t : cell;
}


// Numeric extra columns: when every non-empty cell reads as a number and some
// are NaN or infinite, those cells are problems (the row is dropped) instead
// of making the column categorical.
void nonfinite_extras(Dataset& d) {
  for (size_t e = 0; e < d.extra_columns.size(); ++e) {
    bool numeric = true, nonfinite = false;
    for (const auto& s : d.rows) {
      if (!numeric) break;  // a text column: nothing to drop (and no throw per row)
      const std::string t = trim(s.extra[e]);
      if (t.empty()) continue;
      size_t used = 0;
      double v = 0;
      try {
        v = std::stod(t, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != t.size() || used == 0 || hex_number(t)) numeric = false;
      else if (!std::isfinite(v)) nonfinite = true;
    }
    if (!numeric || !nonfinite) continue;
    std::vector<Sample> keep;
    for (auto& s : d.rows) {
      const std::string t = trim(s.extra[e]);
      double v = 0;
      std::string why;
      if (t.empty() || parse_number(t, v, why)) {
        keep.push_back(std::move(s));
        continue;
      }
      d.problems.push_back({d.path, s.line, d.extra_columns[e],
                            why + " in a numeric column (the row is dropped; the column stays numeric)"});
      ++d.rows_dropped;
    }
    d.rows = std::move(keep);
  }
}

// One pass over the records of a measured-data file: the header, then each
// row checked and kept or dropped with its problems (parse_measured below).
struct MeasuredReader {
  Dataset d;
  std::vector<std::string> header;
  int header_line = 0;
  std::map<std::string, int> col;
  std::map<std::string, int> seen;  // row text -> first line
  bool header_ok = false;
  char sep = ',';
  bool decimal_comma = false;

  void problem(int l, const std::string& c, const std::string& m) { d.problems.push_back({d.path, l, c, m}); }

  void comment(const std::string& line, int lineno) {
    if (header.empty()) d.comments.push_back(line.substr(1));
    else problem(lineno, "", "comment line after the header ignored");
  }

  // The cells of the header line, with ';' (and decimal commas) or a tab
  // between them when the header reads that way.
  void split_header(const std::string& line, int lineno) {
    header = split_csv_line(line);
    if (semicolon_header(header)) {  // a spreadsheet export: ';' between cells, decimal commas
      sep = ';';
      decimal_comma = true;
      header = split_csv_line(line, sep);
      d.format_note += std::string(d.format_note.empty() ? "" : "; ") +
                       "read with ';' between cells and ',' as the decimal mark (line " + std::to_string(lineno) + ")";
    } else if (tab_header(header)) {  // a tab-separated export
      sep = '\t';
      header = split_csv_line(line, sep);
      d.format_note += std::string(d.format_note.empty() ? "" : "; ") + "read with a tab between cells (line " +
                       std::to_string(lineno) + ")";
    }
    trim_trailing_empty_header(header);  // an empty formatted column at the right (Excel)
  }

  void read_header(const std::string& line, int lineno) {
    split_header(line, lineno);
    header_line = lineno;
    if (const std::string q = csv_quote_problem(line, sep); !q.empty()) {
      problem(lineno, "", q);  // no row can be read by column names that may be cut wrongly
      header_ok = false;
      return;
    }
    for (auto& h : header) h = trim(h);
    header_ok = true;
    for (size_t i = 0; i < header.size(); ++i) {
      if (header[i].empty() || col.count(header[i])) {  // no row can be read by its column names
        problem(lineno, header[i], header[i].empty() ? "empty column name (column " + std::to_string(i + 1) + ")"
                                                     : "duplicate column name");
        header_ok = false;
      }
      col[header[i]] = static_cast<int>(i);
    }
    for (const auto& r : kRequiredColumns)
      if (!col.count(r)) {
        problem(lineno, r, "required column missing");
        header_ok = false;
      }
    d.has_sliding = col.count("sliding_distance_mm") > 0;
    d.has_time = col.count("time_s") > 0;
    for (const auto& h : header) {
      bool known = h == "sliding_distance_mm" || h == "time_s";
      for (const auto& r : kRequiredColumns) known = known || h == r;
      if (!known) d.extra_columns.push_back(h);
    }
  }

  // The row's cells, one per header column; false (the row dropped, with its
  // problem) when the quoting or the cell count is wrong or the header unusable.
  bool row_cells(const std::string& line, int lineno, std::vector<std::string>& cells) {
    if (const std::string q = csv_quote_problem(line, sep); !q.empty()) {
      problem(lineno, "", q);
      ++d.rows_dropped;
      return false;
    }
    cells = split_csv_line(line, sep);
    drop_trailing_empty(cells, header.size());
    if (decimal_comma)
      for (auto& c : cells) c = decimal_point(c);
    if (cells.size() != header.size()) {
      problem(lineno, "", "has " + std::to_string(cells.size()) + " cells, the header (line " +
                              std::to_string(header_line) + ") has " + std::to_string(header.size()));
      ++d.rows_dropped;
      return false;
    }
    if (!header_ok) {  // required columns missing: no row is usable
      ++d.rows_dropped;
      return false;
    }
    return true;
  }

  // The sample of a row's cells, a problem per unreadable value; `pin` gets
  // the pin column's text.
  Sample parse_sample(const std::vector<std::string>& cells, int lineno, std::string& pin) {
    auto cell = [&](const std::string& c) { return trim(cells[col.at(c)]); };
    auto num = [&](const std::string& c, double& v) {
      std::string why;
      if (!parse_number(cells[col.at(c)], v, why)) problem(lineno, c, why);
    };
    Sample s;
    s.line = lineno;
    s.test_id = cell("test_id");
    if (s.test_id.empty()) problem(lineno, "test_id", "empty value");
    s.lubricant = cell("lubricant");
    num("pin_diameter_mm", s.pin_d_mm);
    num("direction_deg", s.direction_deg);
    num("speed_mm_s", s.speed_mm_s);
    num("back_tension_N", s.back_tension_N);
    num("outlet_force_N", s.outlet_force_N);
    pin = cell("pin");
    if (pin == "rotating") s.rotating = true;
    else if (pin != "fixed") problem(lineno, "pin", "'" + pin + "' is neither 'fixed' nor 'rotating'");
    s.sliding_mm = s.time_s = std::nan("");
    if (d.has_sliding) num("sliding_distance_mm", s.sliding_mm);
    if (d.has_time) num("time_s", s.time_s);
    for (const auto& e : d.extra_columns) s.extra.push_back(cell(e));
    return s;
  }

  // Physical plausibility of a sample's parsed values, a problem for each
  // value a draw-bend test cannot have.
  void check_plausible(const Sample& s, const std::string& pin, int lineno) {
    if (s.pin_d_mm <= 0) problem(lineno, "pin_diameter_mm", "pin diameter must be positive");
    if (s.pin_d_mm > kMaxPinDiameterMM)
      problem(lineno, "pin_diameter_mm", "expected a pin diameter up to " + fmt(kMaxPinDiameterMM) +
                                             " mm (a draw-bend pin; check the units), found " + fmt(s.pin_d_mm) + " mm");
    if (s.speed_mm_s <= 0)
      problem(lineno, "speed_mm_s", "expected a sliding speed > 0 mm/s, found " + fmt(s.speed_mm_s) +
                                        " (a test without sliding measures no friction)");
    if (s.speed_mm_s > kMaxSlidingSpeedMMs)
      problem(lineno, "speed_mm_s", "expected a sliding speed up to " + fmt(kMaxSlidingSpeedMMs) +
                                        " mm/s (a draw-bend test; check the units), found " + fmt(s.speed_mm_s) + " mm/s");
    for (const char* f : {"back_tension_N", "outlet_force_N"}) {
      const double v = std::string(f) == "back_tension_N" ? s.back_tension_N : s.outlet_force_N;
      if (v > kMaxStripForceN)
        problem(lineno, f, "expected a force below " + fmt(kMaxStripForceN) + " N (a strip test; check the units), found " +
                               fmt(v) + " N");
    }
    if (s.direction_deg < 0 || s.direction_deg > 90)
      problem(lineno, "direction_deg", "direction must lie in 0..90 deg (0 = RD, 90 = TD)");
    if (s.back_tension_N < 0) problem(lineno, "back_tension_N", "negative force");
    else if (s.back_tension_N == 0) problem(lineno, "back_tension_N", "zero back tension (Eq. 5.1 undefined)");
    if (s.outlet_force_N < 0) problem(lineno, "outlet_force_N", "negative force");
    else if (s.back_tension_N > 0 && s.outlet_force_N < s.back_tension_N)
      problem(lineno, "outlet_force_N",
              "outlet force " + fmt(s.outlet_force_N) + " N below back tension " + fmt(s.back_tension_N) +
                  " N on a " + pin + " pin: friction and bending can only add to the back tension");
    if (d.has_sliding && s.sliding_mm < 0) problem(lineno, "sliding_distance_mm", "negative sliding distance");
  }

  // A data row: kept when it parses, is plausible and repeats no earlier row.
  void read_row(const std::string& line, int lineno) {
    ++d.rows_read;
    std::vector<std::string> cells;
    if (!row_cells(line, lineno, cells)) return;
    const size_t before = d.problems.size();
    std::string pin;
    Sample s = parse_sample(cells, lineno, pin);
    if (d.problems.size() == before) check_plausible(s, pin, lineno);
    if (d.problems.size() == before) {
      std::string key;
      for (const auto& c : cells) key += trim(c) + "\x1f";
      auto [it, fresh] = seen.emplace(key, lineno);
      if (!fresh) problem(lineno, "", "duplicate of line " + std::to_string(it->second) + " (dropped)");
    }
    if (d.problems.size() != before) ++d.rows_dropped;
    else d.rows.push_back(std::move(s));
  }
};

}  // namespace

namespace {

// Natural order of ids: runs of digits compare as numbers (leading zeros
// aside), other runs as text; equal so far, plain text order decides.
int natural_compare(const std::string& a, const std::string& b) {
  size_t i = 0, j = 0;
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  while (i < a.size() && j < b.size()) {
    if (digit(a[i]) && digit(b[j])) {
      size_t i1 = i, j1 = j;
      while (i1 < a.size() && digit(a[i1])) ++i1;
      while (j1 < b.size() && digit(b[j1])) ++j1;
      size_t i0 = i, j0 = j;  // leading zeros
      while (i0 + 1 < i1 && a[i0] == '0') ++i0;
      while (j0 + 1 < j1 && b[j0] == '0') ++j0;
      if (i1 - i0 != j1 - j0) return i1 - i0 < j1 - j0 ? -1 : 1;
      if (const int c = a.compare(i0, i1 - i0, b, j0, j1 - j0)) return c < 0 ? -1 : 1;
      i = i1, j = j1;
    } else {
      if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]) ? -1 : 1;
      ++i, ++j;
    }
  }
  if (i < a.size() || j < b.size()) return i < a.size() ? 1 : -1;
  const int c = a.compare(b);
  return c < 0 ? -1 : c > 0 ? 1 : 0;
}

// Numbers in a total order: NaN (a column the file lacks) before every number.
int number_compare(double a, double b) {
  const bool na = std::isnan(a), nb = std::isnan(b);
  if (na || nb) return na == nb ? 0 : na ? -1 : 1;
  return a < b ? -1 : a > b ? 1 : 0;
}

}  // namespace

void canonical_row_order(Dataset& d) {
  const auto less = [](const Sample& a, const Sample& b) {
    if (const int c = natural_compare(a.test_id, b.test_id)) return c < 0;
    for (const auto& [x, y] : {std::pair{a.time_s, b.time_s}, std::pair{a.sliding_mm, b.sliding_mm},
                               std::pair{a.back_tension_N, b.back_tension_N}, std::pair{a.pin_d_mm, b.pin_d_mm},
                               std::pair{a.direction_deg, b.direction_deg}, std::pair{a.speed_mm_s, b.speed_mm_s},
                               std::pair{a.outlet_force_N, b.outlet_force_N}})
      if (const int c = number_compare(x, y)) return c < 0;
    if (a.rotating != b.rotating) return !a.rotating;
    if (a.lubricant != b.lubricant) return a.lubricant < b.lubricant;
    return a.extra < b.extra;  // rows equal in every cell are dropped as duplicates
  };
  std::stable_sort(d.rows.begin(), d.rows.end(), less);
}

Dataset read_measured(const std::string& path) { return parse_measured(read_file(path), path); }

Dataset parse_measured(const std::string& text, const std::string& path) {
  // UTF-8 (a byte-order mark dropped), UTF-16 named, Windows-1252 converted,
  // quoted line breaks, trailing empty columns (core/csv_dialect.hpp).
  std::string encoding_note;
  std::istringstream in(csv_text_utf8(text, path, &encoding_note));
  MeasuredReader r;
  r.d.path = path;
  r.d.format_note = encoding_note;
  std::string line;
  int lineno = 0, physical_line = 0;
  while (next_csv_record(in, line, physical_line, lineno)) {  // lineno: the record's first line
    if (trim(line).empty()) continue;
    if (line[0] == '#') r.comment(line, lineno);
    else if (r.header.empty()) r.read_header(line, lineno);
    else r.read_row(line, lineno);
  }
  if (r.header.empty()) r.problem(0, "", "no header row (file empty or only comments)");
  nonfinite_extras(r.d);
  canonical_row_order(r.d);
  return std::move(r.d);
}

void write_measured(const std::string& path, const Dataset& d) {
  std::ostringstream o;
  for (const auto& c : d.comments) o << "#" << c << "\n";
  std::vector<std::string> h = kRequiredColumns;
  if (d.has_sliding) h.push_back("sliding_distance_mm");
  if (d.has_time) h.push_back("time_s");
  for (const auto& e : d.extra_columns) h.push_back(e);
  for (size_t i = 0; i < h.size(); ++i) o << (i ? "," : "") << csv_quote(h[i]);
  o << "\n";
  for (const auto& s : d.rows) {
    std::vector<std::string> c = {s.test_id, fmt(s.pin_d_mm, 8), s.rotating ? "rotating" : "fixed",
                                  fmt(s.direction_deg, 8), fmt(s.speed_mm_s, 8), s.lubricant,
                                  fmt(s.back_tension_N, 8), fmt(s.outlet_force_N, 8)};
    if (d.has_sliding) c.push_back(fmt(s.sliding_mm, 8));
    if (d.has_time) c.push_back(fmt(s.time_s, 8));
    for (const auto& e : s.extra) c.push_back(e);
    for (size_t i = 0; i < c.size(); ++i) o << (i ? "," : "") << csv_quote(c[i]);
    o << "\n";
  }
  write_file_atomic(path, o.str());
}

}  // namespace drawbend::loop
