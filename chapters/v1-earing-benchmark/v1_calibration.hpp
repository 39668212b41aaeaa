// Chapter v1, step 1b: Yld2004-18p fitted to the sheet's published tests
// (drawbend calibrate's fit), set on the yld2004 variants, with the chapter's
// calibration tables and the values its prose quotes (v1_calibration.cpp).
#pragma once

#include <string>
#include <vector>

#include "study/chapter.hpp"
#include "v1_cup.hpp"

namespace v1 {

/// Fits Yld2004-18p (a = 8, equal weights on the relative residuals) to
/// data/materials/aa6016_t4_esaform2021.csv and sets it on every variant of
/// type yld2004 in `list` (or the set in the TOML `yld_set`, a diagnostic run);
/// writes tables/calibration.csv (measured, Hill'48 from `hr`'s r-values and
/// from `hsv`'s stress ratios, the fit, POSTECH's published set),
/// tables/yield_angles.csv, tables/yld2004_minima.csv and their values.
void calibrate_yld2004(drawbend::study::Chapter& c, std::vector<Variant>& list, const Variant& hr,
                       const Variant& hsv, const std::string& yld_set);

}  // namespace v1
