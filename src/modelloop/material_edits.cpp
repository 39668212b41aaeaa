// How a candidate edits a spec's material (modelloop/material_edits.hpp).
#include "modelloop/material_edits.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/csv.hpp"
#include "core/toml_read.hpp"
#include "io/material_spec.hpp"
#include "modelloop/model_loop.hpp"
#include "sim/material_choice.hpp"

namespace drawbend::modelloop {

using namespace drawbend::sim;

/// The [material] table of a spec's material (empty: the isotropic J2 model on
/// the spec's hardening curve; '{...}': an inline table; else a TOML file).
toml::table material_table(const std::string& material) {
  if (material.empty()) return toml::table{{"type", "j2"}};
  if (material.front() != '{') {
    toml::table file = parse_toml_file(material);
    if (const auto* t = file["material"].as_table()) return *t;
    throw InputError(material + ": expected a [material] table");
  }
  toml::table w = parse_toml("material = " + material, "--material");
  if (const auto* t = w["material"].as_table()) return *t;
  throw InputError("--material: expected a TOML inline table, found " + material);
}

namespace {
/// Every sub-table of t made inline (a material written as one inline table).
void inline_all(toml::table& t) {
  for (auto&& [k, v] : t)
    if (auto* sub = v.as_table()) {
      inline_all(*sub);
      sub->is_inline(true);
    }
}
}  // namespace

/// `current` with the keys of `add` set (a flow-curve key replaces the
/// others), as an inline table: candidates compose (Voce or Hill'48 on top of
/// an accepted combined-hardening model keep its back stress).
std::string merged_material(const std::string& current, const toml::table& add) {
  toml::table m = material_table(current);
  if (io::has_flow_curve(add))
    for (const char* k : io::kFlowCurveKeys) m.erase(k);
  for (auto&& [k, v] : add) m.insert_or_assign(k, v);
  inline_all(m);
  m.is_inline(true);
  std::ostringstream o;
  o << m;
  return o.str();
}

/// One key of a material file's [material] table (InputError if missing).
toml::node_view<const toml::node> file_key(const toml::table& file_material, const std::string& path,
                                           const char* key) {
  if (!file_material.contains(key)) throw InputError(path + ": [material] has no '" + key + "'");
  return file_material[key];
}


/// The flow curve of a [material] table, read by the typed reader
/// (io/material_spec.hpp; `default_table`, a CSV path, when it names none).
material::HardeningCurve curve_of(const toml::table& m, const std::string& default_table) {
  toml::table filled = m;
  const io::MaterialSpec spec = material_choice(filled, default_table, "--material");
  return io::make_flow_curve(spec.curve.value_or(io::CurveFile{default_table}), "");
}

/// The flow curve a spec's material uses (curve_of on its material).
material::HardeningCurve current_curve(const DrawBendSpec& s) { return curve_of(material_table(s.material), s.hardening); }

/// An inline hardening table of plastic strains x and stresses r.
toml::table hardening_table(const std::vector<double>& x, const std::vector<double>& r) {
  toml::array ax, ay;
  for (std::size_t i = 0; i < x.size(); ++i) {
    ax.push_back(x[i]);
    ay.push_back(r[i]);
  }
  toml::table h;
  h.insert("plastic_strain", ax);
  h.insert("true_stress_MPa", ay);
  return h;
}

/// A new flow curve (`add`'s swift or voce) on a model with Chaboche back
/// stresses: the curve is the monotonic response, so it is carved by the
/// model's back-stress terms (X_k = C_k / gamma_k) as the chaboche candidate
/// carves the table, and goes in as an inline hardening table.  Otherwise the
/// back stress would come on top of the new curve and raise every flow stress
/// by X_sat.  `add` unchanged when the model has no Chaboche terms.
toml::table carved_curve(const DrawBendSpec& s, toml::table add) {
  const toml::table cur = material_table(s.material);
  const auto* C = cur["kinematic"]["C"].as_array();
  const auto* g = cur["kinematic"]["gamma"].as_array();
  if (!C || !g || C->size() != g->size() || C->empty()) return add;
  material::HardeningCurve c = curve_of(add, s.hardening);
  std::vector<double> r;
  for (std::size_t k = 0; k < C->size(); ++k) {
    const double gk = (*g)[k].value_or(0.0);
    if (!(gk > 0))  // gamma 0 is linear (Prager) hardening: no saturation X_sat to carve
      throw InputError("material: a new flow curve cannot be carved by the linear kinematic term C = " +
                       fmt((*C)[k].value_or(0.0)) + " MPa with gamma " + fmt(gk) + " (no saturated back stress)");
    const double xk = (*C)[k].value_or(0.0) / gk;
    r = carved_isotropic_part(c, xk, gk);
    c = material::HardeningCurve(c.plastic_strains(), r, "the carved curve");
  }
  for (const char* k : {"voce", "swift"}) add.erase(k);
  add.insert_or_assign("hardening", hardening_table(c.plastic_strains(), c.stresses()));
  return add;
}

/// The chaboche candidate's material (see carved_isotropic_part).
toml::table chaboche_material(const DrawBendSpec& s, double x_sat, double gamma) {
  const material::HardeningCurve c = current_curve(s);
  const toml::table h = hardening_table(c.plastic_strains(), carved_isotropic_part(c, x_sat, gamma));
  toml::table k;
  k.insert("C", toml::array{gamma * x_sat});
  k.insert("gamma", toml::array{gamma});
  toml::table add;
  add.insert("hardening", h);
  add.insert("kinematic", k);
  return add;
}

std::vector<double> carved_isotropic_part(const material::HardeningCurve& c, double x_sat, double gamma) {
  const std::vector<double>& x = c.plastic_strains();
  std::vector<double> r = c.stresses();
  for (std::size_t i = 0; i < x.size(); ++i) r[i] -= x_sat * (1.0 - std::exp(-gamma * x[i]));
  for (std::size_t i = r.size() - 1; i-- > 0;) r[i] = std::min(r[i], r[i + 1]);
  if (!(r.front() > 0)) throw InputError("candidate chaboche: X_sat " + fmt(x_sat) + " MPa leaves no elastic range");
  return r;
}
}  // namespace drawbend::modelloop
