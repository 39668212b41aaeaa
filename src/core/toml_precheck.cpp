#include "core/toml_precheck.hpp"

#include <algorithm>
#include <cstdio>
#include <string_view>

#include "core/csv.hpp"

namespace drawbend {

namespace {
bool key_start(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         c == '"' || c == '\'';
}
}  // namespace

void precheck_table_headers(const std::string& text, const std::string& path) {
  // A small lexer: strings (basic, literal, multi-line), comments, and the
  // nesting depth of array and inline-table values, so that only a '[' that
  // starts a line outside any value is taken for a table header.
  const std::size_t n = text.size();
  std::string open;  // brackets of the values being read, innermost last
  // "path:line:column: TOML syntax error: " of the byte at k, counted only
  // when there is an error (multi-line strings and escapes make keeping a
  // running count error-prone).
  auto at = [&](std::size_t k) {
    const std::size_t bol = k == 0 ? 0 : text.rfind('\n', k - 1) + 1;  // npos + 1 = 0
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(k), '\n');
    return path + ":" + std::to_string(line) + ":" + std::to_string(k - bol + 1) + ": TOML syntax error: ";
  };
  auto byte = [&](std::size_t k) {
    char b[3];
    std::snprintf(b, sizeof b, "%02x", static_cast<unsigned char>(text[k]));
    return std::string(b);
  };
  // TOML allows non-ASCII text only in strings and comments; toml++ 3.3.0
  // classifies other non-ASCII characters with a table that reaches
  // __builtin_unreachable for many of them (undefined behaviour).
  auto non_ascii = [&](std::size_t k) {
    throw InputError(at(k) + "expected ASCII outside strings and comments, found the byte 0x" + byte(k));
  };
  bool line_start = true;
  // Whether the text being read is a value (after '=', or an array's
  // element), not a key: a '.' there belongs to a number, not a dotted key.
  bool in_value = false;
  for (std::size_t i = 0; i < n; ++i) {
    const char c = text[i];
    if (c == '\n') {
      line_start = true;
      if (open.empty()) in_value = false;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') continue;
    if (static_cast<unsigned char>(c) >= 0x80) non_ascii(i);
    const bool at_start = line_start;
    line_start = false;
    if (c == '#') {
      while (i + 1 < n && text[i + 1] != '\n') ++i;
      continue;
    }
    // In a value, a token that is not a string, an array or an inline table
    // (a number, a date, true, inf ...) is read by toml++ 3.3.0 up to the
    // next terminator, each character tested against its whitespace table:
    // undefined behaviour for many non-ASCII code points, quotes and '='
    // included (`x = 0"abc`, `x = 5="abc`: the fuzzer's fourth and seventh
    // findings).  So the whole token is bare text here, where non-ASCII is
    // refused.
    auto terminator = [&](std::size_t k) {
      return std::string_view(" \t\r\n\v\f]},#").find(text[k]) != std::string_view::npos;
    };
    if (in_value && !terminator(i) && std::string_view("\"'[{]},=").find(c) == std::string_view::npos) {
      std::size_t j = i;
      for (; j < n && !terminator(j); ++j)
        if (static_cast<unsigned char>(text[j]) >= 0x80) non_ascii(j);
      // A date's shape (10 characters, '-' 5th and 8th), a space, one digit
      // and a terminator: toml++ takes it for a date-time written with a
      // space, reads the digit and asserts that the next character is not a
      // terminator (with NDEBUG an assumption, so undefined behaviour; the
      // sixth finding, `x = 1979-05-27 1`).  Never valid TOML: a date-time's
      // time has two digits and a colon.
      if (c >= '0' && c <= '9' && j - i == 10 && text[i + 4] == '-' && text[i + 7] == '-' && j + 2 < n &&
          text[j] == ' ' && text[j + 1] >= '0' && text[j + 1] <= '9' && terminator(j + 2))
        throw InputError(at(i) + "expected a date, or a date-time such as 1979-05-27 07:32:00, found '" +
                         text.substr(i, j + 2 - i) + "'");
      i = j - 1;
      continue;
    }
    // A quote starts a string only where TOML lets one begin: at the start of
    // a line, after a space, '=', '[', '{' or ',', or after the '.' of a
    // dotted key.  Glued to a bare value (`x = 0"abc`, `x = 1."abc"`), toml++
    // 3.3.0 reads it as part of that value and tests each following
    // character against its whitespace table until a terminator, which is
    // undefined behaviour for many non-ASCII code points (the fuzzer's fourth
    // finding, tests/fuzz/README.md): so the text after such a quote is lexed
    // as bare text, where non-ASCII is refused.
    const char before = i == 0 ? '\n' : text[i - 1];
    const bool string_may_start = std::string_view(" \t\r\n=[{,").find(before) != std::string_view::npos ||
                                  (before == '.' && !in_value);
    if ((c == '"' || c == '\'') && string_may_start) {
      const bool multi = i + 2 < n && text[i + 1] == c && text[i + 2] == c;
      const std::string close = multi ? std::string(3, c) : std::string(1, c);
      std::size_t j = i + (multi ? 3 : 1);
      while (j < n) {
        if (c == '"' && multi && text[j] == '\\') {
          // A line-ending backslash: toml++ 3.3.0 tests each following
          // character with a whitespace table that is undefined behaviour
          // for many non-ASCII code points, so the run must end in ASCII.
          std::size_t k = j + 1;
          while (k < n && (text[k] == ' ' || text[k] == '\t' || text[k] == '\r' || text[k] == '\n')) ++k;
          if (k > j + 1 && k < n && static_cast<unsigned char>(text[k]) >= 0x80) non_ascii(k);
        }
        if (c == '"' && text[j] == '\\') {
          // An escape is ASCII ('\\n', '\\u00B5', or a line-ending backslash
          // before whitespace).  toml++ 3.3.0 tests the character after a
          // backslash in a multi-line string against its whitespace table
          // (undefined behaviour for e.g. U+02CF, the fuzzer's fifth finding).
          if (j + 1 < n && static_cast<unsigned char>(text[j + 1]) >= 0x80)
            throw InputError(at(j + 1) + "expected an escape sequence after '\\', found the byte 0x" + byte(j + 1));
          j += 2;
          continue;
        }
        if (!multi && text[j] == '\n') break;  // unterminated: toml++ reports it
        if (text.compare(j, close.size(), close) == 0) break;
        ++j;
      }
      i = std::min(n, j + close.size()) - 1;
      continue;
    }
    if (c == '[' && open.empty() && at_start) {
      std::size_t j = i + 1;
      if (j < n && text[j] == '[') ++j;
      while (j < n && (text[j] == ' ' || text[j] == '\t')) ++j;
      if (j >= n || !key_start(text[j]))
        throw InputError(at(i) + "expected a table name after '" + text.substr(i, j - i) +
                         "', found " + (j >= n ? std::string("the end of the file") : text[j] == '\n' ? std::string("the end of the line") : "'" + std::string(1, text[j]) + "'"));
      // The rest of the header is scanned like any text, a key (its closing
      // brackets close no value), so a non-ASCII byte in it is caught too.
      if (text[i + 1] == '[') ++i;
      continue;
    }
    if (c == '=') in_value = true;
    if (c == ',' && !open.empty()) in_value = open.back() == '[';  // an inline table's next key
    if (c == '[' || c == '{') {
      open += c;
      in_value = c == '[';  // an array's elements are values; an inline table starts with a key
    } else if ((c == ']' || c == '}') && !open.empty()) {
      // toml++ 3.3.0 also asserts on a '}' where an array expects a value.
      const char want = open.back() == '[' ? ']' : '}';
      if (c != want)
        throw InputError(at(i) + "expected '" + std::string(1, want) + "' to close the '" +
                         std::string(1, open.back()) + "', found '" + std::string(1, c) + "'");
      open.pop_back();
      in_value = true;  // the rest of the enclosing value
    }
  }
}

}  // namespace drawbend
