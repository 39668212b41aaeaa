// The product forms of a column (FormPlans::products, form_plans.hpp): a
// column that changes mu's slope in the pressure or the speed; see forms.hpp.
#include <set>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "loop/form_plans.hpp"

namespace drawbend::loop::detail {

// What a product form (Effect::times) means, for the report.
std::string product_meaning(EffectKind k, bool levels, const std::string& times) {
  const std::string g = levels ? "one value per level of x but the first"
                        : k == EffectKind::generic_linear ? "a slope in x"
                        : k == EffectKind::generic_step  ? "a step in x at a threshold chosen on a grid"
                                                         : "a natural cubic spline of x";
  const std::string q = times == kNominalPressure ? "q the nominal pressure F_back / (R w) (MPa, Eq. 2.2 at the back tension)"
                                                  : times == kLnSpeed ? "q = ln of the speed (mm/s)" : "q = " + times;
  return "x changes mu's slope in q: mu (1 + g(x) (q - q_mean)), g " + g + " (centred), " + q +
         "; a rougher or warmer surface changes how mu depends on pressure or speed; no physics claimed for g";
}

// A column that changes how mu depends on the pressure or on the speed (a
// rougher or warmer surface changes mu's sensitivity, not mu itself): the
// column's shape times the centred nominal pressure (Eq. 2.2 at the back
// tension: fixed by the design, not by the measured force) or the centred
// log speed (Effect::times).  The shape: a slope, a step (its threshold on
// generic_step's grid, the multiplier on) and a 3-dof smooth of a numeric
// column; its levels (one slope change per level but the first) for
// a categorical column or a numeric one of 3 to 8 replicated values
// (`levels`).  Held-out error and the one-standard-error rule choose among
// them and the other forms.
void FormPlans::products(bool levels) {
  if (!with_products) return;
  const bool numeric = c.kind == "column" && applicable(d, spec, EffectKind::generic_linear, c.name);
  // Levels of a column of the file only (a numeric model input with few
  // values, such as a sliding distance, has no levels in Design::levels).
  levels = levels && d.data->extra_index(c.name) >= 0;
  std::vector<std::string> names;
  if (levels) d.levels(c.name, &names);
  levels = levels && names.size() >= 2 && names.size() <= 9;
  for (const auto& e : spec.effects)  // one generic_smooth per column (applicable)
    levels = levels && !(e.kind == EffectKind::generic_smooth && e.variable == c.name);
  if (!numeric && !levels) return;
  for (const std::string input : {kNominalPressure, kLnSpeed}) {
    std::vector<double> m;
    try {
      m = d.values(input);
    } catch (const InputError&) {
      continue;  // e.g. a speed that is not positive: no log
    }
    std::set<double> seen;
    for (size_t i = 0; i < m.size(); ++i)
      if (!d.rows[i].rotating) seen.insert(m[i]);
    if (seen.size() < 2) continue;  // the quantity does not vary on the fixed-pin rows
    if (numeric)
      for (EffectKind k : {EffectKind::generic_linear, EffectKind::generic_step})
        if (applicable(d, spec, k, c.name)) plans.push_back({{{k, "", 0, -1, false, "", false, input}}});
    if (numeric && applicable(d, spec, EffectKind::generic_smooth, c.name))
      plans.push_back({{{EffectKind::generic_smooth, "", 3, -1, false, "", false, input}}});
    if (levels)
      plans.push_back({{{EffectKind::generic_smooth, "", static_cast<int>(names.size()) - 1, -1, false, "", false,
                         input, true}}});
  }
}

}  // namespace drawbend::loop::detail
