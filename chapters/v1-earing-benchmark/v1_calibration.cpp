// Chapter v1, steps 1b and 1c: Yld2004-18p fitted to the sheet's published
// tests, the calibration table beside both Hill'48 calibrations and POSTECH's
// published set, the functions between the tested angles and the fit's local
// minima (results.md, "Where the 52.5 deg ear comes from").
#include "v1_calibration.hpp"

#include <algorithm>
#include <cmath>

#include "io/material_spec.hpp"
#include "material/hill48.hpp"
#include "material/yld2004_fit.hpp"
#include "v1_yield_values.hpp"

namespace v1 {

using namespace drawbend;

/// Step 1c: between the tested angles, and the flange's pure shear that no test sees (results.md, "Where the
/// 52.5 deg ear comes from"); and the fit's local minima.
namespace {

void yield_between_angles(study::Chapter& c, const material::SheetTests& tests,
                          const std::vector<material::NamedYield>& models, const material::Yld2004Fit& fit) {
  // every 7.5 deg
  std::vector<std::string> head{"angle_deg", "sigma_measured", "r_measured"};
  for (const auto& m : models)
    for (const char* q : {"sigma_", "r_", "flange_"}) head.push_back(q + m.name);
  auto ang = c.table(head, "Every 7.5 deg from RD: the tests (where given) and each function's sigma_t/sigma_0, r_t and "
                           "flange strain ratio -d eps_r/d eps_h under sigma_r = -sigma_h at that polar angle "
                           "(1: no thickness change; below 1 the flange thickens)");
  for (int k = 0; k <= 12; ++k) {
    const double t = 7.5 * k;
    const auto opt = [](double v) { return std::isnan(v) ? std::string() : fmt_fixed(v, 3); };
    std::vector<std::string> row{fmt_shortest(t), opt(tests.uniaxial_stress(t)), opt(tests.r_value(t))};
    for (const auto& m : models)
      row.insert(row.end(), {fmt_fixed(m.uniaxial_ratio(t), 4), fmt_fixed(m.r_value(t), 4),
                             fmt_fixed(m.flange_shear_ratio(t), 4)});
    ang.row(row);
  }
  c.save(ang, "yield_angles");
  // The fit's local minima (its starts, grouped where they converged to the same set): how well each fits the
  // tests, and the flange's shear ratio either side of 45 deg, where no test looks.
  auto mins = c.table({"starts", "cost", "rms_sigma", "rms_r", "sigma_b", "sigma_ps0", "flange_37.5", "flange_52.5",
                       "flange_90", "the_fit"},
                      "The Yld2004-18p fit's converged starts, grouped by the set they reached, best cost first: cost "
                      "(weighted squared relative residuals), RMS over sigma(theta)/sigma0 and r(theta), sigma_b and "
                      "sigma_ps(0), and the flange strain ratio at 37.5, 52.5 and 90 deg");
  std::vector<material::Yld2004Fit::Local> loc = fit.local;
  std::stable_sort(loc.begin(), loc.end(), [](const auto& a, const auto& b) { return a.cost < b.cost; });
  std::vector<std::size_t> groups;  // the first start of each set
  for (std::size_t i = 0; i < loc.size();) {
    groups.push_back(i);
    const material::NamedYield m{"m", &loc[i].yield, nullptr};
    std::string starts;
    std::size_t j = i;
    for (; j < loc.size() && loc[j].cost - loc[i].cost < 1e-7 &&
           std::abs(material::NamedYield{"n", &loc[j].yield, nullptr}.flange_shear_ratio(52.5) -
                    m.flange_shear_ratio(52.5)) < 1e-4;
         ++j)
      starts += (starts.empty() ? "" : " ") + std::to_string(loc[j].start);
    mins.row({starts, fmt_fixed(loc[i].cost, 5), fmt_fixed(m.rms(tests, material::SheetDatum::uniaxial_stress), 4),
              fmt_fixed(m.rms(tests, material::SheetDatum::uniaxial_r), 4), fmt_fixed(loc[i].yield.biaxial_ratio(), 3),
              fmt_fixed(loc[i].yield.plane_strain_ratio(0.0), 3), fmt_fixed(m.flange_shear_ratio(37.5), 3),
              fmt_fixed(m.flange_shear_ratio(52.5), 3), fmt_fixed(m.flange_shear_ratio(90.0), 3),
              i == 0 ? "yes" : ""});
    i = j;
  }
  c.save(mins, "yld2004_minima");
  yield_values(c, models, tests, loc, groups);  // the numbers the prose quotes from both tables
}

}  // namespace

/// Step 1b: Yld2004-18p fitted to every published material test (drawbend calibrate's fit, equal weights on the
/// relative residuals), set on the yld2004 variants, and the loop's before and after on those tests: measured,
/// both Hill'48 calibrations, the fit, and POSTECH's published Yld2004-18p for the same sheet.
void calibrate_yld2004(study::Chapter& c, std::vector<Variant>& list, const Variant& hr, const Variant& hsv,
                       const std::string& yld_set) {
  const material::SheetTests tests = material::load_sheet_tests(c.data("materials/aa6016_t4_esaform2021.csv"));
  const material::FitWeights weights;
  const material::Yld2004Fit fit = material::fit_yld2004(tests, weights, 8.0);
  const material::Yld2004 postech =
      io::load_yld2004_toml(c.data("materials/aa6016_t4_yld2004_postech2022.toml")).normalised();
  for (auto& v : list)
    if (v.type == "yld2004") v.a = fit.raw.a, v.c1 = fit.raw.c1, v.c2 = fit.raw.c2;
  if (!yld_set.empty()) {  // diagnostic: another parameter set (as written; the solver normalises it)
    const material::Yld2004 alt = io::load_yld2004_toml(yld_set);
    for (auto& v : list)
      if (v.type == "yld2004") v.a = alt.a, v.c1 = alt.c1, v.c2 = alt.c2;
  }
  const material::Hill48 h_r = material::Hill48::from_r_values(hr.r0, hr.r45, hr.r90);
  const material::Hill48 h_s = material::Hill48::from_stress_ratios(hsv.s45, hsv.s90, hsv.sb);
  const std::vector<material::NamedYield> models = {
      {"hill48_r", nullptr, &h_r}, {"hill48_s", nullptr, &h_s}, {"yld2004", &fit.yield, nullptr},
      {"yld2004_postech", &postech, nullptr}};
  const auto rows = material::calibration_table(tests, weights, models, 2);
  auto cal = c.table(rows.front(), "Material tests of the sheet: measured, predicted by Hill'48 from the r-values, "
                                   "Hill'48 from the stress ratios, Yld2004-18p fitted here (weights: 1 on each "
                                   "relative residual) and POSTECH's published Yld2004-18p; residual of the fit");
  for (std::size_t k = 1; k < rows.size(); ++k) cal.row(rows[k]);
  c.save(cal, "calibration");
  yield_between_angles(c, tests, models, fit);
  for (const auto& m : models) {
    c.value("rms_s_" + m.name, fmt(m.rms(tests, material::SheetDatum::uniaxial_stress), 3));
    c.value("rms_r_" + m.name, fmt(m.rms(tests, material::SheetDatum::uniaxial_r), 3));
  }
  c.value("yld_c1", fmt(fit.raw.c1[0], 4) + ", " + fmt(fit.raw.c1[1], 4) + ", " + fmt(fit.raw.c1[2], 4) + ", " +
                        fmt(fit.raw.c1[3], 4) + ", " + fmt(fit.raw.c1[4], 4) + ", " + fmt(fit.raw.c1[5], 4) + ", " +
                        fmt(fit.raw.c1[6], 4) + ", " + fmt(fit.raw.c1[7], 4) + ", " + fmt(fit.raw.c1[8], 4));
  c.value("yld_c2", fmt(fit.raw.c2[0], 4) + ", " + fmt(fit.raw.c2[1], 4) + ", " + fmt(fit.raw.c2[2], 4) + ", " +
                        fmt(fit.raw.c2[3], 4) + ", " + fmt(fit.raw.c2[4], 4) + ", " + fmt(fit.raw.c2[5], 4) + ", " +
                        fmt(fit.raw.c2[6], 4) + ", " + fmt(fit.raw.c2[7], 4) + ", " + fmt(fit.raw.c2[8], 4));
  c.value("yld_starts", std::to_string(fit.accepted) + " of " + std::to_string(fit.starts));
}

}  // namespace v1
