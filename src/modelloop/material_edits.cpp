// How a candidate edits a spec's material (modelloop/material_edits.hpp).
#include "modelloop/material_edits.hpp"

#include <algorithm>
#include <cmath>

#include "core/csv.hpp"
#include "modelloop/model_loop.hpp"
#include "sim/material_choice.hpp"

namespace drawbend::modelloop {

using namespace drawbend::sim;

io::MaterialSpec material_of(const DrawBendSpec& s) { return material_choice(s.material, s.hardening); }

void set_material(DrawBendSpec& s, const io::MaterialSpec& m) { s.material = io::to_toml_inline(m); }

io::MaterialSpec material_file(const std::string& path) {
  if (path.empty() || path.front() == '{') throw InputError("material file: expected a path, found '" + path + "'");
  return material_choice(path, "");  // a file without a flow curve: no default (the caller takes other parts)
}

material::HardeningCurve curve_of(const io::MaterialSpec& m) { return io::make_flow_curve(m.curve.value(), ""); }

bool has_back_stress(const io::MaterialSpec& m) {
  const auto* ch = m.kinematic ? std::get_if<io::KinematicChaboche>(&*m.kinematic) : nullptr;
  return ch && !ch->C.empty() && ch->C.size() == ch->gamma.size();
}

io::FlowCurve carved_curve(const io::MaterialSpec& m, const io::FlowCurve& curve) {
  if (!has_back_stress(m)) return curve;
  const auto& ch = std::get<io::KinematicChaboche>(*m.kinematic);
  material::HardeningCurve c = io::make_flow_curve(curve, "");
  for (std::size_t k = 0; k < ch.C.size(); ++k) {
    const double gk = ch.gamma[k];
    if (!(gk > 0))  // gamma 0 is linear (Prager) hardening: no saturation X_sat to carve
      throw InputError("material: a new flow curve cannot be carved by the linear kinematic term C = " + fmt(ch.C[k]) +
                       " MPa with gamma " + fmt(gk) + " (no saturated back stress)");
    const std::vector<double> r = carved_isotropic_part(c, ch.C[k] / gk, gk);
    c = material::HardeningCurve(c.plastic_strains(), r, "the carved curve");
  }
  return io::CurveTable{c.plastic_strains(), c.stresses()};
}

void set_back_stress(io::MaterialSpec& m, double x_sat, double gamma) {
  const material::HardeningCurve c = curve_of(m);
  m.curve = io::CurveTable{c.plastic_strains(), carved_isotropic_part(c, x_sat, gamma)};
  m.kinematic = io::KinematicChaboche{{gamma * x_sat}, {gamma}};  // replaces split's beta: the solver takes one form
  if (m.type != io::MaterialType::hill48) m.type = io::MaterialType::j2_combined;
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
