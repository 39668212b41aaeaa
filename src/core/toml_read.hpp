#pragma once
// The one way into toml++ for text a user wrote: case decks, `--material`
// files and inline tables, `cup-deck --base` decks.  toml++ 3.3.0 (Debian 12)
// asserts on some malformed input, or with NDEBUG has undefined behaviour
// (tests/fuzz/README.md, findings 1-4), so the text first goes through
// precheck_table_headers (core/toml_precheck.hpp); then every syntax error,
// ours or toml++'s, is an InputError "where:line:column: TOML syntax error:
// ..." (exit 2 in the commands).
#include <string>

#include <toml++/toml.h>

namespace drawbend {

/// Parses TOML `text`; `where` names it in messages (a path, or an option
/// such as "--material").  A leading UTF-8 byte-order mark is skipped.
toml::table parse_toml(const std::string& text, const std::string& where);

/// The same for the file at `path` (its read is noted for provenance);
/// InputError if it cannot be read.
toml::table parse_toml_file(const std::string& path);

}  // namespace drawbend
