#pragma once
// The [material] section of a builder's deck (draw-bend, cup) from the user's
// choice, so that every builder offers the same `--material`:
//  - empty: isotropic J2 (type "j2") with the builder's default hardening CSV,
//    the thesis's model (Table 5.1 curves);
//  - a TOML inline table of [material] keys, e.g.
//      { type = "j2_combined", kinematic = { beta = 0.5 } }
//      { type = "hill48", hill48 = { r0 = 0.69, r45 = 0.73, r90 = 0.87 } }
//    merged over E = 70000 MPa, nu = 0.33, density = 2.7e-9 t/mm^3 and, when
//    it names no flow curve, the default hardening CSV;
//  - the path of a TOML file with a [material] table (data/materials/*.toml),
//    merged the same way.
// The merged table is read by io::from_toml (io/material_spec.hpp), which
// checks every key and value with file:line: key messages naming the file or
// "--material", and written by io::to_toml.  Units: MPa, t/mm^3.
#include <string>

#include <toml++/toml.h>

#include "io/material_spec.hpp"

namespace drawbend::sim {

/// The typed material of the choice above.  Throws InputError when the text is
/// neither a readable TOML file with a [material] table nor a TOML inline
/// table, or when a key or value is wrong.
io::MaterialSpec material_choice(const std::string& material, const std::string& default_hardening);
/// The same for a [material] table already parsed (a partial table: the
/// defaults above are inserted into it); `where` names it in messages.
io::MaterialSpec material_choice(toml::table& m, const std::string& default_hardening, const std::string& where);

/// "[material]\n..." for the choice above: io::to_toml(material_choice(...)).
std::string material_section(const std::string& material, const std::string& default_hardening);

/// The [sheet] table { rolling_direction = [...] }: the strip's axis (x) is RD
/// ("rd") or TD ("td", RD across the strip: y).  Throws InputError for anything else.
toml::table sheet_table(const std::string& strip_direction);

}  // namespace drawbend::sim
