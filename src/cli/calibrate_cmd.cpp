// `drawbend calibrate TESTS.csv --out DIR`: Yld2004-18p fitted to a sheet's
// material tests (src/material/yld2004_fit.hpp), written as a material TOML
// (DIR/material.toml, the [material] keys type and yld2004) and a table of
// every datum (DIR/calibration.csv): measured, Hill'48 from the r-values,
// Hill'48 from the stress ratios, the fitted Yld2004-18p (and a published set
// given with --compare), and the fit's residual.  The weights are printed.
// Sample: drawbend calibrate data/materials/aa6016_t4_esaform2021.csv --out cal
//           --compare data/materials/aa6016_t4_yld2004_postech2022.toml
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli/exit_codes.hpp"
#include "core/csv.hpp"
#include "core/file_gate.hpp"
#include "core/options.hpp"
#include "io/material_spec.hpp"
#include "material/yld2004_fit.hpp"

namespace drawbend::cli {

namespace {
std::string array9(const std::array<double, 9>& c) {
  std::string s = "[";
  for (int i = 0; i < 9; ++i) s += (i ? ", " : "") + fmt(c[i], 8);
  return s + "]";
}
}  // namespace

int calibrate_command(int argc, char** argv) {
  std::string out = "calibration", compare;
  double a = 8.0;
  material::FitWeights w;
  Options opt("drawbend calibrate TESTS.csv", "Fit Yld2004-18p to a sheet's material tests (CSV: test, angle_deg, "
                                               "stress_ratio, r_value) by weighted least squares.");
  opt.add(out, "out", "output directory (material.toml, calibration.csv)");
  opt.add(a, "a", "Yld2004-18p exponent (>= 2; 8 for FCC metals)");
  opt.add(w.stress, "w-stress", "weight of each uniaxial yield-stress ratio (on its relative residual)");
  opt.add(w.r, "w-r", "weight of each r-value (on its relative residual)");
  opt.add(w.biaxial, "w-biaxial", "weight of the balanced biaxial stress ratio and rb");
  opt.add(w.plane_strain, "w-plane-strain", "weight of each plane-strain stress ratio");
  opt.add(compare, "compare", "a published Yld2004-18p set (TOML: yld2004 = { a, c1, c2 }, at the top or in [material]) for the table");
  // Every number checked as it is parsed (cli/option_bounds.hpp's style): the exponent from 2
  // (quadratic) to 64 (beyond it |x|^a overflows for stress ratios near 1e5); weights 0 to 1e6.
  opt.range("a", 2, 64).range("w-stress", 0, 1e6).range("w-r", 0, 1e6).range("w-biaxial", 0, 1e6);
  opt.range("w-plane-strain", 0, 1e6);
  opt.example("drawbend calibrate data/materials/aa6016_t4_esaform2021.csv --out my-cal    # my-cal/material.toml");
  opt.example("drawbend calibrate data/materials/aa6016_t4_esaform2021.csv --out my-cal --compare "
              "data/materials/aa6016_t4_yld2004_postech2022.toml");
  if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::cout << opt.usage();
    return 0;
  }
  if (argc >= 2 && std::string(argv[1]).rfind("-", 0) == 0) {  // as `run`: the option is named
    std::cerr << "input error: drawbend calibrate: expected TESTS.csv first, found the option '"
              << clip_for_message(argv[1]) << "' (drawbend calibrate TESTS.csv --out DIR; --help lists the options)\n";
    return 2;
  }
  if (argc < 2) {
    std::cerr << "usage: drawbend calibrate TESTS.csv --out DIR [--a 8] [--w-stress 1] [--w-r 1] [--w-biaxial 1] "
                 "[--w-plane-strain 1] [--compare PUBLISHED.toml] (drawbend calibrate --help: options and examples)\n";
    return 2;
  }
  const std::string path = argv[1];
  if (!opt.parse(argc - 1, argv + 1)) return 0;
  for (double v : {w.stress, w.r, w.biaxial, w.plane_strain})
    if (!(v >= 0) || !std::isfinite(v)) throw InputError("--w-*: weights must be finite and >= 0");
  if (!(a >= 2) || !std::isfinite(a)) throw InputError("--a: the exponent must be >= 2, found " + fmt_shortest(a));
  name_input(path, "TESTS.csv");  // read through the file gate (core/file_gate.hpp)
  ensure_writable_dir(out, "--out");  // checked before any work: exit 2, not a file-system error after the fit
  if (!compare.empty()) name_input(compare, "--compare");
  const material::SheetTests t = material::load_sheet_tests(path);
  // The published set is read before the fit (seconds): a bad --compare is an
  // input error at once, not after the work.
  material::Yld2004 published;
  if (!compare.empty()) published = io::load_yld2004_toml(compare).normalised();
  const double r0 = t.r_value(0), r45 = t.r_value(45), r90 = t.r_value(90);
  const double s45 = t.uniaxial_stress(45), s90 = t.uniaxial_stress(90), sb = t.biaxial_stress();
  std::vector<material::Hill48> hills;
  std::vector<material::NamedYield> models;
  hills.reserve(2);
  if (std::isfinite(r0) && std::isfinite(r45) && std::isfinite(r90))
    hills.push_back(material::Hill48::from_r_values(r0, r45, r90));
  const bool have_r = !hills.empty();
  if (std::isfinite(s45) && std::isfinite(s90) && std::isfinite(sb))
    hills.push_back(material::Hill48::from_stress_ratios(s45, s90, sb));
  if (have_r) models.push_back({"hill48_r", nullptr, &hills[0]});
  if (hills.size() > (have_r ? 1u : 0u)) models.push_back({"hill48_s", nullptr, &hills.back()});
  std::cout << "weights (on relative residuals): uniaxial stress " << fmt_shortest(w.stress) << ", r-value "
            << fmt_shortest(w.r) << ", balanced biaxial " << fmt_shortest(w.biaxial) << ", plane strain "
            << fmt_shortest(w.plane_strain) << "\n";
  const material::Yld2004Fit fit = material::fit_yld2004(t, w, a);
  models.push_back({"yld2004", &fit.yield, nullptr});
  const std::size_t fitted = models.size() - 1;
  if (!compare.empty()) models.push_back({"yld2004_published", &published, nullptr});
  const auto rows = material::calibration_table(t, w, models, fitted);
  std::ostringstream csv;
  for (const auto& r : rows) {
    for (std::size_t i = 0; i < r.size(); ++i) csv << (i ? "," : "") << r[i];
    csv << "\n";
  }
  for (const char* f : {"/calibration.csv", "/material.toml"}) {  // TESTS.csv or --compare as an output, before either is written
    name_input(out + f, "--out");
    refuse_input_as_output(out + f);
  }
  write_file_atomic(out + "/calibration.csv", csv.str());
  std::ostringstream toml;
  toml << "# Yld2004-18p fitted by `drawbend calibrate " << path << "` (weighted least squares on relative residuals;\n"
       << "# weights: uniaxial stress " << fmt_shortest(w.stress) << ", r " << fmt_shortest(w.r) << ", biaxial "
       << fmt_shortest(w.biaxial) << ", plane strain " << fmt_shortest(w.plane_strain) << "; cost " << fmt(fit.cost, 4)
       << ", " << fit.accepted << " of " << fit.starts << " starts valid).\n"
       << "# c44 = c55 = 1 in C' and C'': the sheet tests say nothing about the out-of-plane shears.\n"
       << "# The solver scales c1 and c2 by 1/" << fmt(fit.scale, 8) << " so that sigma_bar of uniaxial tension along\n"
       << "# RD is 1 (the flow curve is that of RD); the ratios in calibration.csv are scale-free.\n"
       << "# Add E, nu, density and a flow curve to use it as a deck's [material].\n"
       << "[material]\ntype = \"yld2004\"\nyld2004 = { a = " << fmt_shortest(a) << ", c1 = " << array9(fit.raw.c1)
       << ", c2 = " << array9(fit.raw.c2) << " }\n";
  write_file_atomic(out + "/material.toml", toml.str());
  for (const auto& r : rows) {
    for (std::size_t i = 0; i < r.size(); ++i) std::cout << (i ? "  " : "") << r[i];
    std::cout << "\n";
  }
  std::cout << "RMS of the residuals over sigma(theta)/sigma0 and over r(theta):\n";
  for (const auto& m : models)
    std::cout << "  " << m.name << ": " << fmt(m.rms(t, material::SheetDatum::uniaxial_stress), 3) << " and "
              << fmt(m.rms(t, material::SheetDatum::uniaxial_r), 3) << "\n";
  const auto weighted = std::count_if(t.data.begin(), t.data.end(), [&](const auto& d) { return w.of(d.kind) > 0; });
  if (weighted < 14)
    std::cout << "note: " << weighted << " weighted data for 14 free coefficients: the fit is not unique; between the "
              << "tested directions the set follows its start (the best of " << fit.starts << " starts is kept).\n";
  std::cout << "c44 = c55 = 1 (and in C''): no test of the sheet loads the out-of-plane shears.\n"
            << "wrote " << out << "/material.toml and " << out << "/calibration.csv (" << fit.accepted << " of "
            << fit.starts << " starts gave a closed, convex set)\n";
  return 0;
}

}  // namespace drawbend::cli
