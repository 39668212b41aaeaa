#pragma once
// How a model-loop candidate edits the material of a draw-bend spec: as a
// typed value.  A spec's material is text (empty: isotropic J2 on the spec's
// hardening curve; "{...}": a TOML inline table; else a material file).
// material_of reads it into an io::MaterialSpec through the one reader
// (sim::material_choice: every key checked, the defaults filled), a candidate
// sets fields of that value, and set_material writes it back through the one
// writer (io::to_toml_inline).  No [material] key is named here or in the
// catalogue: a new flow curve replaces the old one whatever form it had
// because the curve is one field.
#include <string>
#include <vector>

#include "io/material_spec.hpp"
#include "material/hardening_curve.hpp"
#include "sim/drawbend_case.hpp"

namespace drawbend::modelloop {

/// The typed material of a spec (defaults filled; a file's relative flow-curve
/// path taken from the file's folder).  InputError for a bad material.
io::MaterialSpec material_of(const sim::DrawBendSpec& s);

/// The spec's material set to `m` (written as one inline table).
void set_material(sim::DrawBendSpec& s, const io::MaterialSpec& m);

/// The typed [material] of a material file (data/materials/*.toml); InputError naming `path`.
io::MaterialSpec material_file(const std::string& path);

/// The flow curve of a material read by material_of (its curve is always set).
material::HardeningCurve curve_of(const io::MaterialSpec& m);

/// Whether the material has Armstrong-Frederick (Chaboche) back stresses.
bool has_back_stress(const io::MaterialSpec& m);

/// A new flow curve `curve` for a model with Chaboche back stresses: the curve
/// is the monotonic response, so it is carved by the model's back-stress terms
/// (X_k = C_k / gamma_k, carved_isotropic_part) and becomes an inline table;
/// otherwise the back stress would come on top of it and raise every flow
/// stress by X_sat.  `curve` unchanged when the model has none; InputError on
/// a linear term (gamma 0: no saturated back stress to carve).
io::FlowCurve carved_curve(const io::MaterialSpec& m, const io::FlowCurve& curve);

/// The chaboche candidate's edit: one back stress (X_sat [MPa], gamma) in place
/// of any other kinematic part, the flow curve carved by it
/// (carved_isotropic_part), and the type j2_combined unless the surface is Hill'48.
void set_back_stress(io::MaterialSpec& m, double x_sat, double gamma);

}  // namespace drawbend::modelloop
