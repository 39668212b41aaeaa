// The loop's decisions, noise floor, bending choices, group factors and the
// friction-model export (src/loop), on cases with known answers.
//  - sequential_decision (Clopper-Pearson at 1e-3 against thr = 0.0025):
//    0 exceedances in 3000 permutations: upper bound 1 - 0.001^(1/3000) =
//    0.0023 < thr -> significant; 0 in 100: upper 0.067 -> undecided; 50 in
//    100: lower bound far above thr -> not significant.
//  - Noise floor: rows exactly on a line per test -> sigma = 0, flagged exact;
//    null synthetic data with noise sd 5 N (45 tests x 2 dof after the
//    within-test polynomial of 6 terms on 8 rows): estimate within 30 % (4
//    standard errors of an estimated sd, 1/sqrt(2 x 90) = 7.5 %).  The same
//    scatter of given values (the model floor, noise.hpp): of the outlet
//    forces themselves, bit for bit the default; of the forces plus
//    100 + 7 F_back per row (in every test's column span: a constant and a
//    line in the back tension), the same within 1e-9 relative; of values
//    NaN on one test's rows, that test skipped (44 tests, 88 dof).
//  - No rotating-pin rows: make_design throws InputError unless a bending
//    source is chosen; with swift, F_B = Swift Eq. 2.1 (analysis::swift_bending_force)
//    and the label says "NO rotating-pin rows".
//  - A hidden coil (batch) factor of +20 % on coil C: the loop adds a group
//    factor for 'coil' with one parameter per level but the first, and the C
//    level's factor is the largest, within 3 SE of its true value relative to
//    the reference coil.
//  - Export, closed form: nine nodes sampled from the quadratic
//    mu = 0.05 + 0.002 p - 3e-4 v + 1e-5 p v - 2e-5 p^2 + 1e-6 v^2 (p 2-40 MPa,
//    v 6.35-101.6 mm/s; mu 0.031 to 0.083, never clamped) lie in the span of the
//    OpenRadioss generalized viscous law, so its fit is that polynomial: one
//    speed band, coefficients (Fric, C1..C5) equal to those within 1e-9
//    relative (10 printed digits), relative error below 1e-8; Iform 2 in
//    columns 41-50, Idir 0 in columns 51-60 of the pair card.  Without part
//    IDs the OpenRadioss export is refused naming --parts.  The independent
//    readers of all three formats are tests/export (unit.export-files).
#define BOOST_TEST_MODULE loop_outputs
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "analysis/rope.hpp"
#include "core/csv.hpp"
#include "loop/candidates.hpp"
#include "loop/export.hpp"
#include "loop/loop.hpp"
#include "loop/noise.hpp"
#include "loop/synth.hpp"

using namespace drawbend;
using namespace drawbend::loop;

BOOST_AUTO_TEST_CASE(sequential_decisions) {
  BOOST_TEST(sequential_decision(0, 3000, 0.0025) == 1);
  BOOST_TEST(sequential_decision(0, 100, 0.0025) == 0);
  BOOST_TEST(sequential_decision(50, 100, 0.0025) == -1);
}

static Dataset synth(const std::string& effect, double noise, int seed) {
  static MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  SynthOptions o;
  o.effect = effect;
  o.noise_N = noise;
  o.seed = seed;
  SynthTruth t;
  return synthesize(o, maps, t);
}

BOOST_AUTO_TEST_CASE(noise_floor) {
  static MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  const Dataset exact = synth("none", 0, 3);
  BOOST_TEST(replicate_noise(make_design(exact, maps)).exact);
  const Dataset d = synth("none", 5, 3);
  const NoiseFloor n = replicate_noise(make_design(d, maps));
  BOOST_TEST(!n.exact);
  BOOST_TEST(n.tests == 45);
  BOOST_TEST(n.dof == 90);
  BOOST_TEST(std::abs(n.sigma_N / 5 - 1) < 0.3);
  const Design D = make_design(d, maps);
  std::vector<double> y, y2;
  for (const auto& s : d.rows) y.push_back(s.outlet_force_N), y2.push_back(s.outlet_force_N + 100 + 7 * s.back_tension_N);
  BOOST_TEST(replicate_noise(D, &y).sigma_N == n.sigma_N);
  BOOST_TEST(replicate_noise(D, &y2).sigma_N == n.sigma_N, boost::test_tools::tolerance(1e-9));
  const std::string first = d.rows.front().test_id;
  for (size_t i = 0; i < d.rows.size(); ++i)
    if (d.rows[i].test_id == first) y[i] = std::nan("");
  const NoiseFloor m = replicate_noise(D, &y);
  BOOST_TEST(m.tests == 44);
  BOOST_TEST(m.dof == 88);
}

