#pragma once
// The [material] section of a case as a typed value: one reader (from_toml,
// with file:line: key messages) and one writer (to_toml); this file and
// material_spec.cpp are the one place that knows the [material] keys.  The
// deck reader (io/deck.cpp: make_material and material_warnings on the
// deck's table), the builders' `--material` choice (sim/material_choice.cpp:
// read_partial_material fills in the defaults) and the model-level loop's
// candidates (modelloop/material_edits.hpp: they set fields of the typed
// value and write it back with to_toml_inline) go through here, naming no key.
//
// [material]: type = "elastic" | "j2" | "j2_combined" | "hill48" | "yld2004"; E [MPa], nu,
// density [t/mm^3]; the plastic types take one flow curve:
//   hardening = "path.csv"           (plastic_strain,true_stress_MPa; relative to the deck's directory)
//   hardening = { plastic_strain = [...], true_stress_MPa = [MPa, ...] }
//   yield = MPa [, tangent = MPa]    (linear hardening)
//   voce = { sigma0 = MPa, Q = MPa, b }   or   swift = { K = MPa, e0, n };
// j2_combined (and optionally hill48): kinematic = { beta } (split form, beta
// in [0, 1]) or { C = [MPa, ...], gamma = [...] } (1 to 3 Armstrong-Frederick
// terms); hill48: hill48 = { r0, r45, r90 } or { s45, s90, sb } (yield-stress
// ratios to RD) (material/combined_plasticity.hpp, material/hill48.hpp);
// yld2004 (optionally kinematic): yld2004 = { a, c1 = [9], c2 = [9] }
// (material/yld2004_plasticity.hpp).
//
// Reading then writing gives the same spec back (tests/unit/test_material_spec.cpp
// on every tracked deck).  The writer's text is fixed by the spec: keys in the
// order type, E, nu, density, flow curve, kinematic, yield surface; numbers in
// their shortest round-trip form (70000.0, 2.7e-9, 0.33).
//
// A new yield function: an alternative in YieldSurface, its type name in
// MaterialType, its keys in from_toml/to_toml (material_spec.cpp) and its
// construction in make_material; nothing else knows the keys.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <toml++/toml.h>

#include "io/deck_context.hpp"
#include "material/hardening_curve.hpp"
#include "material/material.hpp"
#include "material/yld2004.hpp"

