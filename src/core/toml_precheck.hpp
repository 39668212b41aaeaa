#pragma once
// A check run on deck text before toml++ parses it.  toml++ 3.3.0 (Debian 12)
// asserts, or with NDEBUG assumes, that a table header's '[' or '[[' is
// followed by a key; input such as "[\nx]" or "[[[1]]]" then aborts or is
// undefined behaviour (found by tests/fuzz; fixed upstream in
// marzer/tomlplusplus pull request #301).  This scanner reports such headers
// as an InputError with file:line first, and likewise a '}' where an array
// expects a value ("x = [}"), on which toml++ 3.3.0 asserts too, and a
// non-ASCII character outside strings and comments (not valid TOML; toml++
// 3.3.0's whitespace test is undefined behaviour for many of them).
#include <string>

namespace drawbend {

/// Throws InputError "path:line:column: TOML syntax error: ..." for a table
/// header whose opening bracket is not followed by a key.
void precheck_table_headers(const std::string& text, const std::string& path);

}  // namespace drawbend
