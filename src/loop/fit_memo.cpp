// The loop's memo of model fits; see fit_memo.hpp.
#include "loop/fit_memo.hpp"

#include <cstdio>
#include <sstream>

namespace drawbend::loop {

std::string spec_key(const ModelSpec& s) {
  std::ostringstream k;
  k << s.bending_linear;
  for (const auto& e : s.effects) {
    char lam[40];
    std::snprintf(lam, sizeof lam, "%a", e.lambda_mm);
    char bump[80];
    std::snprintf(bump, sizeof bump, "%a,%a", e.bump_centre, e.bump_width);
    k << '|' << static_cast<int>(e.kind) << ',' << e.variable.size() << ':' << e.variable << ',' << lam << ','
      << e.n_levels << ',' << e.by.size() << ':' << e.by << ',' << e.n_groups << ',' << e.n_basis << ',' << e.cell << ',' << e.bend_scaled << ',' << e.cell_offset
      << ',' << e.times.size() << ':' << e.times << ',' << e.level_basis << ',' << bump;
    if (e.step) {  // a step: its threshold (two steps never share a key)
      std::snprintf(bump, sizeof bump, ",S%a", e.step_at);
      k << bump;
    }
  }
  return k.str();
}

}  // namespace drawbend::loop
