#pragma once
// How a model-loop candidate edits the material of a draw-bend spec.  A
// spec's material is text (empty: isotropic J2 on the spec's hardening
// curve; "{...}": a TOML inline table; else a material file); these read it as
// a [material] table, set keys and write it back as one inline table.  The
// flow-curve keys are the typed reader's (io::kFlowCurveKeys): a new flow
// curve replaces the old one whatever form it had.
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "material/hardening_curve.hpp"
#include "sim/drawbend_case.hpp"

namespace drawbend::modelloop {

/// The [material] table of a spec's material (InputError if a file has none).
toml::table material_table(const std::string& material);

/// `current` with the keys of `add` set (a flow-curve key replaces the
/// others), as an inline table: candidates compose (Voce or Hill'48 on top of
/// an accepted combined-hardening model keep its back stress).
std::string merged_material(const std::string& current, const toml::table& add);

/// One key of a material file's [material] table (InputError naming `path` if missing).
toml::node_view<const toml::node> file_key(const toml::table& file_material, const std::string& path, const char* key);

/// The flow curve of a [material] table (`default_table`, a CSV path, when it names none).
material::HardeningCurve curve_of(const toml::table& m, const std::string& default_table);

/// The flow curve a spec's material uses.
material::HardeningCurve current_curve(const sim::DrawBendSpec& s);

/// An inline hardening table of plastic strains x and stresses r [MPa].
toml::table hardening_table(const std::vector<double>& x, const std::vector<double>& r);

/// A new flow curve (`add`'s swift or voce) on a model with Chaboche back
/// stresses, carved by their saturated values so that the back stress does
/// not come on top of it; `add` unchanged when the model has none.
toml::table carved_curve(const sim::DrawBendSpec& s, toml::table add);

/// The chaboche candidate's material keys: one back stress (X_sat [MPa],
/// gamma) and the flow curve carved by it (carved_isotropic_part).
toml::table chaboche_material(const sim::DrawBendSpec& s, double x_sat, double gamma);

}  // namespace drawbend::modelloop
