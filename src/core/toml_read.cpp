// Parsing user TOML safely; see toml_read.hpp.
#include "core/toml_read.hpp"

#include <sstream>

#include "core/csv.hpp"
#include "core/toml_precheck.hpp"

namespace drawbend {

toml::table parse_toml(const std::string& text_in, const std::string& where) {
  // A UTF-8 byte-order mark, as editors on Windows write it, is not part of the TOML.
  const bool bom = text_in.rfind("\xEF\xBB\xBF", 0) == 0;
  const std::string& text = bom ? text_in.substr(3) : text_in;
  precheck_table_headers(text, where);
  try {
    return toml::parse(text, where);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << where << ":" << e.source().begin.line << ":" << e.source().begin.column
       << ": TOML syntax error: " << e.description();
    throw InputError(os.str());
  }
}

toml::table parse_toml_file(const std::string& path) { return parse_toml(read_file(path), path); }

}  // namespace drawbend