BOOST_AUTO_TEST_CASE(no_rotating_rows) {
  static MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  Dataset d = synth("none", 5, 4);
  std::vector<Sample> fixed;
  for (const auto& s : d.rows)
    if (!s.rotating) fixed.push_back(s);
  d.rows = fixed;
  BOOST_CHECK_THROW(make_design(d, maps), InputError);
  const Design des = make_design(d, maps, 0.4, BendingSource::swift);
  BOOST_TEST(des.missing_rotating);
  BOOST_TEST(des.bending_label.find("NO rotating-pin rows") != std::string::npos);
  const double sw = analysis::swift_bending_force(99.71, 1.04, 25.4, 12.7 / 2, M_PI / 2, analysis::ForceBasis::full_strip);
  BOOST_TEST(des.bend_fallback[0] == sw, boost::test_tools::tolerance(1e-12));
  const Fit f = fit_model(des, ModelSpec{});
  for (size_t i = 0; i < des.rows.size(); ++i) BOOST_TEST(std::isfinite(predict(des, f, static_cast<int>(i))));
}

BOOST_AUTO_TEST_CASE(batch_group_factor) {
  static MapLibrary maps = MapLibrary::stand_in({12.7, 25.4, 42});
  const Dataset d = synth("batch", 5, 5);
  const LoopResult r = run_loop(make_design(d, maps), LoopOptions{});
  BOOST_TEST_REQUIRE(!r.steps.empty());
  BOOST_TEST(r.steps[0].variable == "coil");
  BOOST_TEST(r.steps[0].effect == "group_factor");
  BOOST_TEST_REQUIRE(r.steps[0].params.size() == 2u);  // three coils, one reference
  // True factors relative to the reference level (the first coil seen).
  const std::string ref = d.rows[0].extra[d.extra_index("coil")];
  for (const auto& p : r.steps[0].params) {
    const bool c = p.name.find("= C]") != std::string::npos;
    const double truth = ref == "C" ? (c ? 0 : 1 / 1.2 - 1) : (c ? 0.2 : 0.0);
    BOOST_TEST(std::abs(p.value - truth) < 3 * p.se + 1e-3, p.name << " " << p.value << " +- " << p.se);
  }
}

BOOST_AUTO_TEST_CASE(export_evaluates_back) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "drawbend_test_export";
  fs::create_directories(dir);
  const std::vector<double> truth = {0.05, 0.002, -3e-4, 1e-5, -2e-5, 1e-6};  // Fric, C1 p, C2 v, C3 p v, C4 p^2, C5 v^2
  auto q = [&](double p, double v) { return radioss_mu(truth, p, v); };
  std::ostringstream nodes;
  nodes.precision(17);
  nodes << "node,mu_RD,mu_TD\n";
  const double ps[3] = {2, 21, 40}, vs[3] = {6.35, 53.975, 101.6};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) nodes << 3 * i + j + 1 << "," << q(ps[i], vs[j]) << "," << q(ps[i], vs[j]) << "\n";
  std::ofstream(dir / "nodes.csv") << nodes.str();
  std::ofstream(dir / "friction_model_x.toml") << "[friction]\nlaw = \"surface\"\nnodes = \"nodes.csv\"\np_min = 2\n"
                                                 "p_max = 40\nv_min = 6.35\nv_max = 101.6\ninterval = 100\n";
  const ExportModel m = read_friction_model((dir / "friction_model_x.toml").string());
  BOOST_TEST(export_path((dir / "friction_model_x.toml").string(), "openradioss") ==
             (dir / "friction_openradioss_x.rad").string());
  ExportOptions o;
  BOOST_CHECK_EXCEPTION(export_openradioss(m, o), std::invalid_argument, [](const std::invalid_argument& e) {
    return std::string(e.what()).rfind("--parts", 0) == 0;
  });
  o.sheet_part = 3;
  o.tool_part = 2;
  const ExportResult ra = export_openradioss(m, o);
  BOOST_TEST(ra.bands == 1);
  BOOST_TEST(ra.max_error < 1e-8);
  const std::vector<double> c = radioss_fit(m.rd, 6.35, 101.6);
  for (int k = 0; k < 6; ++k) BOOST_TEST(std::abs(c[k] - truth[k]) <= 1e-9 * std::abs(truth[k]), "coefficient " << k << ": " << c[k]);
  std::istringstream in(ra.text);
  std::vector<std::string> cards;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') cards.push_back(line);
  // /FRICTION/1, title, Ifric card, C1..C5, C6 Fric VISF, pair card, ...
  BOOST_TEST_REQUIRE(cards.size() >= 9u);
  BOOST_TEST(cards[2].substr(40, 10) == "         2");  // Iform
  BOOST_TEST(cards[5].substr(20, 10) == "         3");  // part_ID1
  BOOST_TEST(cards[5].substr(30, 10) == "         2");  // part_ID2
  BOOST_TEST(cards[5].substr(40, 10) == "          ");
  BOOST_TEST(cards[5].substr(50, 10) == "         0");  // Idir
  for (int k = 0; k < 5; ++k)
    BOOST_TEST(std::abs(std::stod(cards[6].substr(20 * k, 20)) - truth[k + 1]) <= 1e-9 * std::abs(truth[k + 1]));
  BOOST_TEST(std::abs(std::stod(cards[7].substr(20, 20)) - truth[0]) <= 1e-9 * truth[0]);
  fs::remove_all(dir);
}
