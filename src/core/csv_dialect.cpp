#include "core/csv_dialect.hpp"

#include "core/csv.hpp"
#include "core/file_gate.hpp"

namespace drawbend {

namespace csv_dialect_detail {
// Windows-1252's 0x80..0x9F (the rest of the high half is Latin-1 = U+00A0..U+00FF).
const char16_t kCp1252High[32] = {0x20AC, 0xFFFD, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021,
                                  0x02C6, 0x2030, 0x0160, 0x2039, 0x0152, 0xFFFD, 0x017D, 0xFFFD,
                                  0xFFFD, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014,
                                  0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0xFFFD, 0x017E, 0x0178};

void put_utf8(std::string& out, unsigned cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}
}  // namespace csv_dialect_detail

std::string csv_text_utf8(const std::string& text, const std::string& path, std::string* note) {
  using namespace csv_dialect_detail;
  auto starts = [&](const char* p, std::size_t n) { return text.size() >= n && text.compare(0, n, p, n) == 0; };
  const char* how = ": save it as 'CSV UTF-8 (comma delimited)' (Excel) or re-encode it (iconv -f UTF-16 -t UTF-8)";
  if (starts("\xFF\xFE\x00\x00", 4) || starts("\x00\x00\xFE\xFF", 4))
    throw InputError(path + ": the file is UTF-32 text; expected UTF-8" + how);
  if (starts("\xFF\xFE", 2) || starts("\xFE\xFF", 2))
    throw InputError(path + ": the file is UTF-16 text (it starts with a UTF-16 byte-order mark); expected UTF-8" + how);
  // UTF-16 without a mark: NUL bytes between ASCII characters, all on the
  // odd (LE) or all on the even (BE) bytes; NUL bytes elsewhere: a binary file
  // (a program, a spreadsheet's .xlsx), which is not called UTF-16.
  std::size_t nul = 0, nul_odd = 0;
  const std::size_t probe = std::min<std::size_t>(text.size(), 4096);
  for (std::size_t i = 0; i < probe; ++i)
    if (text[i] == '\0') ++nul, nul_odd += i % 2;
  const std::size_t one_side = std::max(nul_odd, nul - nul_odd), other = nul - one_side;
  if (probe >= 4 && one_side * 4 >= probe && other * 20 <= one_side)
    throw InputError(path + ": the file holds NUL bytes between its characters (UTF-16 text?); expected UTF-8" + how);
  if (nul > 0)
    throw InputError(path + ": the file holds NUL bytes (a binary file, e.g. a program or an .xlsx workbook?): "
                            "expected CSV text (UTF-8)");
  std::string t = text.rfind("\xEF\xBB\xBF", 0) == 0 ? text.substr(3) : text;
  if (valid_utf8(t) == t) return t;
  std::string out;
  out.reserve(t.size() + t.size() / 8);
  for (unsigned char c : t) {
    if (c < 0x80) out += static_cast<char>(c);
    else if (c < 0xA0) put_utf8(out, kCp1252High[c - 0x80]);
    else put_utf8(out, c);
  }
  if (note) *note = "not UTF-8: read as Windows-1252 (converted to UTF-8)";
  return out;
}

bool next_csv_record(std::istream& in, std::string& record, int& lineno, int& first) {
  std::string line;
  if (!std::getline(in, line)) return false;
  ++lineno;
  first = lineno;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  record = line;
  // An odd count of '"' leaves a quote open (a doubled "" inside a quote counts twice).
  auto open_quote = [](const std::string& s) {
    bool q = false;
    for (char c : s) q = c == '"' ? !q : q;
    return q;
  };
  if (!record.empty() && record.find_first_not_of(" \t") != std::string::npos &&
      record[record.find_first_not_of(" \t")] == '#')
    return true;  // a comment line: quotes in it mean nothing
  bool q = open_quote(record);
  while (q && std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    record += "\n" + line;
    q = open_quote(record);
  }
  return true;
}

bool tab_header(const std::vector<std::string>& cells) {
  return cells.size() == 1 && cells[0].find('\t') != std::string::npos;
}

void drop_trailing_empty(std::vector<std::string>& cells, std::size_t keep) {
  while (cells.size() > keep && cells.back().empty()) cells.pop_back();
}

void trim_trailing_empty_header(std::vector<std::string>& header) {
  while (header.size() > 1 && header.back().empty()) header.pop_back();
}

}  // namespace drawbend
