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

namespace {

/// The scanner over one text: a small lexer of strings (basic, literal,
/// multi-line), comments, bare values and the nesting depth of array and
/// inline-table values, so that only a '[' that starts a line outside any
/// value is taken for a table header.  Each method reads one kind of token
/// starting at i and returns the index of its last character.
class Precheck {
 public:
  Precheck(const std::string& text, const std::string& path) : text_(text), path_(path), n_(text.size()) {}
  void run();

 private:
  /// "path:line:column: TOML syntax error: " of the byte at k, counted only
  /// when there is an error (multi-line strings and escapes make keeping a
  /// running count error-prone).
  std::string at(std::size_t k) const {
    const std::size_t bol = k == 0 ? 0 : text_.rfind('\n', k - 1) + 1;  // npos + 1 = 0
    const auto line = 1 + std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(k), '\n');
    return path_ + ":" + std::to_string(line) + ":" + std::to_string(k - bol + 1) + ": TOML syntax error: ";
  }
  std::string byte(std::size_t k) const {
    char b[3];
    std::snprintf(b, sizeof b, "%02x", static_cast<unsigned char>(text_[k]));
    return std::string(b);
  }
  /// TOML allows non-ASCII text only in strings and comments; toml++ 3.3.0
  /// classifies other non-ASCII characters with a table that reaches
  /// __builtin_unreachable for many of them (undefined behaviour).
  [[noreturn]] void non_ascii(std::size_t k) const {
    throw InputError(at(k) + "expected ASCII outside strings and comments, found the byte 0x" + byte(k));
  }
  bool terminator(std::size_t k) const {
    return std::string_view(" \t\r\n\v\f]},#").find(text_[k]) != std::string_view::npos;
  }
  std::size_t bare_value(std::size_t i) const;
  std::size_t string_token(std::size_t i) const;
  std::size_t table_header(std::size_t i) const;
  void bracket(std::size_t i);

  const std::string& text_;
  const std::string& path_;
  const std::size_t n_;
  std::string open_;  // brackets of the values being read, innermost last
  // Whether the text being read is a value (after '=', or an array's
  // element), not a key: a '.' there belongs to a number, not a dotted key.
  bool in_value_ = false;
};

