// Where a study's reduction reads, and the deck reader's check of it (no
// solver needed).  See case_reduction.hpp.
#include <algorithm>

#include "core/csv.hpp"
#include "io/case_reduction.hpp"

namespace drawbend::io {

const std::vector<std::string>& reduction_kinds() {
  static const std::vector<std::string> k{"block_slide", "strip_draw", "cup_draw", "earing_cup"};
  return k;
}

ReductionPlace reduction_place(const ReductionSpec& r, const fe::Model& m) {
  ReductionPlace w;
  for (std::size_t k = 0; k < m.steps.size(); ++k)
    if (m.steps[k].name == r.step) w.step = static_cast<int>(k);
  for (std::size_t k = 0; k < m.contacts.size(); ++k)
    if (m.contacts[k].tool == r.tool) w.pair = static_cast<int>(k);
  if (w.step < 0) throw InputError("output.reduce.step: no step named \"" + r.step + "\"");
  if (w.pair < 0) throw InputError("output.reduce.tool: no [[contact]] on a tool named \"" + r.tool + "\"");
  return w;
}

void check_reduction(const ReductionSpec& r, const fe::Model& m) {
  const auto& kinds = reduction_kinds();
  if (std::find(kinds.begin(), kinds.end(), r.kind) == kinds.end())
    throw InputError("output.reduce.kind: expected block_slide, strip_draw, cup_draw or earing_cup, found \"" + r.kind + "\"");
  reduction_place(r, m);
}

}  // namespace drawbend::io
