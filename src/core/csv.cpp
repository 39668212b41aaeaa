#include "core/csv.hpp"

#include "core/csv_dialect.hpp"
#include "core/file_gate.hpp"
#include "core/input_problems.hpp"
#include "core/provenance.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace drawbend {

namespace {
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}
}  // namespace

std::vector<std::string> split_csv_line(const std::string& line) { return split_csv_line(line, ','); }

std::vector<std::string> split_csv_line(const std::string& line, char sep) {
  std::vector<std::string> cells;
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cur += '"';
        ++i;
      } else if (ch == '"') {
        quoted = false;
      } else {
        cur += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == sep) {
      cells.push_back(trim(cur));
      cur.clear();
    } else {
      cur += ch;
    }
  }
  cells.push_back(trim(cur));
  return cells;
}

std::string csv_quote_problem(const std::string& line, char sep) {
  enum { start, unquoted, quoted, closed } state = start;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (state == quoted) {
      if (ch != '"') continue;
      if (i + 1 < line.size() && line[i + 1] == '"') ++i;  // a doubled quote
      else state = closed;
    } else if (ch == sep) {
      state = start;
    } else if (ch == '"') {
      if (state != start)
        return "cell " + std::to_string(1 + std::count(line.begin(), line.begin() + static_cast<long>(i), sep)) +
               ": a quote inside " + std::string(state == closed ? "a cell after its closing quote" : "an unquoted cell") +
               ": quote the whole cell and double each quote in it (\"12\"\" pin\")";
      state = quoted;
    } else if (state == closed) {
      if (ch != ' ' && ch != '\t' && ch != '\r')
        return "cell " + std::to_string(1 + std::count(line.begin(), line.begin() + static_cast<long>(i), sep)) +
               ": text after the cell's closing quote: quote the whole cell and double each quote in it";
    } else if (state == start && ch != ' ' && ch != '\t') {
      state = unquoted;
    }
  }
  if (state == quoted) return "a quote opened and never closed";
  return "";
}

CsvTable read_csv(const std::string& path) {
  return parse_csv(read_file(path), path);
}

std::string strip_bom(const std::string& text) {
  return text.rfind("\xEF\xBB\xBF", 0) == 0 ? text.substr(3) : text;
}

bool semicolon_header(const std::vector<std::string>& cells) {
  return cells.size() == 1 && cells[0].find(';') != std::string::npos;
}

std::string semicolon_message() {
  return "expected ',' between cells, found ';' (a spreadsheet export with decimal commas?): "
         "save it as CSV with ',' between cells and '.' as the decimal mark";
}

CsvTable parse_csv(const std::string& text, const std::string& path) {
  // Every ragged row and every bad header cell is reported, in one message.
  InputProblems problems(path);
  CsvTable t;
  t.path = path;
  // UTF-8 (a byte-order mark dropped), UTF-16 named, Windows-1252 converted;
  // quoted line breaks and trailing empty columns (core/csv_dialect.hpp).
  std::istringstream in(csv_text_utf8(text, path));
  std::string line;
  int lineno = 0, first = 0;
  while (next_csv_record(in, line, lineno, first)) {
    const std::string s = trim(line);
    if (s.empty()) continue;
    if (s[0] == '#') {
      t.comments.push_back(trim(s.substr(1)));
      continue;
    }
    if (const std::string q = csv_quote_problem(s); !q.empty()) {
      problems.add(path + ":" + std::to_string(first) + ": " + q);
      continue;
    }
    auto cells = split_csv_line(s);
    if (t.header.empty()) {
      if (semicolon_header(cells))  // one message, not one per row
        throw InputError(path + ":" + std::to_string(first) + ": header: " + semicolon_message());
      if (tab_header(cells))
        throw InputError(path + ":" + std::to_string(first) +
                         ": header: expected ',' between cells, found a tab (a tab-separated file): save it as CSV "
                         "with ',' between cells");
      trim_trailing_empty_header(cells);
      t.header = std::move(cells);
      for (std::size_t i = 0; i < t.header.size(); ++i) {
        const std::string col = "header cell " + std::to_string(i + 1);
        if (t.header[i].empty())
          problems.add(path + ":" + std::to_string(first) + ": " + col + ": expected a column name, found an empty cell");
        for (std::size_t j = 0; j < i; ++j)
          if (!t.header[i].empty() && t.header[j] == t.header[i])
            problems.add(path + ":" + std::to_string(first) + ": " + col + ": expected unique column names, found '" +
                         t.header[i] + "' twice");
      }
      continue;
    }
    drop_trailing_empty(cells, t.header.size());
    if (cells.size() != t.header.size()) {
      problems.add(path + ":" + std::to_string(first) + ": expected " + std::to_string(t.header.size()) +
                   " cells (as in the header), found " + std::to_string(cells.size()));
      continue;
    }
    t.rows.push_back({first, std::move(cells)});
  }
  if (t.header.empty()) problems.add(path + ": expected a header row, found none");
  problems.throw_if_any();
  return t;
}

