#include "sim/material_choice.hpp"

#include <filesystem>

#include <toml++/toml.h>

#include "core/csv.hpp"
#include "core/toml_read.hpp"

namespace drawbend::sim {

io::MaterialSpec material_choice(toml::table& m, const std::string& default_hardening, const std::string& where) {
  return io::read_partial_material(m, default_hardening, std::nullopt, where);
}

io::MaterialSpec material_choice(const std::string& material, const std::string& default_hardening) {
  if (material.empty()) {  // the thesis's model
    io::MaterialSpec m;
    m.curve = io::CurveFile{default_hardening};
    return m;
  }
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
  auto* t = root["material"].as_table();  // filled in place: a copy would lose the keys' lines
  if (!t && file) throw InputError(material + ": expected a [material] table");
  if (!t)
    throw InputError("--material: expected a TOML inline table such as { type = \"j2_combined\", "
                     "kinematic = { beta = 0.5 } } or the path of a TOML file with a [material] table");
  // A flow-curve file named in a material file is that file's (relative to its folder).
  const std::optional<std::string> dir =
      file ? std::optional<std::string>(std::filesystem::path(material).parent_path().string()) : std::nullopt;
  return io::read_partial_material(*t, default_hardening, dir, file ? material : "--material");
}

std::string material_section(const std::string& material, const std::string& default_hardening) {
  return io::to_toml(material_choice(material, default_hardening));
}

toml::table sheet_table(const std::string& strip_direction) {
  if (strip_direction != "rd" && strip_direction != "td")
    throw InputError("strip direction: expected \"rd\" or \"td\", found \"" + strip_direction + "\"");
  const bool rd = strip_direction == "rd";
  return toml::table{{"rolling_direction", toml::array{rd ? 1.0 : 0.0, rd ? 0.0 : 1.0, 0.0}}};
}

}  // namespace drawbend::sim
