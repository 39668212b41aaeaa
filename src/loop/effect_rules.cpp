// Where each friction parameter lives in theta, and its name, from the effect
// table (effect_rules.hpp).
#include "loop/effect_rules.hpp"

namespace drawbend::loop::detail {

Layout layout(const Design& d, const ModelSpec& spec) {
  Layout L;
  for (size_t c = 0; c < d.cells.size(); ++c) {
    L.mu_rd.push_back(d.cell_rd[c] ? L.n++ : -1);
    L.mu_td.push_back(d.cell_td[c] ? L.n++ : -1);
  }
  for (const auto& e : spec.effects) {
    L.eff_start.push_back(L.n);
    L.n += visit_rule(e.kind, [&](auto rule) { return rule.count(d, e); });
  }
  return L;
}

std::vector<std::string> friction_names(const Design& d, const ModelSpec& spec, const Layout& L,
                                        const std::vector<std::vector<std::string>>& level_names) {
  std::vector<std::string> n(L.n);
  for (size_t c = 0; c < d.cells.size(); ++c) {
    if (L.mu_rd[c] >= 0) n[L.mu_rd[c]] = "mu_RD [" + d.cells[c] + "]";
    if (L.mu_td[c] >= 0) n[L.mu_td[c]] = "mu_TD [" + d.cells[c] + "]";
  }
  for (size_t k = 0; k < spec.effects.size(); ++k) {
    const Effect& e = spec.effects[k];
    visit_rule(e.kind, [&](auto rule) { rule.name(d, e, level_names[k], L.eff_start[k], n); });
  }
  return n;
}

}  // namespace drawbend::loop::detail
