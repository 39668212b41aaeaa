#pragma once
// A check run on TOML text before toml++ parses it (called by parse_toml,
// core/toml_read.hpp; never call toml::parse on a user's text without it).
// toml++ 3.3.0 (Debian 12) asserts, or with NDEBUG assumes, on some malformed
// input, and tests characters against Unicode tables that reach
// __builtin_unreachable for many non-ASCII code points: undefined behaviour
// either way (tests/fuzz/README.md, findings 1-7).  This scanner follows
// toml++'s reading where that matters (strings and comments, bare values up
// to their terminator, table headers, the nesting of arrays and inline
// tables) and reports, as an InputError with file:line:column first:
//  - a table header whose '[' or '[[' is not followed by a key ("[\nx]",
//    "[[[1]]]"; fixed upstream in marzer/tomlplusplus pull request #301);
//  - a '}' where an array expects a value ("x = [}");
//  - a non-ASCII character outside strings and comments (not valid TOML),
//    including one inside a bare value after a glued quote ("x = 0\"é");
//  - a backslash before a non-ASCII character in a basic string;
//  - a date's shape followed by a space, one digit and a terminator
//    ("x = 1979-05-27 1").
// None of these is valid TOML, so no valid document is refused.
#include <string>

namespace drawbend {

/// Throws InputError "path:line:column: TOML syntax error: ..." for the
/// inputs listed above; returns normally for anything else.
void precheck_table_headers(const std::string& text, const std::string& path);

}  // namespace drawbend
