// The bump and step forms of a column (FormPlans::bumps, form_plans.hpp): a
// local Gaussian bump and a step of a numeric column (bump.hpp) on mu and on
// the force channel; see forms.hpp.
#include <set>
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "loop/bump.hpp"
#include "loop/form_plans.hpp"

namespace drawbend::loop::detail {

std::string bump_meaning(EffectKind k) {
  const std::string b = "b(x) = exp(-((x - c)/w)^2 / 2) a Gaussian bump of x, its centre c and width w scanned on a "
                        "grid (49 centres, 7 widths from 0.03 to 0.33 of the range) where it explains the most of "
                        "the held-out residual and counted as two parameters by the F test";
  return k == EffectKind::force_offset
             ? "force channel: an extra force c b(x) on the outlet force of every row (fixed and rotating pin), " + b +
                   "; an effect local in x (a drag or a bending-force change over a band of x only)"
             : "generic local effect: mu (1 + beta b(x)), " + b + "; an effect local in x, no physics claimed";
}

std::string step_meaning(EffectKind k) {
  const std::string s = "s(x) = [x > c] a step of x, its threshold c scanned between the column's values where it "
                        "explains the most of the held-out residual (at least two values and max(10, n / 20) rows "
                        "on each side) and counted as one parameter by the F test";
  return k == EffectKind::force_offset
             ? "force channel: an extra force c s(x) on the outlet force of every row (fixed and rotating pin), " + s +
                   "; an effect that switches on above a value of x (a drag or a bending-force change)"
             : "generic step: mu (1 + beta s(x)), " + s + "; an effect that switches on above a value of x, no physics "
                                                         "claimed";
}

// A numeric column of the file (FormPlans::measured_column) with more than 8 distinct values: a bump of it
// on mu (1 dof: its height), and on the force channel in newtons and as a
// share of each pin's bending force (scaled), overall (cell_group < 0) or in
// the one group cell_group of cell_by only (friction, and with `force` the
// force channel; no scaled form for a pin, as force_in_cell).  Centre and
// width: scan_bump on the current held-out residual of the rows the form acts
// on (friction: the fixed-pin rows; force: every row), within the cell for a
// one-cell form.  Likewise a step of it (scan_step; threshold counted as one
// parameter, q + 1): on mu in one cell (overall, generic_step is the step on
// mu) and on the force channel, overall or in the cell.  Held-out error, the
// F test (q + 2 for a bump) and the one-SE rule (never handed the step from a
// better form) choose among them and the others.
void FormPlans::bumps(const std::set<double>& distinct, const std::string& cell_by, int cell_group, bool force) {
  if (!cur || c.kind != "column" || c.categorical || !measured_column() || distinct.size() <= 8) return;
  std::vector<double> x;
  try {
    x = d.values(c.name);  // what the basis reads (an empty cell at the column's mean)
  } catch (const InputError&) {
    return;
  }
  std::vector<int> grp;
  if (cell_group >= 0) {
    int n = 0;
    grp = d.groups(cell_by, &n);
  }
  const std::string by = cell_group >= 0 ? cell_by : "";
  auto rows = [&](bool fixed_only) {
    std::vector<char> use(d.rows.size(), 0);
    for (size_t i = 0; i < d.rows.size(); ++i)
      use[i] = (!fixed_only || !d.rows[i].rotating) && (cell_group < 0 || grp[i] == cell_group);
    return use;
  };
  if (applicable(d, spec, EffectKind::generic_smooth, c.name)) {
    if (const auto b = scan_bump(x, cur->resid, rows(true)))
      plans.push_back({{{EffectKind::generic_smooth, by, 1, cell_group, false, "", false, "", false, b->centre,
                         b->width}}});
    if (cell_group >= 0)
      if (const auto s = scan_step(x, cur->resid, rows(true)))
        plans.push_back({{{EffectKind::generic_smooth, by, 1, cell_group, false, "", false, "", false, s->at, 0, true}}});
  }
  if (!force || !applicable(d, spec, EffectKind::force_offset, c.name)) return;
  const auto b = scan_bump(x, cur->resid, rows(false));
  const auto s = scan_step(x, cur->resid, rows(false));
  for (bool scaled : {false, true}) {
    if (scaled && cell_group >= 0 && cell_by == "pin") break;
    if (b)
      plans.push_back({{{EffectKind::force_offset, by, 1, cell_group, scaled, "", false, "", false, b->centre,
                         b->width}}});
    if (s) plans.push_back({{{EffectKind::force_offset, by, 1, cell_group, scaled, "", false, "", false, s->at, 0, true}}});
  }
}

}  // namespace drawbend::loop::detail
