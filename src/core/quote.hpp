#pragma once
/// One quoter for every TOML and JSON string we write.
///
/// Contract: `string_literal(s)` is `s` between double quotes with `"` and `\` escaped
/// by a backslash and every control character (below 0x20, and 0x7f) written
/// as `\u00XX`. Both a TOML basic string and a JSON string read that text back
/// as exactly `s` (bytes at or above 0x80 pass through unchanged; callers write
/// UTF-8). Used by the run result, the material spec, the loop's summary and
/// friction model, the portable deck writer and the blind generator's truth.
#include <cstdio>
#include <string>
#include <string_view>

namespace drawbend {

inline std::string string_literal(std::string_view v) {
  std::string s = "\"";
  s.reserve(v.size() + 2);
  for (const char ch : v) {
    if (ch == '"' || ch == '\\') {
      s += '\\';
      s += ch;
    } else if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(ch)));
      s += buf;
    } else {
      s += ch;
    }
  }
  return s + "\"";
}

}  // namespace drawbend
