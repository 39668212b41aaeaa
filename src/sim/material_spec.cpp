#include "sim/material_spec.hpp"

#include <filesystem>
#include <sstream>

#include <toml++/toml.h>

#include "core/csv.hpp"
#include "core/toml_read.hpp"

namespace drawbend::sim {

namespace {
// Inline every sub-table so that each key prints on one line of [material].
void make_inline(toml::table& t) {
  for (auto&& [k, v] : t)
    if (auto* sub = v.as_table()) {
      make_inline(*sub);
      sub->is_inline(true);
    }
}
}  // namespace

std::string material_section(const std::string& material, const std::string& default_hardening) {
  if (material.empty())  // the thesis's model, written as it always was (decks and run caches unchanged)
    return "[material]\ntype = \"j2\"\nE = 70000.0\nnu = 0.33\ndensity = 2.7e-9\nhardening = \"" + default_hardening +
           "\"\n";
  toml::table m;
  {
    // '{' first: an inline table; anything else is the path of a TOML file,
    // read through the file gate (a missing file, a folder or a device is
    // named as such, not parsed as TOML).
    const std::size_t first = material.find_first_not_of(" \t");
    const bool file = first == std::string::npos || material[first] != '{';
    toml::table root;
    try {
      root = file ? parse_toml_file(material) : parse_toml("material = " + material, "--material");
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + " (expected a TOML inline table or a file with a [material] table)");
    }
    const auto* t = root["material"].as_table();
    if (!t && file) throw InputError(material + ": expected a [material] table");
    if (!t)
      throw InputError("--material: expected a TOML inline table such as { type = \"j2_combined\", "
                       "kinematic = { beta = 0.5 } } or the path of a TOML file with a [material] table");
    m = *t;
  }
  if (!m.contains("type")) m.insert("type", "j2");
  if (!m.contains("E")) m.insert("E", 70000.0);
  if (!m.contains("nu")) m.insert("nu", 0.33);
  if (!m.contains("density")) m.insert("density", 2.7e-9);
  const std::string type = m["type"].value_or(std::string());
  const bool has_curve = m.contains("hardening") || m.contains("yield") || m.contains("voce") || m.contains("swift");
  if (type != "elastic" && !has_curve) m.insert("hardening", default_hardening);
  make_inline(m);
  std::ostringstream o;
  o << "[material]\n";
  // A fixed key order (type first), so the same choice always writes the same deck.
  auto put = [&o](std::string_view key, const toml::node& v) {
    o << key << " = ";
    v.visit([&o](const auto& x) { o << x; });
    o << "\n";
  };
  for (const char* k : {"type", "E", "nu", "density"}) put(k, *m.get(k));
  for (auto&& [k, v] : m)
    if (k != "type" && k != "E" && k != "nu" && k != "density") put(k.str(), v);
  return o.str();
}

std::string sheet_section(const std::string& strip_direction) {
  if (strip_direction == "rd") return "[sheet]\nrolling_direction = [1.0, 0.0, 0.0]  # RD along the strip\n";
  if (strip_direction == "td") return "[sheet]\nrolling_direction = [0.0, 1.0, 0.0]  # RD across the strip (a TD strip)\n";
  throw InputError("strip direction: expected \"rd\" or \"td\", found \"" + strip_direction + "\"");
}

}  // namespace drawbend::sim