bool CsvTable::has_column(const std::string& name) const {
  for (const auto& h : header)
    if (h == name) return true;
  return false;
}

int CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  throw InputError(path + ": missing required column '" + name + "'");
}

const std::string& CsvTable::text(const CsvRow& r, const std::string& name) const {
  return r.cells[static_cast<std::size_t>(column(name))];
}

std::string CsvTable::where(const CsvRow& r, const std::string& name) const {
  return path + ":" + std::to_string(r.line) + ": column '" + name + "'";
}

bool hex_number(const std::string& text) { return text.find_first_of("xX") != std::string::npos; }

double CsvTable::number(const CsvRow& r, const std::string& name) const {
  const std::string& s = text(r, name);
  // The cell shown clipped (a 100,000-character cell was echoed whole, 2026-12-04).
  const std::string found = "found '" + clip_for_message(s) + "'";
  if (hex_number(s)) throw InputError(where(r, name) + ": expected a number, " + found);
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    throw InputError(where(r, name) + ": expected a number, " + found);
  }
  if (used != s.size()) throw InputError(where(r, name) + ": expected a number, " + found);
  if (!std::isfinite(v)) throw InputError(where(r, name) + ": expected a finite number, " + found);
  return v;
}

std::string csv_quote(const std::string& cell) {
  if (cell.find_first_of(",\"\n") == std::string::npos) return cell;
  std::string out = "\"";
  for (char c : cell) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

CsvWriter::CsvWriter(std::vector<std::string> header) : header_(std::move(header)) {
  // The readers (parse_csv) refuse a repeated column name, so never write one.
  for (std::size_t i = 0; i < header_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (header_[i] == header_[j]) throw std::logic_error("CsvWriter: column '" + header_[i] + "' named twice");
}
void CsvWriter::comment(const std::string& line) { comments_.push_back(line); }
void CsvWriter::row(const std::vector<std::string>& cells) {
  if (cells.size() != header_.size())
    throw std::logic_error("CsvWriter: row has " + std::to_string(cells.size()) + " cells, header has " +
                           std::to_string(header_.size()));
  rows_.push_back(cells);
}

void CsvWriter::save(const std::string& path) const {
  std::ostringstream os;
  for (const auto& c : comments_) os << "# " << c << "\n";
  for (std::size_t i = 0; i < header_.size(); ++i) os << (i ? "," : "") << csv_quote(header_[i]);
  os << "\n";
  for (const auto& r : rows_) {
    for (std::size_t i = 0; i < r.size(); ++i) os << (i ? "," : "") << csv_quote(r[i]);
    os << "\n";
  }
  write_file_atomic(path, os.str());
}

std::string fmt(double v, int significant) {
  if (std::isnan(v)) return "nan";
  char buf[64];
  // std::to_chars in the general format with a precision is printf's "%.*g"
  // in the C locale, by the standard ([charconv.to.chars]; 87 million values
  // and precisions 0 to 17 compared, ties and zeros included, 2026-12-06),
  // at about a third of snprintf's time (a 50,000-row loop formats millions).
  if (significant >= 0) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, significant);
    if (r.ec == std::errc()) return std::string(buf, r.ptr);
  }
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return buf;
}

std::string fmt_shortest(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string fmt_fixed(double v, int decimals) {
  if (std::isnan(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s == "-0" || s.rfind("-0.", 0) == 0) {
    // Avoid printing "-0.000" for values that round to zero.
    bool all_zero = true;
    for (char c : s.substr(1))
      if (c != '0' && c != '.') all_zero = false;
    if (all_zero) s = s.substr(1);
  }
  return s;
}

void write_file_atomic(const std::string& path, const std::string& text) { write_output(path, text); }

void ensure_writable_dir(const std::string& dir, const std::string& what) {
  namespace fs = std::filesystem;
  const std::string name = what + " '" + dir + "'";
  if (dir.empty()) throw InputError(what + ": expected a folder name, found an empty one");
  std::error_code ec;
  // The nearest existing ancestor that is not a folder is the usual cause.
  for (fs::path p = fs::path(dir); !p.empty(); p = p.parent_path()) {
    if (fs::exists(p, ec) && !fs::is_directory(p, ec))
      throw InputError(name + ": cannot be a folder, because '" + p.string() + "' is a file");
    if (p == p.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  if (ec) throw InputError(name + ": cannot create the folder: " + ec.message());
  const fs::path probe = fs::path(dir) / (".drawbend-write-test." + std::to_string(::getpid()));
  {
    std::ofstream out(probe, std::ios::binary | std::ios::trunc);
    out << "test\n";
    out.flush();
    if (!out) {
      fs::remove(probe, ec);
      throw InputError(name + ": cannot write in the folder (permission denied or disk full?)");
    }
  }
  fs::remove(probe, ec);
}

std::string read_file(const std::string& path) { return read_input(path); }

}  // namespace drawbend