void Precheck::run() {
  bool line_start = true;
  for (std::size_t i = 0; i < n_; ++i) {
    const char c = text_[i];
    if (c == '\n') {
      line_start = true;
      if (open_.empty()) in_value_ = false;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') continue;
    if (static_cast<unsigned char>(c) >= 0x80) non_ascii(i);
    const bool at_start = line_start;
    line_start = false;
    if (c == '#') {
      while (i + 1 < n_ && text_[i + 1] != '\n') ++i;
      continue;
    }
    if (in_value_ && !terminator(i) && std::string_view("\"'[{]},=").find(c) == std::string_view::npos) {
      i = bare_value(i);
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
    const char before = i == 0 ? '\n' : text_[i - 1];
    const bool string_may_start = std::string_view(" \t\r\n=[{,").find(before) != std::string_view::npos ||
                                  (before == '.' && !in_value_);
    if ((c == '"' || c == '\'') && string_may_start) {
      i = string_token(i);
      continue;
    }
    if (c == '[' && open_.empty() && at_start) {
      i = table_header(i);
      continue;
    }
    bracket(i);
  }
}

/// In a value, a token that is not a string, an array or an inline table (a
/// number, a date, true, inf ...) is read by toml++ 3.3.0 up to the next
/// terminator, each character tested against its whitespace table: undefined
/// behaviour for many non-ASCII code points, quotes and '=' included (`x =
/// 0"abc`, `x = 5="abc`: the fuzzer's fourth and seventh findings).  So the
/// whole token is bare text here, where non-ASCII is refused.
std::size_t Precheck::bare_value(std::size_t i) const {
  const char c = text_[i];
  std::size_t j = i;
  for (; j < n_ && !terminator(j); ++j)
    if (static_cast<unsigned char>(text_[j]) >= 0x80) non_ascii(j);
  // A date's shape (10 characters, '-' 5th and 8th), a space, one digit
  // and a terminator: toml++ takes it for a date-time written with a
  // space, reads the digit and asserts that the next character is not a
  // terminator (with NDEBUG an assumption, so undefined behaviour; the
  // sixth finding, `x = 1979-05-27 1`).  Never valid TOML: a date-time's
  // time has two digits and a colon.
  if (c >= '0' && c <= '9' && j - i == 10 && text_[i + 4] == '-' && text_[i + 7] == '-' && j + 2 < n_ &&
      text_[j] == ' ' && text_[j + 1] >= '0' && text_[j + 1] <= '9' && terminator(j + 2))
    throw InputError(at(i) + "expected a date, or a date-time such as 1979-05-27 07:32:00, found '" +
                     text_.substr(i, j + 2 - i) + "'");
  return j - 1;
}

/// A string (basic or literal, single- or multi-line) from its opening quote at i.
std::size_t Precheck::string_token(std::size_t i) const {
  const char c = text_[i];
  const bool multi = i + 2 < n_ && text_[i + 1] == c && text_[i + 2] == c;
  const std::string close = multi ? std::string(3, c) : std::string(1, c);
  std::size_t j = i + (multi ? 3 : 1);
  while (j < n_) {
    if (c == '"' && multi && text_[j] == '\\') {
      // A line-ending backslash: toml++ 3.3.0 tests each following
      // character with a whitespace table that is undefined behaviour
      // for many non-ASCII code points, so the run must end in ASCII.
      std::size_t k = j + 1;
      while (k < n_ && (text_[k] == ' ' || text_[k] == '\t' || text_[k] == '\r' || text_[k] == '\n')) ++k;
      if (k > j + 1 && k < n_ && static_cast<unsigned char>(text_[k]) >= 0x80) non_ascii(k);
    }
    if (c == '"' && text_[j] == '\\') {
      // An escape is ASCII ('\\n', '\\u00B5', or a line-ending backslash
      // before whitespace).  toml++ 3.3.0 tests the character after a
      // backslash in a multi-line string against its whitespace table
      // (undefined behaviour for e.g. U+02CF, the fuzzer's fifth finding).
      if (j + 1 < n_ && static_cast<unsigned char>(text_[j + 1]) >= 0x80)
        throw InputError(at(j + 1) + "expected an escape sequence after '\\', found the byte 0x" + byte(j + 1));
      j += 2;
      continue;
    }
    if (!multi && text_[j] == '\n') break;  // unterminated: toml++ reports it
    if (text_.compare(j, close.size(), close) == 0) break;
    ++j;
  }
  return std::min(n_, j + close.size()) - 1;
}

/// A table header's '[' or '[[' at the start of a line, outside any value: a key must follow.
std::size_t Precheck::table_header(std::size_t i) const {
  std::size_t j = i + 1;
  if (j < n_ && text_[j] == '[') ++j;
  while (j < n_ && (text_[j] == ' ' || text_[j] == '\t')) ++j;
  if (j >= n_ || !key_start(text_[j]))
    throw InputError(at(i) + "expected a table name after '" + text_.substr(i, j - i) +
                     "', found " + (j >= n_ ? std::string("the end of the file") : text_[j] == '\n' ? std::string("the end of the line") : "'" + std::string(1, text_[j]) + "'"));
  // The rest of the header is scanned like any text, a key (its closing
  // brackets close no value), so a non-ASCII byte in it is caught too.
  return text_[i + 1] == '[' ? i + 1 : i;
}

/// Any other character: '=' starts a value; ',' '[' '{' ']' '}' track the nesting of values.
void Precheck::bracket(std::size_t i) {
  const char c = text_[i];
  if (c == '=') in_value_ = true;
  if (c == ',' && !open_.empty()) in_value_ = open_.back() == '[';  // an inline table's next key
  if (c == '[' || c == '{') {
    open_ += c;
    in_value_ = c == '[';  // an array's elements are values; an inline table starts with a key
  } else if ((c == ']' || c == '}') && !open_.empty()) {
    // toml++ 3.3.0 also asserts on a '}' where an array expects a value.
    const char want = open_.back() == '[' ? ']' : '}';
    if (c != want)
      throw InputError(at(i) + "expected '" + std::string(1, want) + "' to close the '" +
                       std::string(1, open_.back()) + "', found '" + std::string(1, c) + "'");
    open_.pop_back();
    in_value_ = true;  // the rest of the enclosing value
  }
}

}  // namespace

void precheck_table_headers(const std::string& text, const std::string& path) { Precheck(text, path).run(); }

}  // namespace drawbend