namespace drawbend::io {

/// hardening = "curve.csv": the path as written (relative paths are taken from
/// the deck's directory when the material is built).
struct CurveFile {
  std::string path;
  bool operator==(const CurveFile&) const = default;
};
/// hardening = { plastic_strain = [...], true_stress_MPa = [...] }.
struct CurveTable {
  std::vector<double> plastic_strain, true_stress_MPa;
  bool operator==(const CurveTable&) const = default;
};
/// yield = sigma_y [MPa] with an optional tangent = H [MPa] (linear hardening; 0 when absent).
struct CurveLinear {
  double yield = 0;
  std::optional<double> tangent;
  bool operator==(const CurveLinear&) const = default;
};
/// voce = { sigma0 [MPa], Q [MPa], b }: sigma0 + Q (1 - exp(-b eps_p)).
struct CurveVoce {
  double sigma0 = 0, Q = 0, b = 0;
  bool operator==(const CurveVoce&) const = default;
};
/// swift = { K [MPa], e0, n }: K (e0 + eps_p)^n.
struct CurveSwift {
  double K = 0, e0 = 0, n = 0;
  bool operator==(const CurveSwift&) const = default;
};
/// The flow curve: exactly one of the five forms.
using FlowCurve = std::variant<CurveFile, CurveTable, CurveLinear, CurveVoce, CurveSwift>;

/// kinematic = { beta }: the split form (kinematic fraction of the curve's hardening).
struct KinematicSplit {
  double beta = 0;
  bool operator==(const KinematicSplit&) const = default;
};
/// kinematic = { C = [MPa, ...], gamma = [...] }: 1 to 3 Armstrong-Frederick terms.
struct KinematicChaboche {
  std::vector<double> C, gamma;
  bool operator==(const KinematicChaboche&) const = default;
};
using Kinematic = std::variant<KinematicSplit, KinematicChaboche>;

/// The isotropic von Mises surface (types j2 and j2_combined).
struct VonMises {
  bool operator==(const VonMises&) const = default;
};
/// hill48 = { r0, r45, r90 }: Lankford r-values.
struct Hill48R {
  double r0 = 0, r45 = 0, r90 = 0;
  bool operator==(const Hill48R&) const = default;
};
/// hill48 = { s45, s90, sb }: yield-stress ratios to RD.
struct Hill48S {
  double s45 = 0, s90 = 0, sb = 0;
  bool operator==(const Hill48S&) const = default;
};
/// yld2004 = { a, c1 = [9], c2 = [9] }: Yld2004-18p's exponent and its two
/// linear transformations C' and C'' (c12, c13, c21, c23, c31, c32, c44, c55,
/// c66; material/yld2004.hpp).
struct Yld2004Surface {
  double a = 8;
  std::array<double, 9> c1{}, c2{};
  bool operator==(const Yld2004Surface&) const = default;
};
/// The yield surface; the next yield function is one more alternative here.
using YieldSurface = std::variant<VonMises, Hill48R, Hill48S, Yld2004Surface>;

enum class MaterialType { elastic, j2, j2_combined, hill48, yld2004 };
/// "elastic", "j2", "j2_combined", "hill48", "yld2004".
const char* type_name(MaterialType t);

struct MaterialSpec {
  MaterialType type = MaterialType::j2;
  double E = 70000.0;       ///< [MPa]
  double nu = 0.33;
  double density = 2.7e-9;  ///< [t/mm^3]
  std::optional<FlowCurve> curve;      ///< every type but elastic
  std::optional<Kinematic> kinematic;  ///< j2_combined (required), hill48 and yld2004 (optional)
  YieldSurface surface;                ///< Hill48R/S for hill48, Yld2004Surface for yld2004, VonMises otherwise
  bool operator==(const MaterialSpec&) const = default;
};

/// Reads the [material] table t.  Every problem is recorded in c's collector
/// (file:line: key: ...), or thrown as InputError when the table cannot be
/// read on (an unknown type, a sub-table that is not a table); the returned
/// spec is meaningful only when no problem was recorded.
MaterialSpec from_toml(const DeckContext& c, const toml::table& t);

/// from_toml on a table that came from `where` (a path, or "--material"):
/// InputError listing every problem.
MaterialSpec read_material(const toml::table& t, const std::string& where);

/// A partial [material] table t (a builder's --material) read as a spec: a flow-curve
/// file named in t is first made absolute from `curve_dir` when one is given (a
/// material file's folder); then the keys t lacks are inserted into it: type "j2",
/// E, nu and density of MaterialSpec{} and, for a plastic type without a flow
/// curve, hardening = default_curve.  `where` names t in messages (read_material).
MaterialSpec read_partial_material(toml::table& t, const std::string& default_curve,
                                   const std::optional<std::string>& curve_dir, const std::string& where);

/// The keys that choose a flow curve (the five forms above), for code that
/// completes a partial [material] table (sim::material_choice) without
/// listing them again.
inline constexpr const char* kFlowCurveKeys[] = {"hardening", "yield", "tangent", "voce", "swift"};
/// Whether t names a flow curve (one of kFlowCurveKeys).
bool has_flow_curve(const toml::table& t);

/// The key a flow curve is written under: "hardening" (a file or an inline
/// table), "yield", "voce" or "swift"; and a yield surface's: "hill48",
/// "yld2004" ("" for von Mises).  For layout (CaseSpec::material_sections)
/// without naming a key.
const char* key_of(const FlowCurve& f);
const char* key_of(const YieldSurface& s);

/// "[material]\n" and one line per key, in the fixed order above.
std::string to_toml(const MaterialSpec& m);
/// The same keys as one TOML inline table, "{ type = ..., E = ..., ... }" (to_toml's
/// lines joined): a material carried as text in a builder's spec
/// (sim::DrawBendSpec::material), as the model loop's candidates write it.
std::string to_toml_inline(const MaterialSpec& m);

/// A Yld2004-18p parameter set from a TOML file with [material] yld2004 = { a, c1 = [9], c2 = [9] }
/// (as `drawbend calibrate` writes it) or yld2004 = {...} at the top (a published set alone), as
/// written, not normalised; InputError naming file:line: key when it is missing, malformed or
/// refused by Yld2004::validate().
material::Yld2004 load_yld2004_toml(const std::string& path);

/// The flow curve's table; `dir` resolves a relative CurveFile path ("" for
/// as written).  Throws InputError for an unreadable or bad table file.
material::HardeningCurve make_flow_curve(const FlowCurve& f, const std::string& dir);

/// The Material the spec describes (a spec from from_toml without problems).
/// Throws InputError (a bad table file) or std::invalid_argument (constants
/// the model refuses).
std::shared_ptr<const material::Material> make_material(const MaterialSpec& m, const std::string& dir);

/// The deck reader's [material] t: from_toml, a flow-curve file that is not a
/// readable file named at its line, then the Material (the model's refusals
/// as problems at the table, or at yld2004 for its convexity).  Problems are
/// recorded in c's collector; returns nullptr if the material could not be built.
/// `type` (when given) receives the type's name ("j2", ...) once the table is read.
std::shared_ptr<const material::Material> make_material(const DeckContext& c, const toml::table& t,
                                                        const std::string& deck_dir, std::string* type = nullptr);

/// Values of [material] t outside the range of real materials (most likely
/// other units): one warning each in `warnings` (file:line: material.KEY: ...).
void material_warnings(const DeckContext& c, const toml::table& t, std::vector<std::string>& warnings);

}  // namespace drawbend::io
