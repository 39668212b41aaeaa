#pragma once
// The numbers results.md's section "Where the 52.5 deg ear comes from" quotes
// from the yield functions and the fit's local minima, written into the
// chapter's values.csv (issue 51 item 5: the prose quotes the run, not a
// hand copy of tables/yield_angles.csv and tables/yld2004_minima.csv).
#include <vector>

#include "material/yld2004_fit.hpp"
#include "study/chapter.hpp"

namespace v1 {

/// Per function (its name): flange_<f>_<a> (the flange's pure-shear strain ratio at a = 0, 37.5, 45, 52.5,
/// 90 deg; "37.5" written 37_5), r_<f>_<a> and sigma_<f>_<a> at 52.5 and 60 deg, <f>_rmin and <f>_smin (the
/// lowest r(theta) and sigma(theta)/sigma0 every 7.5 deg, "value at angle"); for the fitted Yld2004-18p
/// flange_yld2004_turned (where its flange ratio lies on the other side of 1 than every quadratic function's:
/// above 1 below 45 deg, below 1 above it), and of the fit's minima yld_cost (the best set's cost) and
/// yld_minima_next (the next four sets by cost: starts, cost, RMS over sigma and r, flange ratio at 37.5 / 52.5).
/// `minima` sorted by cost and grouped as tables/yld2004_minima.csv groups them: first index of each group.
void yield_values(drawbend::study::Chapter& c, const std::vector<drawbend::material::NamedYield>& models,
                  const drawbend::material::SheetTests& tests, const std::vector<drawbend::material::Yld2004Fit::Local>& minima,
                  const std::vector<std::size_t>& groups);

}  // namespace v1
